#!/usr/bin/env bash
# The layers of lib/, checked: a file of lib/LAYER/ may include headers of
# its own layer and of the layers it uses (below), never of another. The
# build links each layer's static library after the ones before it in
# lib/meson.build's layer_order; this test names the include that would
# break the order, or reach sideways (dual and dummies both stand on mesh
# and know nothing of each other). Each layer also has its row in the
# architecture table of docs/design.md, beside lib/.
#   check_layers.sh LIB_DIR
set -euo pipefail
lib=$1
declare -A uses=(
  [exact]=""
  [domain]="exact"
  [group]="exact"
  [surface]="exact group"
  [predicates]="exact group surface"
  [mesh]="exact domain group surface predicates"
  [dummies]="exact domain group surface predicates mesh"
  [dual]="exact domain group surface predicates mesh"
  [capi]="exact domain group surface predicates mesh dummies dual"
  [picture]="capi"
)

status=0
for dir in "$lib"/*/; do
  layer=$(basename "$dir")
  if [ -z "${uses[$layer]+x}" ]; then
    echo "lib/$layer/ is not a layer of $0"
    status=1
    continue
  fi
  while IFS=: read -r file line text; do
    used=$(sed -E 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"([a-z_]+)\/.*/\1/' <<<"$text")
    [ -n "${uses[$used]+x}" ] || continue
    [ "$used" = "$layer" ] && continue
    if [[ " ${uses[$layer]} " != *" $used "* ]]; then
      echo "${file#"$lib"/}:$line: layer '$layer' includes a header of '$used', which it does not use: $text"
      status=1
    fi
  done < <(grep -Hn -E '^[[:space:]]*#[[:space:]]*include[[:space:]]*"[a-z_]+/' "$dir"* || true)
done
design=$lib/../docs/design.md
for layer in "${!uses[@]}"; do
  if ! grep -q "^| \`lib/$layer/\` |" "$design"; then
    echo "docs/design.md has no row for lib/$layer/ in its architecture table"
    status=1
  fi
done
if [ $status -eq 0 ]; then
  for layer in exact domain group surface predicates mesh dummies dual capi picture; do
    echo "layer $layer uses: ${uses[$layer]:-nothing}"
  done
fi
exit $status
