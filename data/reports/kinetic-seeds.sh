#!/usr/bin/env bash
# Lesson 14's seed table (beyond the article): do the statistics' error bars
# hold? Runs build/gas itself, as a process, on seeds nobody tuned on, and
# sets every figure of --csv that has a theory (every column x with an
# x_theory) beside it, normalised by the combined error: over the seeds those
# numbers should scatter like a standard normal (root mean square about 1;
# 0.7 to 1.4 with 8 seeds), and no run should be off by more than 3.
#
#   bash data/reports/kinetic-seeds.sh [GAS] > data/reports/kinetic-seeds.md
#
# The combined error of x - x_theory: x_deviation_error where the CSV has a
# deviation column (the difference taken sample by sample, so that what the
# figure and its theory share cancels, lesson 14), else
# sqrt(x_error^2 + x_theory_error^2) (no x_theory_error: the theory is exact).
#
# GAS: the program (default build/gas); LATTICE_SEEDS="...", LARGE_SEEDS="..."
# other seeds (default 41 to 48 and 51 to 58). Two runs at a time (the
# machine may be shared); about three CPU-minutes in all on an idle machine:
# - 1024 balls of radius 1 on a lattice at eta = 0.5 (side 80.2121), every
#   speed 1, to T = 800;
# - scenes like data/large-10000.scene (10000 balls at eta = 0.3 at random
#   places) with other seeds, to T = 1500.
# And the warm-up (lesson 14): on the lattice starts, Z - Z_theory over the
# first 200 time units of averages against the whole run.
set -euo pipefail
gas=${1:-build/gas}
lattice_seeds=${LATTICE_SEEDS:-"41 42 43 44 45 46 47 48"}
large_seeds=${LARGE_SEEDS:-"51 52 53 54 55 56 57 58"}
lattice_until=800
large_until=1500
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

{
  for s in $lattice_seeds; do
    printf 'a 1\nT0 1\nA1 80.2121\nA2 80.2121\nlattice 1024 %s 1\n' "$s" >"$tmp/lattice-$s.scene"
    echo "lattice-$s $lattice_until"
  done
  for s in $large_seeds; do
    printf 'a 1\nT0 1\nA1 373.67\nA2 280.25\nrandom 10000 %s 1\n' "$s" >"$tmp/large-$s.scene"
    echo "large-$s $large_until"
  done
} | xargs -P 2 -n 2 sh -c '"$0" "$1/$2.scene" --until "$3" --mode none --csv "$1/$2.csv"' \
  "$gas" "$tmp"

