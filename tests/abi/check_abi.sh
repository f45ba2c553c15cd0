#!/usr/bin/env bash
# ABI check of the built libhdt against the committed baseline of the
# released ABI (tests/abi/libhdt.so.0.abi), with abidiff from Debian's
# abigail-tools. Registered as the meson test 'abi' (suite 'products');
# policy and how to update the baseline: tests/abi/README.md.
#
#   check_abi.sh BASELINE LIBRARY HEADERS_DIR
#
# Exit status: 0 compatible (or only functions added in a new version node),
# 1 an ABI change that is not allowed, or abidiff failed; 77 (meson: skipped)
# when abidiff is not installed.
#
# Policy, from abidiff's exit status (a bit field: 1 error, 2 usage error,
# 4 ABI change, 8 incompatible ABI change):
#   - 1 or 2: fail (the check could not run);
#   - 8 (a function or variable removed, e.g. a symbol dropped, renamed or
#     moved to another version node): fail;
#   - 4 (any other change: a parameter or return type, an enumerator's
#     value, a typedef, ...): fail, unless the only changes are added
#     functions or variables, each in a version node the baseline does not
#     have (a released node of lib/hdt.map is never edited). Then pass with
#     a note: the baseline is updated when that version is released.
#
# Only the exported interface counts: the hdt_* symbols (lib/hdt.map) and the
# types reachable from them that hdt.h defines (--headers-dir2,
# --drop-private-types, --exported-interfaces-only); the opaque
# hdt_triangulation stays a declaration. So the C++ core's types and the
# build type (optimisation level, sanitizers, extra DT_NEEDED entries) do not
# matter, as long as the library carries DWARF (-g: meson's debug,
# debugoptimized and the sanitizer builds). Without DWARF (buildtype=release)
# only the symbol tables can be compared; the check says so and does that.
set -uo pipefail

if [ $# -ne 3 ]; then
  echo "usage: $0 BASELINE LIBRARY HEADERS_DIR" >&2
  exit 1
fi
baseline=$1 lib=$2 headers=$3

if ! command -v abidiff >/dev/null 2>&1; then
  echo "abi: abidiff not found (Debian: apt-get install abigail-tools); skipped"
  exit 77
fi
for f in "$baseline" "$lib"; do
  [ -f "$f" ] || { echo "abi: $f not found" >&2; exit 1; }
done

opts=(--no-corpus-path --no-architecture --drop-private-types --exported-interfaces-only
      --headers-dir2 "$headers")

if command -v readelf >/dev/null 2>&1 && ! readelf -S "$lib" 2>/dev/null | grep -q '\.debug_info'; then
  echo "abi: NOTE: $lib has no DWARF (a build without -g): only the symbol tables are compared;"
  echo "abi:       the types of the interface are checked in builds with debug info (the default)."
fi

report=$(abidiff "${opts[@]}" "$baseline" "$lib" 2>&1)
rc=$?
[ -z "$report" ] || printf '%s\n' "$report"

if [ $rc -eq 0 ]; then
  echo "abi: $lib matches the baseline $(basename "$baseline")"
  exit 0
fi
if [ $((rc & 3)) -ne 0 ]; then
  echo "abi: abidiff failed (exit status $rc)" >&2
  exit 1
fi
if [ $((rc & 8)) -ne 0 ]; then
  echo "abi: FAIL: incompatible ABI change (abidiff exit status $rc): a released function or variable is gone." >&2
  echo "abi: an incompatible change needs a new SONAME; see tests/abi/README.md" >&2
  exit 1
fi

# Bit 4 alone: allowed only when nothing but additions is left once added
# symbols are ignored, and each added symbol sits in a version node the
# baseline does not know.
abidiff "${opts[@]}" --no-added-syms "$baseline" "$lib" >/dev/null 2>&1
rc_changes=$?
if [ $rc_changes -ne 0 ]; then
  echo "abi: FAIL: the ABI changed (abidiff exit status $rc); only additions in a new version node are allowed." >&2
  echo "abi: if the change is intended, see tests/abi/README.md" >&2
  exit 1
fi
released=$(grep '<elf-symbol ' "$baseline" | grep -o "version='[^']*'" | sort -u | sed "s/version='\(.*\)'/\1/")
# Added symbols are listed as {name@@VERSION} (or {name} when unversioned).
added=$(printf '%s\n' "$report" | grep -o '{[^{}]*}' | tr -d '{}' | sort -u)
bad=0
while IFS= read -r sym; do
  [ -n "$sym" ] || continue
  case "$sym" in
    *@*) node=${sym##*@} ;;
    *) node="" ;;
  esac
  if [ -z "$node" ]; then
    echo "abi: FAIL: added symbol $sym has no version node" >&2
    bad=1
  elif printf '%s\n' "$released" | grep -qx -- "$node"; then
    echo "abi: FAIL: added symbol $sym is in the released version node $node (add a new node to lib/hdt.map)" >&2
    bad=1
  fi
done <<<"$added"
[ $bad -eq 0 ] || exit 1
echo "abi: OK: only additions in new version nodes ($(printf '%s' "$added" | tr '\n' ' '));"
echo "abi: update the baseline when that version is released (tests/abi/README.md)"
exit 0
