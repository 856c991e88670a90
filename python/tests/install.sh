#!/usr/bin/env bash
# ctest python_install: `cmake --install` puts the package where HSX_PYTHON_INSTALL_DIR says, and it imports and
# runs from there, away from the build tree. Usage: install.sh BUILD_DIR PYTHON INSTALL_DIR SCENE
set -euo pipefail
build="$1" python="$2" dir="$3" scene="$4"
prefix="$(mktemp -d)"
trap 'rm -rf "$prefix"' EXIT
cmake --install "$build" --prefix "$prefix" >/dev/null
for f in __init__.py _scene.py _draw.py __init__.pyi _hsx.pyi py.typed; do
  [ -f "$prefix/$dir/hsx/$f" ] || { echo "not installed: $dir/hsx/$f"; exit 1; }
done
cd "$prefix"
PYTHONPATH="$prefix/$dir" "$python" -c "
import sys, hsx
assert hsx.__file__.startswith('$prefix'), hsx.__file__
r = hsx.extract(sys.argv[1], method='exact')
assert r.optimal, r
print('installed hsx imports from', hsx.__file__, 'and extracts', r)
" "$scene"
