#!/usr/bin/env bash
# consumer_test.sh BUILD_DIR SOURCE_DIR CXX [CXXFLAGS [LDFLAGS]]: installs
# BUILD_DIR into a fresh prefix, builds examples/consumer against it with
# find_package(vri) alone (no path into the source or build tree), and checks
# that the consumer's render equals the installed `vri render` of the same
# scene byte for byte, and that both report the package's version.
set -euo pipefail
build=$(cd "$1" && pwd); src=$(cd "$2" && pwd); cxx=$3; cxxflags=${4:-}; ldflags=${5:-}
cmake=${CMAKE:-cmake}  # the build's own cmake, from tests/CMakeLists.txt
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
scene=$src/scenes/marschner_lobb.json

# Only vri's own components: the python component goes to the system's site-packages.
for component in runtime devel; do
  "$cmake" --install "$build" --prefix "$tmp/prefix" --component $component >/dev/null
done
for f in bin/vri include/vri/version.hpp include/vri/scene.hpp; do
  [[ -e $tmp/prefix/$f ]] || { echo "FAIL: $f not installed"; exit 1; }
done
[[ -n $(find "$tmp/prefix" -name vriConfig.cmake) ]] || { echo "FAIL: no vriConfig.cmake installed"; exit 1; }
[[ -n $(find "$tmp/prefix" -name vriConfigVersion.cmake) ]] || { echo "FAIL: no vriConfigVersion.cmake"; exit 1; }

"$cmake" -S "$src/examples/consumer" -B "$tmp/consumer" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="$cxx" \
      -DCMAKE_PREFIX_PATH="$tmp/prefix" -DCMAKE_CXX_FLAGS="-Wall -Wextra -Wpedantic -Werror $cxxflags" \
      -DCMAKE_EXE_LINKER_FLAGS="$ldflags" >"$tmp/configure.log" 2>&1 \
  || { cat "$tmp/configure.log"; echo "FAIL: configuring examples/consumer"; exit 1; }
"$cmake" --build "$tmp/consumer" >"$tmp/build.log" 2>&1 || { cat "$tmp/build.log"; echo "FAIL: building examples/consumer"; exit 1; }

out=$("$tmp/consumer/vri_consumer" "$scene" "$tmp/consumer.npy" 48 40)
echo "$out"
"$tmp/prefix/bin/vri" render "$scene" -o "$tmp/cli.npy" --width 48 --height 40 2>/dev/null
cmp "$tmp/consumer.npy" "$tmp/cli.npy" || { echo "FAIL: the consumer's image differs from vri render's"; exit 1; }
"$tmp/prefix/bin/vri" compare "$tmp/consumer.npy" "$tmp/cli.npy" --tolerance 0 >/dev/null

version=$("$tmp/prefix/bin/vri" --version)
[[ $out == "${version}: 48x40 "* ]] || { echo "FAIL: '$out' does not start with '$version: 48x40'"; exit 1; }
# Not a blank image: the comparison above must have had something to compare.
[[ $out != *"mean alpha 0.000000" ]] || { echo "FAIL: the consumer rendered nothing"; exit 1; }
echo "PASS: find_package(vri) consumer built against $tmp/prefix; its image equals vri render's"
