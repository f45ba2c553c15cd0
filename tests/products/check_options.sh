#!/usr/bin/env bash
# The build options of a plain configuration (issue: a user building the
# library alone needs neither Check nor the benchmarks):
#   meson setup -Dtests=false  looks up no Check, registers no test, and
#                              builds no benchmark (-Dbenchmarks is off by
#                              default).
#   check_options.sh MESON SOURCE_ROOT
set -euo pipefail
meson=$1
source=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
if ! "$meson" setup "$dir/build" "$source" -Dtests=false >"$dir/setup.log" 2>&1; then
  cat "$dir/setup.log"
  echo "meson setup -Dtests=false failed"
  exit 1
fi
status=0
if grep -qi "dependency check" "$dir/setup.log"; then
  echo "-Dtests=false still looks up Check:"
  grep -i "dependency check" "$dir/setup.log"
  status=1
fi
tests=$("$meson" introspect --tests "$dir/build")
if [ "$tests" != "[]" ]; then
  echo "-Dtests=false still registers tests: $tests" | cut -c1-300
  status=1
fi
if "$meson" introspect --targets "$dir/build" | grep -q '"name": "[a-z_]*_bench"'; then
  echo "the benchmarks build without -Dbenchmarks=true"
  status=1
fi
for target in hdt hdt-triangulate; do
  "$meson" introspect --targets "$dir/build" | grep -q "\"name\": \"$target\"" || { echo "no target $target"; status=1; }
done
[ $status -eq 0 ] && echo "options: -Dtests=false needs no Check and registers no test; no benchmark by default"
exit $status
