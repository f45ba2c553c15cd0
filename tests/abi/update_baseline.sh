#!/usr/bin/env bash
# Regenerates tests/abi/libhdt.so.0.abi from a build's library, with the
# options the check relies on (see tests/abi/README.md: only when the
# released ABI changes, together with lib/hdt.map).
#
#   bash tests/abi/update_baseline.sh [BUILD_DIR]     (default: build)
set -euo pipefail
cd "$(dirname "$0")/../.."
dir=${1:-build}
lib=$(ls "$dir"/lib/libhdt.so.*.*.* | head -n 1)
if ! readelf -S "$lib" | grep -q '\.debug_info'; then
  echo "update_baseline: $lib has no DWARF; use a build with debug info (the default debugoptimized)" >&2
  exit 1
fi
abidw --no-corpus-path --no-comp-dir-path --no-show-locs --no-architecture \
  --drop-private-types --exported-interfaces-only --headers-dir include \
  --out-file tests/abi/libhdt.so.0.abi "$lib"
echo "update_baseline: wrote tests/abi/libhdt.so.0.abi from $lib" \
  "($(grep -c '<elf-symbol ' tests/abi/libhdt.so.0.abi) symbols)"