# One state's table: a row per seed with (x - x_theory) / combined error for
# every theory column, then their root mean square and mean over the seeds,
# and each difference's mean over the seeds beside the scatter of the seeds
# and the typical combined error (like with like: those two should agree).
table() {
  local kind=$1 title=$2 seeds=$3
  echo "### $title"
  echo
  for s in $seeds; do
    echo "$tmp/$kind-$s.csv"
  done | xargs awk -F, -v window=200 '
    function num(v) { return (v == "nan" || v == "-nan" || v == "") ? "nan" : v + 0 }
    FNR == 1 {
      if (NR == 1) {
        for (i = 1; i <= NF; ++i) c[$i] = i
        for (i = 1; i <= NF; ++i) {
          if ($i ~ /_theory$/) { x = substr($i, 1, length($i) - 7); names[++pairs] = x }
        }
      }
      if (NR > 1) finish()
      file = FILENAME; first = ""; next
    }
    { last = $0 }
    $c["averages_since"] != "nan" && first == "" && $c["T"] >= $c["averages_since"] + window { first = $0 }
    function finish(   f, w, p, x, value, theory, err, e1, e2, z) {
      ++runs
      split(last, f, ",")
      seed = file; sub(/.*-/, "", seed); sub(/\.csv$/, "", seed)
      row[runs] = sprintf("| %s | %.0f |", seed, f[c["averages_since"]])
      for (p = 1; p <= pairs; ++p) {
        x = names[p]
        value = num(f[c[x]]); theory = num(f[c[x "_theory"]])
        if ((x "_deviation_error") in c) {
          err = num(f[c[x "_deviation_error"]])
        } else {
          e1 = num(f[c[x "_error"]])
          e2 = ((x "_theory_error") in c) ? num(f[c[x "_theory_error"]]) : 0
          err = (e1 == "nan" || e2 == "nan") ? "nan" : sqrt(e1 * e1 + e2 * e2)
        }
        if (value == "nan" || theory == "nan" || err == "nan" || err <= 0) {
          row[runs] = row[runs] " error not known |"; ++unknown[p]; continue
        }
        z = (value - theory) / err
        row[runs] = row[runs] sprintf(" %+.2f |", z)
        ++known[p]; zz[p] += z * z; zs[p] += z
        if (z > 3 || z < -3) ++beyond[p]
        d[p] += value - theory; dd[p] += (value - theory)^2; ee[p] += err * err
      }
      if (first != "") {
        split(first, w, ",")
        if (num(w[c["Z_deviation_error"]]) != "nan") {
          ++warm; wd += w[c["Z_deviation"]]; we += w[c["Z_deviation_error"]]^2
        }
      }
      ++all; ad += f[c["Z_deviation"]]; aq += f[c["Z_deviation"]]^2
    }
    END {
      finish()
      head = "| seed | averages from T |"; rule = "|---|---|"
      for (p = 1; p <= pairs; ++p) { head = head " " names[p] " |"; rule = rule "---|" }
      print head; print rule
      for (r = 1; r <= runs; ++r) print row[r]
      line = "| **root mean square** | |"
      for (p = 1; p <= pairs; ++p)
        line = line (known[p] ? sprintf(" **%.2f** |", sqrt(zz[p] / known[p])) : " - |")
      print line
      line = "| mean | |"
      for (p = 1; p <= pairs; ++p) line = line (known[p] ? sprintf(" %+.2f |", zs[p] / known[p]) : " - |")
      print line
      line = "| beyond 3, error not known | |"
      for (p = 1; p <= pairs; ++p) line = line sprintf(" %d, %d |", beyond[p], unknown[p])
      print line
      print ""
      print "| figure | mean of x − x_theory over the seeds | its scatter over the seeds (one run) | root mean square combined error |"
      print "|---|---|---|---|"
      for (p = 1; p <= pairs; ++p) {
        if (known[p] < 2) continue
        m = d[p] / known[p]
        printf "| %s | %+.3g | %.3g | %.3g |\n", names[p], m,
          sqrt((dd[p] - known[p] * m * m) / (known[p] - 1)), sqrt(ee[p] / known[p])
      }
      if (warm > 1) {
        printf "\nWarm-up: Z − Z_theory over the first %d time units of averages, mean over %d seeds %+.5f ± %.5f; over the whole runs %+.5f ± %.5f (the error from the seeds).\n",
          window, warm, wd / warm, sqrt(we) / warm, ad / all, sqrt((aq - ad * ad / all) / (all - 1) / all)
      }
      print ""
    }'
}

echo "# Lesson 14: the statistics' errors across seeds"
echo
echo "Generated by \`bash data/reports/kinetic-seeds.sh\` (build/gas as processes)."
echo "Each row is one run of build/gas (the last row of its --csv); each cell"
echo "is (x − x_theory) / combined error for a column x of the CSV that has an"
echo "x_theory: x_deviation_error where a deviation column exists, else"
echo "√(x_error² + x_theory_error²). The errors are batch means over 8 to 15"
echo "batches (stages/beyond/blocking.hpp; lesson 14)."
echo
table lattice "1024 balls on a lattice at η = 0.5, T = $lattice_until" "$lattice_seeds"
table large "10000 balls at random places at η = 0.3 (large-10000 with other seeds), T = $large_until" "$large_seeds"
