#!/usr/bin/env bash
# The layer order of lib/, checked: a file of lib/LAYER/ may include headers
# of its own layer and of the layers listed before it, never of a later one.
# The build links each layer's static library only with the layers below
# (lib/meson.build); this test names the include that would break that.
#   check_layers.sh LIB_DIR
set -euo pipefail
lib=$1
layers=(exact group surface predicates triangulation capi picture)
declare -A rank
for i in "${!layers[@]}"; do rank[${layers[$i]}]=$i; done

status=0
for dir in "$lib"/*/; do
  layer=$(basename "$dir")
  if [ -z "${rank[$layer]+x}" ]; then
    echo "lib/$layer/ is not in the layer order of $0"
    status=1
    continue
  fi
  while IFS=: read -r file line text; do
    used=$(sed -E 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"([a-z_]+)\/.*/\1/' <<<"$text")
    [ -n "${rank[$used]+x}" ] || continue
    if [ "${rank[$used]}" -gt "${rank[$layer]}" ]; then
      echo "${file#"$lib"/}:$line: layer '$layer' includes a header of the higher layer '$used': $text"
      status=1
    fi
  done < <(grep -Hn -E '^[[:space:]]*#[[:space:]]*include[[:space:]]*"[a-z_]+/' "$dir"* || true)
done
[ $status -eq 0 ] && echo "layers: ${layers[*]} (each includes only itself and those before it)"
exit $status
