#!/usr/bin/env bash
# Side-by-side load benchmark: runs each bench_load binary given (say the
# previous version's and this one's), alternated, ROUNDS times, and prints
# the fastest of REPS repetitions of each load benchmark in ms. On a shared
# machine the fastest repetition, alternated with the other binary, is the
# figure that other work disturbs least.
#   bash tests/bench/load_ab.sh [-r REPS] [-n ROUNDS] BENCH_LOAD...
set -euo pipefail
reps=8 rounds=2
while getopts "r:n:" o; do
  case $o in
    r) reps=$OPTARG ;;
    n) rounds=$OPTARG ;;
    *) echo "usage: $0 [-r REPS] [-n ROUNDS] BENCH_LOAD..." >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
[ $# -ge 1 ] || { echo "usage: $0 [-r REPS] [-n ROUNDS] BENCH_LOAD..." >&2; exit 2; }
filter='loadOnly|eigenOnly|loadAndEigen(Guarded)?/'
for ((i = 1; i <= rounds; i++)); do
  for b in "$@"; do
    printf '%s ' "$b"
    "$b" --benchmark_filter="$filter" --benchmark_repetitions="$reps" --benchmark_format=csv 2>/dev/null |
      tr -d '"' | awk -F, 'NR > 1 && $1 !~ /_(mean|median|stddev|cv)$/ {
        split($1, a, "/"); t = $3 + 0
        if (!(a[1] in m) || t < m[a[1]]) m[a[1]] = t
      } END { for (k in m) printf "%s=%.0f ", k, m[k] }'
    echo
  done
done
