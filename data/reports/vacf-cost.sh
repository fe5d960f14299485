#!/usr/bin/env bash
# What --vacf costs (lesson 16; beyond the article): build/gas itself, as a
# process, with and without --vacf on the same gas.
#
#   bash data/reports/vacf-cost.sh [GAS [BASE_GAS]]
#
# 1. Instructions (callgrind, repeatable on a busy machine): data/large-10000.scene
#    to T = 150 without and with --vacf; with BASE_GAS (the program built from
#    a commit before --vacf existed), the same run without --vacf by it too:
#    the cost of the option when not asked.
# 2. Processor time (user + sys) and the largest memory, in interleaved pairs
#    (without, with; ROUNDS rounds, default 5): data/large-100000.scene run to
#    T = 50 and dumped, then from the dump to T = 250 (the hidden test's
#    gas), and data/long-time-tail.scene to T = 200. The ratio is taken round
#    by round, and its median printed.
# Prints Markdown for data/reports/vacf.md. About ten processor-minutes.
set -euo pipefail
gas=${1:-build/gas}
base=${2:-}
rounds=${ROUNDS:-5}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

instructions() {  # instructions of "$@", from callgrind's summary
  valgrind --tool=callgrind --callgrind-out-file="$tmp/cg.out" "$@" 2>&1 |
    awk '/Collected/ {print $4}'
}

echo "### Instructions (callgrind): data/large-10000.scene to T = 150"
echo
echo "| run | instructions |"
echo "|---|---:|"
without=$(instructions "$gas" data/large-10000.scene --mode none --until 150)
with=$(instructions "$gas" data/large-10000.scene --mode none --until 150 --vacf "$tmp/v.csv")
if [ -n "$base" ]; then
  before=$(instructions "$base" data/large-10000.scene --mode none --until 150)
  echo "| the program before --vacf | $before |"
fi
echo "| without --vacf | $without |"
echo "| with --vacf | $with |"
awk -v a="$without" -v b="$with" 'BEGIN { printf "\n--vacf: %+.1f %% instructions.\n\n", 100 * (b / a - 1) }'

# One timed run: "user+sys max_rss_kB".
timed() {
  /usr/bin/time -f "%U %S %M" -o "$tmp/time" "$@" >/dev/null 2>&1
  awk '{ printf "%.2f %d\n", $1 + $2, $3 }' "$tmp/time"
}

"$gas" data/large-100000.scene --mode none --until 50 --dump "$tmp/d50.scene"
for case in "hidden:$tmp/d50.scene:250" "tail:data/long-time-tail.scene:200"; do
  IFS=: read -r name scene until <<<"$case"
  echo "### Processor time, $rounds interleaved pairs: $(basename "$scene") to T = $until"
  echo
  echo "| round | without (s) | with (s) | with / without | memory without (MB) | with (MB) |"
  echo "|---:|---:|---:|---:|---:|---:|"
  for r in $(seq 1 "$rounds"); do
    read -r t0 m0 < <(timed "$gas" "$scene" --mode none --until "$until")
    read -r t1 m1 < <(timed "$gas" "$scene" --mode none --until "$until" --vacf "$tmp/v.csv")
    awk -v r="$r" -v t0="$t0" -v t1="$t1" -v m0="$m0" -v m1="$m1" \
      'BEGIN { printf "| %d | %.2f | %.2f | %.3f | %.0f | %.0f |\n", r, t0, t1, t1 / t0, m0 / 1024, m1 / 1024 }'
    echo "$t1 $t0" >>"$tmp/ratios-$name"
  done
  awk '{ print $1 / $2 }' "$tmp/ratios-$name" | sort -g |
    awk '{ r[NR] = $1 } END { printf "\nMedian ratio: %.3f.\n\n", (NR % 2) ? r[(NR + 1) / 2] : (r[NR / 2] + r[NR / 2 + 1]) / 2 }'
done
