#!/usr/bin/env bash
# The statistics' seed tables (beyond the article; lessons 13 and 14): do the
# error bars hold, and does the theory of the same thing agree? Runs build/gas
# itself, as a process, on seeds nobody tuned on:
#
#   bash data/reports/kinetic-seeds.sh [GAS] > data/reports/kinetic-seeds.md
#   SECTIONS=eos bash data/reports/kinetic-seeds.sh > data/reports/equation-of-state.md
#
# Five sections (SECTIONS="theory spread closed speeds", the default, runs
# four; SECTIONS=eos the fifth); each table follows a line
# '<!-- section: NAME -->', which the lessons quote (lessons/README.md, "How
# the lessons quote"):
#
# theory: every figure of --csv that has a theory (every column x with an
#   x_theory) beside it, normalised by the combined error: over the seeds
#   those numbers should scatter like a standard normal (root mean square
#   about 1; 0.7 to 1.4 with 8 seeds), and no run should be off by more
#   than 3. The combined error of x - x_theory: x_deviation_error where the
#   CSV has a deviation column (the difference taken sample by sample, so
#   that what the figure and its theory share cancels), else
#   sqrt(x_error^2 + x_theory_error^2) (no x_theory_error: the theory is
#   exact). Runs: 1024 balls of radius 1 on a lattice at eta = 0.5 (side
#   80.2121), every speed 1, to T = 800 (LATTICE_SEEDS, default 41 to 48);
#   scenes like data/large-10000.scene (10000 balls at eta = 0.3 at random
#   places) to T = 1500 (LARGE_SEEDS, default 51 to 58). And the warm-up: on
#   the lattice starts, Z - Z_theory over the first 200 time units of
#   averages against the whole run. Sections theory-lattice, theory-large
#   (a row per seed) and theory (the root mean squares of both).
# spread: are the errors honest where a student reads them? 40 gases like
#   data/large-1000.scene (`random 1000 SEED 1`, SPREAD_SEEDS, default 201
#   to 240) to T = 12000; at T = 150, 400, 1000, 3000 and 12000, for each of
#   eight figures x_s with error e_s (scaled by the power of the seed's own
#   kT the figure goes with: eta_interior, Z and g_contact none, the speeds,
#   rates and the exponent 1/2, kT_interior and the pressure 1), the spread
#   of (x_s - mean) / e_s over the seeds whose error is known (the root mean
#   square, over n - 1; about 1 for honest errors: 1.04 to 1.07 for
#   Student's t of 16 to 31 batches, about 1.17 for the exponent's six
#   overlapping ones, within some 0.15 over 40 seeds), and how many seeds
#   show no error yet.
# closed: the closed box's 1/N (kinetic_theory.hpp, fixed_count_shift; lesson 13):
#   lattice gases of N = 256 balls (CLOSED_SEEDS_256, default 301 to 340)
#   and N = 1024 (CLOSED_SEEDS_1024, default 401 to 424) at eta = 0.1, 0.2,
#   0.3, 0.4, 0.45, every speed 1, to T = 12000: the mean of Z_deviation over
#   the seeds with its standard error (from the seeds' scatter), which
#   should be within 3 of them of zero, and the mean of (Z - Z_open) /
#   Z_open, Z_open the open bulk's reference at eta_int (Z_theory less
#   Z_fixed_N_shift), beside the shift the formula predicts.
# speeds: how fast the figures forget (gas_statistics.hpp,
#   speeds_batch_collisions; lesson 14): the spread's 40 gases again, to
#   T = 1500 with a row every time unit; from each run's mean_speed_average,
#   eta_interior, kT_interior and pressure (the push on the walls' middles)
#   their series over single time units (the sums between rows), scaled by
#   the seed's kT to their powers; over the
#   seeds their autocorrelation at lags of 1 to 400 time units (section
#   speeds), the mean speed's lag below 1/e (interpolated) in time units and
#   in pair collisions per ball at the gases' mean rate, collision_rate_box
#   (speeds-fold), and the spread over the seeds of each average over the
#   first W time units against what independent time units would give
#   (speeds-windows: flat in W, no slow part; falling for the push, whose
#   noise the sound it sends cancels), and that spread of the push beside
#   the error the program quotes for it from theory (speeds-push).
# eos: the equation of state of lesson 13: data/eos-0.1.scene, eos-0.3 and
#   eos-0.5 (4096 balls on a lattice) to T = 2000, 4000, 2000; the last row
#   of each --csv: Z, its theory for N balls, their difference sample by
#   sample with its error, Henderson's, the box's two Z's (section eos); and
#   at the walls, g(2a+) against its reference, kT n at the walls' middles
#   against the push there, the whole walls' push, the bulk's (eos-walls).
#
# GAS: the program (default build/gas). Two runs at a time (the machine may
# be shared); on an idle machine some 3 CPU-minutes for theory, 4 for
# spread, 16 for closed, half a minute for speeds and for eos.
set -euo pipefail
gas=${1:-build/gas}
sections=${SECTIONS:-"theory spread closed speeds"}
lattice_seeds=${LATTICE_SEEDS:-"41 42 43 44 45 46 47 48"}
large_seeds=${LARGE_SEEDS:-"51 52 53 54 55 56 57 58"}
spread_seeds=${SPREAD_SEEDS:-$(seq -s ' ' 201 240)}
closed_seeds_256=${CLOSED_SEEDS_256:-$(seq -s ' ' 301 340)}
closed_seeds_1024=${CLOSED_SEEDS_1024:-$(seq -s ' ' 401 424)}
lattice_until=800
large_until=1500
spread_until=12000
speeds_until=1500
closed_until=12000
closed_etas="0.1 0.2 0.3 0.4 0.45"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

