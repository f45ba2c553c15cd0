#!/usr/bin/env bash
# Installs the build into a temporary DESTDIR, builds a small program against
# the installed header and library found through the installed hdt.pc, and
# runs it against the installed library.
# Usage: CC="cc" check_install.sh MESON BUILD_ROOT PROGRAM_SOURCE HEADER
set -euo pipefail

meson_tool=$1
build_root=$2
program=$3
header=$4
read -r -a c_compiler <<<"${CC:-cc}"

if ! command -v pkg-config >/dev/null 2>&1; then
  echo "pkg-config not found: skipped"
  exit 77
fi

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
dest=$tmp/dest

"$meson_tool" install -C "$build_root" --no-rebuild --quiet --destdir "$dest"

pc=$(find "$dest" -name hdt.pc -print -quit)
installed_header=$(find "$dest" -name hdt.h -path '*/include/*' -print -quit)
library=$(find "$dest" -name 'libhdt.so' -print -quit)
for found in "$pc" "$installed_header" "$library"; do
  if [[ -z $found ]]; then
    echo "the install lacks hdt.pc, include/hdt.h or libhdt.so:" >&2
    find "$dest" >&2
    exit 1
  fi
done
cmp "$header" "$installed_header"
libdir=$(dirname "$library")

# The .pc file holds the real prefix; the sysroot puts its paths under DESTDIR.
flags=$(PKG_CONFIG_PATH="$(dirname "$pc")${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}" \
  PKG_CONFIG_SYSROOT_DIR="$dest" pkg-config --cflags --libs hdt)
echo "pkg-config: $flags"
if [[ $flags != *"-I$dest/"* || $flags != *"-L$dest/"* ]]; then
  echo "pkg-config flags do not point into the install" >&2
  exit 1
fi

read -r -a flag_array <<<"$flags"
"${c_compiler[@]}" -std=c99 -o "$tmp/installed_systole" "$program" "${flag_array[@]}" -lm

if command -v ldd >/dev/null 2>&1; then
  resolved=$(LD_LIBRARY_PATH="$libdir" ldd "$tmp/installed_systole" | grep libhdt || true)
  echo "ldd: $resolved"
  if [[ $resolved != *"$libdir/"* ]]; then
    echo "the program does not load the installed libhdt" >&2
    exit 1
  fi
fi
LD_LIBRARY_PATH="$libdir" "$tmp/installed_systole"
