#!/usr/bin/env bash
# The layers (README "Layout"): kernel -> geometry -> complex -> algorithms -> io -> cli. Public headers live in
# include/hsx/<layer>/ (included as <hsx/<layer>/x.hpp>), sources and private headers in src/<layer>/ (private
# headers included as "<layer>/x.hpp"). Rules checked on every include of every file:
#   1. a file of one layer includes only its own layer and the layers before it;
#   2. only kernel/ and geometry/ include CGAL;
#   3. no public header includes a private one (everything it includes must itself be public);
#   4. src/cli includes only public headers of the library (and its own cli/ headers), and so does the Python
#      module (python/src, the layer "python" after cli; its own headers are included without a folder);
#   5. a public header is spelled <hsx/...>, never "layer/x.hpp".
# Usage: layering.sh SOURCE_DIR [EXTRA_FILE...]. Prints every offending include and fails if any. Extra files
# (for testing this script) are checked as if they were at the path named by the first line "// layering-path: P".
set -u
root="${1:?usage: layering.sh SOURCE_DIR}"
shift
layers=(kernel geometry complex algorithms io cli python)
bad=0
declare -A index_of
for i in "${!layers[@]}"; do index_of[${layers[$i]}]=$i; done
include_re='^[[:space:]]*#[[:space:]]*include[[:space:]]*([<"])([^>"]+)[>"]'

check_file() {  # check_file FILE LOGICAL_PATH (relative to root: include/hsx/<layer>/... or src/<layer>/...)
  local file="$1" path="$2" public=0 layer rest
  case "$path" in
    include/hsx/*) public=1; rest="${path#include/hsx/}" ;;
    src/*) rest="${path#src/}" ;;
    python/src/*) rest="python/${path#python/src/}" ;;
    *) return ;;
  esac
  layer="${rest%%/*}"
  local li="${index_of[$layer]:--1}"
  [ "$li" -ge 0 ] || return
  while IFS= read -r line; do
    local inc quote=0
    [[ "$line" =~ $include_re ]] || continue
    inc="${BASH_REMATCH[2]}"; [ "${BASH_REMATCH[1]}" = '"' ] && quote=1
    local target="$inc" is_hsx=0
    if [[ "$inc" == hsx/* ]]; then target="${inc#hsx/}"; is_hsx=1; fi
    local tl="${target%%/*}" ti
    ti="${index_of[$tl]:--1}"
    if [ "$ti" -ge 0 ] && [[ "$target" == */* ]]; then
      if [ "$ti" -gt "$li" ]; then
        echo "$path: includes $inc (layer $tl comes after $layer)"; bad=$((bad + 1))
      fi
      if [ "$is_hsx" -eq 1 ] && [ ! -f "$root/include/hsx/$target" ]; then
        echo "$path: includes $inc, which is not a public header"; bad=$((bad + 1))
      fi
      if [ "$is_hsx" -eq 0 ] && [ "$quote" -eq 1 ]; then
        if [ -f "$root/include/hsx/$target" ]; then
          echo "$path: includes public header \"$inc\" as private; spell it <hsx/$target>"; bad=$((bad + 1))
        elif [ "$public" -eq 1 ]; then
          echo "$path: public header includes private header $inc"; bad=$((bad + 1))
        elif [ "$layer" = cli ] && [ "$tl" != cli ]; then
          echo "$path: the CLI includes private header $inc (use the public API)"; bad=$((bad + 1))
        elif [ "$layer" = python ]; then
          echo "$path: the Python module includes private header $inc (use the public API)"; bad=$((bad + 1))
        fi
      fi
    fi
    if [[ "$inc" == CGAL/* ]] && [[ "$layer" != kernel && "$layer" != geometry ]]; then
      echo "$path: includes $inc (only kernel/ and geometry/ may use CGAL)"; bad=$((bad + 1))
    fi
    if [[ "$inc" == CGAL/* || "$inc" == boost/* ]] && [ "$public" -eq 1 ]; then
      echo "$path: public header includes $inc (CGAL and Boost stay inside the library)"; bad=$((bad + 1))
    fi
  done < <(grep -E '^[[:space:]]*#[[:space:]]*include' "$file")
}

count=0
while IFS= read -r f; do
  check_file "$f" "${f#$root/}"; count=$((count + 1))
done < <(find "$root/include/hsx" "$root/src" $([ -d "$root/python/src" ] && echo "$root/python/src") -type f \
           \( -name '*.hpp' -o -name '*.cpp' \) | sort)
for extra in "$@"; do
  logical="$(sed -nE '1s|^// layering-path: (.*)$|\1|p' "$extra")"
  check_file "$extra" "${logical:?$extra: first line must be // layering-path: P}"; count=$((count + 1))
done
if [ "$bad" -ne 0 ]; then echo "$bad layering violations in $count files"; exit 1; fi
echo "layering holds in $count files"