has() { case " $sections " in *" $1 "*) return 0 ;; *) return 1 ;; esac; }

# The scenes, and a list "NAME UNTIL" for the runs.
{
  if has theory; then
    for s in $lattice_seeds; do
      printf 'a 1\nT0 1\nA1 80.2121\nA2 80.2121\nlattice 1024 %s 1\n' "$s" >"$tmp/lattice-$s.scene"
      echo "lattice-$s $lattice_until"
    done
    for s in $large_seeds; do
      printf 'a 1\nT0 1\nA1 373.67\nA2 280.25\nrandom 10000 %s 1\n' "$s" >"$tmp/large-$s.scene"
      echo "large-$s $large_until"
    done
  fi
  if has spread; then
    for s in $spread_seeds; do
      printf 'a 1\nT0 50\nA1 118.16\nA2 88.62\nrandom 1000 %s 1\n' "$s" >"$tmp/spread-$s.scene"
      echo "spread-$s $spread_until"
    done
  fi
  if has speeds; then
    for s in $spread_seeds; do
      printf 'a 1\nT0 1\nA1 118.16\nA2 88.62\nrandom 1000 %s 1\n' "$s" >"$tmp/speeds-$s.scene"
      echo "speeds-$s $speeds_until"
    done
  fi
  if has closed; then
    for eta in $closed_etas; do
      for n in 256 1024; do
        side=$(awk -v n="$n" -v eta="$eta" 'BEGIN { printf "%.6f", sqrt(n * 3.141592653589793 / eta) }')
        if [ "$n" = 256 ]; then seeds=$closed_seeds_256; else seeds=$closed_seeds_1024; fi
        for s in $seeds; do
          printf 'a 1\nT0 1000\nA1 %s\nA2 %s\nlattice %s %s 1\n' "$side" "$side" "$n" "$s" \
            >"$tmp/closed-$n-$eta-$s.scene"
          echo "closed-$n-$eta-$s $closed_until"
        done
      done
    done
  fi
  if has eos; then
    for e in 0.1:2000 0.3:4000 0.5:2000; do
      cp "data/eos-${e%%:*}.scene" "$tmp/eos-${e%%:*}.scene"
      echo "eos-${e%%:*} ${e##*:}"
    done
  fi
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
  echo "<!-- section: theory-$kind -->"
  for s in $seeds; do
    echo "$tmp/$kind-$s.csv"
  done | xargs awk -F, -v window=200 -v title="$title" -v summary="$tmp/summary-$kind" '
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
      short = "| " title " |"; names_line = "| state |"; rule_line = "|---|"
      for (p = 1; p <= pairs; ++p) {
        line = line (known[p] ? sprintf(" **%.2f** |", sqrt(zz[p] / known[p])) : " - |")
        short = short (known[p] ? sprintf(" %.2f |", sqrt(zz[p] / known[p])) : " no error |")
        names_line = names_line " " names[p] " |"; rule_line = rule_line "---|"
      }
      print line
      print names_line > (summary ".head"); print rule_line > (summary ".head")
      print short > summary
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

# The spread of (x_s - mean) / e_s over the seeds, figure by figure, at
# each of the times given.
spread_table() {
  local seeds=$1 times=$2
  for s in $seeds; do
    echo "$tmp/spread-$s.csv"
  done | xargs awk -F, -v times="$times" '
    function num(v) { return (v == "nan" || v == "-nan" || v == "") ? "nan" : v + 0 }
    BEGIN {
      split("eta_interior kT_interior mean_speed_average Z g_contact collision_rate pressure lyapunov", names, " ")
      split("0 1 0.5 0 0 0.5 1 0.5", power, " ")
      figures = 8
      ntimes = split(times, at, " ")
    }
    FNR == 1 { if (NR == 1) for (i = 1; i <= NF; ++i) c[$i] = i; ++runs; next }
    {
      for (t = 1; t <= ntimes; ++t) {
        if ($c["T"] + 0 != at[t] + 0) continue
        kT = $c["kT"]
        for (f = 1; f <= figures; ++f) {
          x = num($c[names[f]]); e = num($c[names[f] "_error"])
          key = t SUBSEP f
          if (x == "nan" || e == "nan" || e <= 0) { ++blank[key]; continue }
          scale = kT ^ power[f]
          n[key]++; xs[key, n[key]] = x / scale; es[key, n[key]] = e / scale
        }
      }
    }
    END {
      head = "| figure (scaled by kT to the power) |"; rule = "|---|"
      for (t = 1; t <= ntimes; ++t) { head = head sprintf(" T = %s |", at[t]); rule = rule "---|" }
      print head; print rule
      for (f = 1; f <= figures; ++f) {
        line = sprintf("| %s (%s) |", names[f], power[f])
        for (t = 1; t <= ntimes; ++t) {
          key = t SUBSEP f
          if (n[key] < 3) { line = line sprintf(" no error (%d of %d) |", blank[key] + 0, runs); continue }
          mean = 0
          for (i = 1; i <= n[key]; ++i) mean += xs[key, i] / n[key]
          zz = 0
          for (i = 1; i <= n[key]; ++i) zz += ((xs[key, i] - mean) / es[key, i])^2
          line = line sprintf(" %.2f (%d of %d no error) |", sqrt(zz / (n[key] - 1)), blank[key] + 0, runs)
        }
        print line
      }
      print ""
    }'
}

# The closed box: the mean Z_deviation over the seeds at each N and eta.
closed_table() {
  echo "| η | N | seeds | mean Z_deviation ± its standard error | in standard errors | (Z − Z_open)/Z_open, mean ± error | the formula's shift / Z_open |"
  echo "|---|---|---|---|---|---|---|"
  for eta in $closed_etas; do
    for n in 256 1024; do
      if [ "$n" = 256 ]; then seeds=$closed_seeds_256; else seeds=$closed_seeds_1024; fi
      for s in $seeds; do echo "$tmp/closed-$n-$eta-$s.csv"; done | xargs awk -F, -v eta="$eta" -v n="$n" '
        FNR == 1 { if (NR == 1) for (i = 1; i <= NF; ++i) c[$i] = i; next }
        { last[FILENAME] = $0 }
        END {
          for (file in last) {
            split(last[file], f, ",")
            d = f[c["Z_deviation"]]; open = f[c["Z_theory"]] - f[c["Z_fixed_N_shift"]]
            r = (f[c["Z"]] - open) / open
            ++k; sd += d; sdd += d * d; sr += r; srr += r * r
            shift += f[c["Z_fixed_N_shift"]] / open
          }
          md = sd / k; ed = sqrt((sdd - k * md * md) / (k - 1) / k)
          mr = sr / k; er = sqrt((srr - k * mr * mr) / (k - 1) / k)
          printf "| %s | %d | %d | %+.5f ± %.5f | %+.1f | %+.3f ± %.3f %% | %+.3f %% |\n",
            eta, n, k, md, ed, md / ed, 100 * mr, 100 * er, 100 * shift / k
        }'
    done
  done
  echo
}

command="bash data/reports/kinetic-seeds.sh"
if [ "$sections" != "theory spread closed speeds" ]; then command="SECTIONS=\"$sections\" $command"; fi
echo "# The statistics' errors and theories across seeds"
echo
echo "Generated by \`$command\` (build/gas as processes)."
echo "The errors are batch means over 16 to 31 batches,"
echo "known once the batches are as long as the table's heat time (for the"
echo "figures that follow it; 25 pair collisions per ball for the mean speed)"
echo "and Jonsson's test sees them uncorrelated (stages/beyond/blocking.hpp);"
echo "until then the interior's η, kT, Z, collision rate and free path take"
echo "theirs from the box's heat and sound (stages/beyond/box_modes.hpp), the"
echo "mean speed from kinetic theory (stages/beyond/speed_relaxation.hpp), the"
echo "push on the walls' middles from the fluid's friction on them and the box's"
echo "sound (stages/beyond/wall_push.hpp). The Lyapunov exponent's error is"
echo "overlapping batches a sixth of the run, never shorter than 16 samples"
echo "(stages/beyond/overlapping_batches.hpp; its samples are anticorrelated)."
echo
if has theory; then
  echo "## Each figure against its theory"
  echo
  echo "Each row is one run of build/gas (the last row of its --csv); each cell"
  echo "is (x − x_theory) / combined error for a column x of the CSV that has an"
  echo "x_theory: x_deviation_error where a deviation column exists, else"
  echo "√(x_error² + x_theory_error²)."
  echo
  table lattice "1024 balls on a lattice at η = 0.5, T = $lattice_until" "$lattice_seeds"
  table large "10000 balls at random places at η = 0.3 (large-10000 with other seeds), T = $large_until" "$large_seeds"
  echo "### Both states: the root mean squares"
  echo
  echo "<!-- section: theory -->"
  head -2 "$tmp/summary-lattice.head"
  cat "$tmp/summary-lattice" "$tmp/summary-large"
  echo
fi
if has spread; then
  echo "## The spread of each figure over seeds"
  echo
  echo "$(echo "$spread_seeds" | wc -w) gases like data/large-1000.scene (\`random 1000 SEED 1\`, seeds"
  echo "$(echo "$spread_seeds" | awk '{ print $1 }') to $(echo "$spread_seeds" | awk '{ print $NF }')); each cell the spread of (x_s − mean) / e_s over the"
  echo "seeds whose error is known (root mean square, over n − 1; honest errors"
  echo "give about 1), and how many seeds show no error yet."
  echo
  echo "<!-- section: spread -->"
  spread_table "$spread_seeds" "150 400 1000 3000 12000"
fi
if has closed; then
  echo "## The closed box: Z at the gas's own N"
  echo
  echo "Lattice gases, every speed 1, square tables, to T = $closed_until. Z_deviation"
  echo "is Z less the reference for a closed box of N balls (the open bulk's"
  echo "plus the shift of stages/beyond/kinetic_theory.hpp); Z_open is the open"
  echo "bulk's reference at the interior's density."
  echo
  echo "<!-- section: closed -->"
  closed_table
fi
if has speeds; then
  echo "## How fast the figures forget"
  echo
  echo "The spread's $(echo "$spread_seeds" | wc -w) gases to T = $speeds_until, a row every time unit:"
  echo "each figure over each time unit from the averages' start (the sums"
  echo "between rows: the mean speed over √kT, η_int, kT_int and the push on"
  echo "the walls' middles over kT), its autocorrelation over the seeds, and the"
  echo "spread over the seeds of its average over the first W time units against"
  echo "independent time units' (the ratio: the square root of the statistical"
  echo "inefficiency over W). Last, the push's spread beside the error the"
  echo "program quotes for it from theory (beyond/wall_push.hpp), the root mean"
  echo "square over the seeds at the row that ends the W-th time unit."
  echo
  for s in $spread_seeds; do echo "$tmp/speeds-$s.csv"; done | xargs awk -F, '
    function num(v) { return (v == "nan" || v == "-nan" || v == "") ? "nan" : v + 0 }
    FNR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; ++runs; have = 0; next }
    {
      since = num($c["averages_since"]); t = $c["T"] - since
      if (since == "nan" || t <= 0) next
      # Running sums: the mean speed, the interior ball-time (as eta t) and
      # its kinetic energy (as kT_int eta t).
      speed = $c["mean_speed_average"] * t; inside = $c["eta_interior"] * t
      energy = $c["kT_interior"] * inside; push = $c["pressure"] * t
      if (have && t - last_t > 0.999 && t - last_t < 1.001) {
        ++len[runs]
        x[1, runs, len[runs]] = speed - last_speed
        x[2, runs, len[runs]] = inside - last_inside
        x[3, runs, len[runs]] = (energy - last_energy) / (inside - last_inside)
        x[4, runs, len[runs]] = push - last_push
        push_error[runs, len[runs]] = num($c["pressure_error"])
      }
      last_t = t; last_speed = speed; last_inside = inside; last_energy = energy
      last_push = push; have = 1
      kT[runs] = $c["kT"]; rate[runs] = $c["collision_rate_box"]
    }
    END {
      split("mean speed|eta_interior|kT_interior|pressure", names, "|")
      split("0.5 0 1 1", power, " ")
      n = len[1]
      for (r = 1; r <= runs; ++r) if (len[r] < n) n = len[r]
      for (f = 1; f <= 4; ++f) {
        for (r = 1; r <= runs; ++r) for (i = 1; i <= n; ++i) {
          x[f, r, i] /= kT[r] ^ power[f]; mean[f] += x[f, r, i] / (runs * n)
        }
        for (r = 1; r <= runs; ++r) for (i = 1; i <= n; ++i) var[f] += (x[f, r, i] - mean[f]) ^ 2 / (runs * n)
      }
      for (r = 1; r <= runs; ++r) mean_rate += rate[r] / runs
      split("1 2 3 5 10 20 30 40 50 60 100 200 400", lags, " ")
      print "<!-- section: speeds -->"
      header = "| autocorrelation at lag (time units) |"; rule = "|---|"
      for (k = 1; k in lags; ++k) { header = header " " lags[k] " |"; rule = rule "---|" }
      print header; print rule
      for (f = 1; f <= 4; ++f) {
        row = "| " names[f] " |"
        for (k = 1; k in lags; ++k) row = row sprintf(" %.3f |", acf(f, lags[k]))
        print row
      }
      print ""
      previous = 1
      for (lag = 1; lag < n; ++lag) {
        a = acf(1, lag)
        if (a < exp(-1)) { fold = lag - 1 + (previous - exp(-1)) / (previous - a); break }
        previous = a
      }
      print "<!-- section: speeds-fold -->"
      print "| the mean speed: below 1/e after (time units) | pair collisions per ball | rate per ball |"
      print "|---|---|---|"
      printf "| %.1f | %.1f | %.3f |\n\n", fold, fold * mean_rate, mean_rate
      print "<!-- section: speeds-windows -->"
      print "| W (time units) | mean speed | eta_interior | kT_interior | pressure |"
      print "|---|---|---|---|---|"
      split("30 100 270 870 1300", windows, " ")
      for (k = 1; k in windows; ++k) {
        w = windows[k]; if (w > n) break
        row = sprintf("| %d |", w)
        for (f = 1; f <= 4; ++f) {
          row = row sprintf(" %.2f |", sqrt(scatter(f, w) / (var[f] / w)))
        }
        print row
      }
      print ""
      print "<!-- section: speeds-push -->"
      print "| W (time units) | the push: scatter over the seeds | error from theory | scatter / error |"
      print "|---|---|---|---|"
      split("30 100 200 270 400 870 1300", windows, " ")
      for (k = 1; k in windows; ++k) {
        w = windows[k]; if (w > n) break
        e = 0; known = 0
        for (r = 1; r <= runs; ++r) if (push_error[r, w] != "nan") { e += (push_error[r, w] / kT[r]) ^ 2; ++known }
        if (known < runs) { printf "| %d | %.3g | not known in %d of %d | |\n", w, sqrt(scatter(4, w)), runs - known, runs; continue }
        printf "| %d | %.3g | %.3g | %.2f |\n", w, sqrt(scatter(4, w)), sqrt(e / known), sqrt(scatter(4, w) / (e / known))
      }
    }
    # The variance over the seeds of figure f averaged over the first w time units.
    function scatter(f, w,   r, i, m, v, a_w) {
      for (r = 1; r <= runs; ++r) { a_w[r] = 0; for (i = 1; i <= w; ++i) a_w[r] += x[f, r, i] / w; m += a_w[r] / runs }
      for (r = 1; r <= runs; ++r) v += (a_w[r] - m) ^ 2 / (runs - 1)
      return v
    }
    function acf(f, lag,   r, i, s, m) {
      for (r = 1; r <= runs; ++r) for (i = 1; i + lag <= n; ++i) { s += (x[f, r, i] - mean[f]) * (x[f, r, i + lag] - mean[f]); ++m }
      return s / m / var[f]
    }'
  echo
