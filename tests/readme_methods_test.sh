#!/usr/bin/env bash
# The README's method table (between its methods-table markers) is what
# `pds methods --readme` prints. Regenerate it from the registry if this fails.
set -euo pipefail
pds=$1 readme=$2
sed -n '/^<!-- methods-table/,/^<!-- \/methods-table/p' "$readme" | sed '1d;$d' >"${TMPDIR:-/tmp}/readme_table.$$"
trap 'rm -f "${TMPDIR:-/tmp}/readme_table.$$"' EXIT
[[ -s "${TMPDIR:-/tmp}/readme_table.$$" ]] || { echo "README has no methods-table block"; exit 1; }
"$pds" methods --readme | diff -u "${TMPDIR:-/tmp}/readme_table.$$" - && echo "README method table in sync"
