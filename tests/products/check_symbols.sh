#!/usr/bin/env bash
# The shared library exports exactly the functions of include/hdt.h: every
# defined dynamic symbol is hdt_* (besides the version node HDT_x.y), and every
# function the header declares is exported.
# Usage: check_symbols.sh NM LIBRARY HEADER
set -euo pipefail

nm_tool=$1
library=$2
header=$3

# "0000000000012340 T hdt_systole@@HDT_0.1" -> "hdt_systole"
exported=$("$nm_tool" -D --defined-only "$library" | awk 'NF >= 2 { print $NF }' | sed 's/@.*//' | sort -u)
if [[ -z $exported ]]; then
  echo "no dynamic symbols found in $library" >&2
  exit 1
fi

status=0
while IFS= read -r symbol; do
  case $symbol in
    hdt_*) ;;
    HDT_[0-9]*.[0-9]*) ;; # the symbol version node (lib/hdt.map)
    *)
      echo "exported symbol outside the hdt_ namespace: $symbol" >&2
      status=1
      ;;
  esac
done <<<"$exported"

# Declarations start with HDT_API; the function name is on that line.
declared=$(grep -E '^HDT_API' "$header" | grep -oE 'hdt_[a-z0-9_]+[[:space:]]*\(' | tr -d '( ' | sort -u)
if [[ -z $declared ]]; then
  echo "no declarations found in $header" >&2
  exit 1
fi
missing=$(comm -23 <(echo "$declared") <(echo "$exported" | grep '^hdt_' || true))
if [[ -n $missing ]]; then
  echo "declared in hdt.h but not exported:" $missing >&2
  status=1
fi
undeclared=$(comm -13 <(echo "$declared") <(echo "$exported" | grep '^hdt_' || true))
if [[ -n $undeclared ]]; then
  echo "exported but not declared in hdt.h:" $undeclared >&2
  status=1
fi

if [[ $status -eq 0 ]]; then
  echo "ok: $(echo "$declared" | wc -l) functions exported, nothing else"
fi
exit $status
