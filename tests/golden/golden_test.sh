#!/usr/bin/env bash
# The output bytes of every registered method, pinned: each line of
# outputs.sha256 is the SHA-256 of the float64 .npy that `pds generate` writes
# for the arguments after it. A change of behaviour (a sampler, the sizing,
# the seeding) changes a hash and fails here; where bytes are meant to change,
# the commit that changes them regenerates the file and says why:
#   tests/golden/golden_test.sh PATH_TO_PDS --update
# Every method the registry lists must have at least one line.
set -u
pds=$1
update=${2:-}
here=$(dirname "$0")
list="$here/outputs.sha256"
source "$here/../cli_lib.sh"

if [[ $update == --update ]]; then
  : >"$tmp/new"
  while read -r _ args; do
    # shellcheck disable=SC2086
    "$pds" generate $args -o "$tmp/out.npy" || { echo "pds generate $args failed"; exit 1; }
    echo "$(sha256sum <"$tmp/out.npy" | cut -d' ' -f1)  $args" >>"$tmp/new"
  done <"$list"
  cp "$tmp/new" "$list"
  echo "golden: rewrote $list"
  exit 0
fi

while read -r want args; do
  # shellcheck disable=SC2086
  if ! "$pds" generate $args -o "$tmp/out.npy" 2>"$tmp/err"; then
    bad "pds generate $args failed: $(cat "$tmp/err")"
    continue
  fi
  got=$(sha256sum <"$tmp/out.npy" | cut -d' ' -f1)
  [[ $got == "$want" ]] && ok || bad "pds generate $args: bytes changed (sha256 $got, pinned $want)"
done <"$list"

# Coverage: every registered method is pinned.
"$pds" methods --markdown | sed -n 's/^| `\([a-z0-9-]*\)`.*/\1/p' >"$tmp/methods"
[[ -s $tmp/methods ]] || bad "no methods listed by pds methods --markdown"
while read -r m; do
  grep -qE "^[0-9a-f]{64}  $m " "$list" && ok || bad "method $m has no pinned output in $list"
done <"$tmp/methods"
finish golden
