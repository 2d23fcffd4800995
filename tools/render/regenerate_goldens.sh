#!/usr/bin/env bash
# Rewrites the render golden images in tests/render/data on purpose. Look at every PNG it
# writes before committing them.
#   tools/render/regenerate_goldens.sh [build-dir]   (default: build/render)
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="${1:-$root/build/render}"
if [[ ! -f "$build/CMakeCache.txt" ]]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCOOLAABER_WERROR=ON
fi
cmake --build "$build" --target render_tests
COOLAABER_REGENERATE_GOLDENS=1 "$build/tests/render_tests" --gtest_filter='GoldenTest.*'
echo "goldens written to $root/tests/render/data:"
ls -l "$root/tests/render/data"/*.png