fi
if has eos; then
  echo "## The equation of state (lesson 13)"
  echo
  echo "data/eos-0.1.scene, eos-0.3.scene, eos-0.5.scene to T = 2000, 4000, 2000;"
  echo "the last row of each --csv. Z_theory is the reference for a closed box of"
  echo "4096 balls at η_int; Z − Z_theory is Z_deviation (sample by sample), with"
  echo "its error, in errors σ; Z's own error from the box's heat and sound"
  echo "while its batches are short, the box's Z without one until then."
  echo
  # A value with its error, or alone while the error is not known (both tables).
  awk_shown='function shown(v, e) { return (e == "nan" || e == "-nan") ? sprintf("%.5f", v) : sprintf("%.5f ± %.5f", v, e) }'
  echo "<!-- section: eos -->"
  echo "| N/A | η_int | Z bulk | Z_theory | Z − Z_theory | Henderson | Z box: walls | Z box: virial |"
  echo "|---|---|---|---|---|---|---|---|"
  for eta in 0.1 0.3 0.5; do
    awk -F, -v eta="$eta" "$awk_shown"'
      NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
      { last = $0 }
      END {
        split(last, f, ",")
        d = f[c["Z_deviation"]]; de = f[c["Z_deviation_error"]]
        printf "| %s | %.5f | %s | %.5f | %+.5f ± %.5f (%+.1f σ) | %.5f | %s | %s |\n", eta,
          f[c["eta_interior"]], shown(f[c["Z"]], f[c["Z_error"]]), f[c["Z_theory"]], d, de, d / de,
          f[c["Z_henderson"]], shown(f[c["Z_box_walls"]], f[c["Z_box_walls_error"]]),
          shown(f[c["Z_box_virial"]], f[c["Z_box_virial_error"]])
      }' "$tmp/eos-$eta.csv"
  done
  echo
  echo "At the walls, the same runs: g(2a+) and its reference at η_int; kT n(contact)"
  echo "at the walls' middles against the push on them (the contact theorem: kT n"
  echo "less the push, in errors of kT n); the push on the whole walls; the bulk's"
  echo "pressure, the reference for N balls in the strips in front of the middles."
  echo
  echo "<!-- section: eos-walls -->"
  echo "| N/A | g(2a+) | reference g(2a) | kT n at the walls' middles | P on the walls' middles | contact theorem | P on the whole walls | bulk P |"
  echo "|---|---|---|---|---|---|---|---|"
  for eta in 0.1 0.3 0.5; do
    awk -F, -v eta="$eta" "$awk_shown"'
      NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
      { last = $0 }
      END {
        split(last, f, ",")
        k = f[c["wall_contact_pressure"]]; ke = f[c["wall_contact_pressure_error"]]; p = f[c["pressure"]]
        printf "| %s | %s | %.5f | %s | %s | %+.1f σ | %s | %.5f |\n", eta,
          shown(f[c["g_contact"]], f[c["g_contact_error"]]), f[c["g_contact_theory"]],
          shown(k, ke), shown(p, f[c["pressure_error"]]), (k - p) / ke,
          shown(f[c["pressure_box"]], f[c["pressure_box_error"]]), f[c["pressure_theory"]]
      }' "$tmp/eos-$eta.csv"
  done
  echo
fi
