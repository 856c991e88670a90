#!/usr/bin/env bash
# The layers of src/ (README "Layout"): each may include only itself and the layers before it, and only kernel/ and
# geometry/ may include CGAL. Usage: layering.sh SOURCE_DIR. Prints every offending include and fails if any.
set -u
src="${1:?usage: layering.sh SOURCE_DIR}/src"
layers=(kernel geometry complex algorithms io cli)
bad=0
for i in "${!layers[@]}"; do
  layer="${layers[$i]}"
  later=("${layers[@]:$((i + 1))}")
  while IFS= read -r file; do
    while IFS= read -r line; do
      inc="$(sed -E 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*[<"]([^>"]+)[>"].*/\1/' <<<"$line")"
      for l in "${later[@]}"; do
        if [[ "$inc" == "$l/"* ]]; then
          echo "${file#$src/}: includes $inc (layer $l comes after $layer)"; bad=$((bad + 1))
        fi
      done
      if [[ "$inc" == CGAL/* ]] && [[ "$layer" != kernel && "$layer" != geometry ]]; then
        echo "${file#$src/}: includes $inc (only kernel/ and geometry/ may use CGAL)"; bad=$((bad + 1))
      fi
    done < <(grep -E '^[[:space:]]*#[[:space:]]*include' "$file")
  done < <(find "$src/$layer" -type f \( -name '*.hpp' -o -name '*.cpp' \) | sort)
done
count=$(find "$src" -type f \( -name '*.hpp' -o -name '*.cpp' \) | wc -l)
if [ "$bad" -ne 0 ]; then echo "$bad layering violations in $count files"; exit 1; fi
echo "layering holds in $count files"
