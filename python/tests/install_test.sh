#!/usr/bin/env bash
# install_test.sh BUILD_DIR PYTHON: `cmake --install BUILD --component python`
# (staged under a temporary DESTDIR) puts the package (its extension, Python
# and stubs) into one folder from which PYTHON imports it and renders.
set -euo pipefail
build=$1 python=$2 root=$(cd "$(dirname "$0")/../.." && pwd)
dest=$(mktemp -d)
trap 'rm -rf "$dest"' EXIT
DESTDIR=$dest cmake --install "$build" --component python >/dev/null
module=$(find "$dest" -path '*/vri/_vri.cpython-*.so')
site=$(dirname "$(dirname "$module")")
test -f "$site/vri/__init__.py" && test -f "$site/vri/__init__.pyi"
cd "$dest"
PYTHONPATH=$site "$python" -c "
import vri, numpy
assert vri.__file__.startswith('$dest'), vri.__file__
img = vri.render(vri.load_scene('$root/scenes/neghip.json'), method='preint1', width=32, height=32)
assert img.shape == (32, 32, 4) and img.dtype == numpy.float32 and img[..., 3].max() > 0
assert isinstance(img, vri.Image) and img._repr_png_()[1:4] == b'PNG'
print('installed and imported from', '$site')"
