#!/bin/sh
# The snapshot schedule does not change the answer (with the pressure preconditioner built every
# step, numerics.pressure_preconditioner_steps = 1): the 10 mm bin discharging to 0.1 s with
# snapshots every 0.02 s and every 0.05 s takes the same steps (identical monitors) and ends in
# identical fields. Each snapshot is written at the end of the first step past its time.
#   snapshot_schedule.sh BAGNOLD WORK_DIR
set -eu
bagnold=$1; work=$2
deck=cases/bin/bin-10mm.toml
rm -rf "$work"
# The deck keeps its pressure preconditioner for 20 steps but builds it again after each
# snapshot; only a build every step (the default) makes the schedule leave no trace.
for interval in 0.02 0.05; do
  $bagnold run $deck --set run.end_time=0.1 --set output.progress=never \
    --set numerics.pressure_preconditioner_steps=1 \
    --set output.snapshot_interval=$interval --set output.directory=$work/every_$interval > "$work.$interval.log"
done
cmp "$work/every_0.02/monitor.csv" "$work/every_0.05/monitor.csv"
/usr/bin/python3 tools/compare-snapshots "$work/every_0.02" "$work/every_0.05" --tolerance 0
# More snapshots in the first: 0, one per 0.02 s passed, the final one.
/usr/bin/python3 - "$work" <<'PY'
import glob, sys
import h5py
d = sys.argv[1]
counts = {i: len(glob.glob(f"{d}/every_{i}/snapshot_*.h5")) for i in ("0.02", "0.05")}
times = sorted(float(h5py.File(f, "r").attrs["time"]) for f in glob.glob(f"{d}/every_0.02/snapshot_*.h5"))
print("snapshots:", counts, "times (every 0.02 s):", ", ".join(f"{t:.5f}" for t in times))
ok = counts["0.02"] >= 5 and counts["0.05"] >= 2 and counts["0.02"] > counts["0.05"]
ok = ok and abs(times[-1] - 0.1) < 1e-12 and all(t >= 0.02 * k - 1e-12 for k, t in enumerate(times))
sys.exit(0 if ok else 1)
PY
