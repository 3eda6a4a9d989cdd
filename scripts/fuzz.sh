#!/usr/bin/env bash
# Runs each libFuzzer target for SECONDS from its seeds in fuzz/corpus, JOBS
# targets at a time (each fuzzer is one process on one core, so on 2 cores two
# run side by side and each still gets its full time). The corpus a target
# grows stays in BUILD/corpus/TARGET, its log in BUILD/fuzz-TARGET.log; a crash
# leaves its input in BUILD as crash-* and fails the run, with the log's tail.
#   scripts/fuzz.sh BUILD SECONDS JOBS TARGET...   (make fuzz calls it)
set -uo pipefail
build=$1 seconds=$2 jobs=$3
shift 3
root=$(cd "$(dirname "$0")/.." && pwd)

corpus_of() {
  case $1 in
    read_csv) echo csv ;; read_npy) echo npy ;; read_png) echo png ;; read_geojson) echo geojson ;;
    read_manifest) echo manifest ;; read_mesh) echo mesh ;; *) echo request ;;
  esac
}

run_one() {
  local t=$1
  mkdir -p "$build/corpus/$t"
  (cd "$build" && "./fuzz/${t}_fuzz" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 "corpus/$t" "$root/fuzz/corpus/$(corpus_of "$t")" >"fuzz-$t.log" 2>&1)
}

declare -A pid_of
failed=()
running=0
for t in "$@"; do
  echo "fuzz: $t for $seconds s"
  run_one "$t" &
  pid_of[$t]=$!
  running=$((running + 1))
  if ((running >= jobs)); then
    wait -n
    running=$((running - 1))
  fi
done
for t in "$@"; do
  if wait "${pid_of[$t]}"; then
    echo "fuzz: $t passed"
    tail -6 "$build/fuzz-$t.log"
  else
    failed+=("$t")
  fi
done
for t in "${failed[@]}"; do
  echo "fuzz: $t FAILED; the last 60 lines of $build/fuzz-$t.log:"
  tail -60 "$build/fuzz-$t.log"
done
((${#failed[@]} == 0))
