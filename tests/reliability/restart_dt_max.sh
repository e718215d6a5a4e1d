#!/bin/sh
# A restart obeys the deck's dt limits, not only the snapshot's next dt: the cavity runs to
# t = 0.1 s (next dt 0.05 s), is restarted with dt_max = 0.002 s to 0.11 s, and every step after
# the restart must be at most 0.002 s.
#   restart_dt_max.sh BAGNOLD WORK_DIR
set -eu
bagnold=$1; work=$2
deck=tests/verification/lid_driven_cavity/re100.toml
grid="--set grid.x.cells=16 --set grid.z.cells=16 --set output.progress=never"
rm -rf "$work"
$bagnold run $deck $grid --set run.end_time=0.1 --set output.directory=$work > /dev/null
$bagnold run $deck $grid --set run.end_time=0.11 --set run.dt_max=0.002 --set run.dt_initial=0.002 \
  --set output.directory=$work --restart $work > /dev/null
/usr/bin/python3 - "$work/monitor.csv" <<'PY'
import csv, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if float(r["time"]) > 0.1 + 1e-9]
largest = max(float(r["dt"]) for r in rows)
print(f"{len(rows)} steps after the restart, largest dt {largest:g} s (bound 0.002 s)")
sys.exit(0 if len(rows) >= 5 and largest <= 0.002 * (1 + 1e-12) else 1)
PY
