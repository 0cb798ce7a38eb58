#!/usr/bin/env bash
# install-python.sh [BUILD_DIR]: installs what is needed, builds vri and puts
# the Python module `vri` (and its type stubs) into the site-packages of
# Debian's python3 (/usr/bin/python3, which has numpy): docs/PYTHON.md.
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-build}
bash scripts/install-deps.sh
bash scripts/build.sh "$dir" -DVRI_PYTHON=ON
cmake --install "$dir" --component python
/usr/bin/python3 -c "import vri; print('installed vri', vri.__version__, 'at', vri.__file__)"
