#!/usr/bin/env bash
# hdt.h compiles cleanly on its own as strict C99 and as C++17.
# Usage: CC="cc" CXX="c++" check_header.sh INCLUDE_DIR SOURCE
set -euo pipefail

include_dir=$1
source=$2
read -r -a c_compiler <<<"${CC:-cc}"
read -r -a cxx_compiler <<<"${CXX:-c++}"

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

set -x
"${c_compiler[@]}" -std=c99 -pedantic -Wall -Wextra -Wstrict-prototypes -Werror \
  -I"$include_dir" -c "$source" -o "$tmp/strict_c.o"
"${cxx_compiler[@]}" -x c++ -std=c++17 -pedantic -Wall -Wextra -Werror \
  -I"$include_dir" -c "$source" -o "$tmp/strict_cxx.o"
