#!/bin/sh
# The memory estimate `bagnold check` prints (src/run/memory_estimate.cpp) against the peak
# resident memory of a run of the same grid, measured by /usr/bin/time -v: the 10 mm bin's deck
# on 16 x 16 x 200 cells, one step, on 1 and on 2 ranks (per rank). They must agree within 20 %:
# the fit was within 2 % of its five measurements; 20 % leaves room for other machines and
# libraries, and still fails if the solver's memory per cell changes by a fifth.
#   memory_estimate.sh BAGNOLD MPIEXEC WORK_DIR
# Skipped (77) where /usr/bin/time is missing.
set -eu
bagnold=$1; mpiexec=$2; work=$3
[ -x /usr/bin/time ] || { echo "skipped: /usr/bin/time (Debian package time) is missing"; exit 77; }
grid="cases/bin/bin-10mm.toml --set grid.x.cells=16 --set grid.y.cells=16 --set grid.z.cells=200"
rm -rf "$work"; mkdir -p "$work"
for ranks in 1 2; do
  launch=""
  [ "$ranks" -gt 1 ] && launch="$mpiexec --oversubscribe -np $ranks"
  $launch $bagnold check $grid > "$work/check_$ranks.log"
  estimate=$(sed -n 's/^memory: about \([0-9.e+]*\) \([MG]\)B per rank.*/\1 \2/p' "$work/check_$ranks.log" |
             awk '{ print ($2 == "G" ? $1 * 1000 : $1) }')
  $launch /usr/bin/time -v $bagnold run $grid --set run.end_time=1e-4 --set run.dt_initial=1e-4 \
    --set output.progress=never --set output.directory="$work/run_$ranks" > "$work/run_$ranks.log" 2>&1
  # The largest rank's peak, in MB (time reports kB = 1024 B).
  measured=$(sed -n 's/.*Maximum resident set size (kbytes): \([0-9]*\)/\1/p' "$work/run_$ranks.log" |
             awk 'BEGIN { m = 0 } { if ($1 > m) m = $1 } END { print m * 1024 / 1e6 }')
  echo "$ranks rank(s): estimate $estimate MB per rank, measured peak $measured MB"
  awk -v e="$estimate" -v m="$measured" 'BEGIN { r = e / m; exit !(m > 0 && r > 0.8 && r < 1.2) }' || {
    echo "FAIL: the estimate is not within 20 % of the measured peak"; exit 1; }
done
