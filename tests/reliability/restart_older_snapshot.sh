#!/bin/sh
# A restart from snapshots written before the field pressure_shear_rate existed: the chute
# (sidewalls.toml with P_s's shear rate lagged over 0.5 ms) runs to 0.02 s with snapshots every 0.01 s (each at
# the first step past its time); the field is then deleted from every snapshot (as an older
# Bagnold wrote them) and the run restarts from the one near 0.01 s to 0.03 s. The restart must run, the new snapshots must have the field, and run.xmf
# must name only datasets that exist (the older snapshots' entries without the field).
#   restart_older_snapshot.sh BAGNOLD WORK_DIR
set -eu
bagnold=$1; work=$2
deck=cases/chute/sidewalls.toml
common="--set numerics.pressure_shear_rate_relaxation_time=0.0005 --set output.progress=never --set output.snapshot_interval=0.01 --set output.directory=$work"
rm -rf "$work"
$bagnold run $deck $common --set run.end_time=0.02 > /dev/null
/usr/bin/python3 - "$work" <<'PY'
import glob, sys
import h5py
for path in glob.glob(sys.argv[1] + "/snapshot_*.h5"):
    with h5py.File(path, "a") as f:
        del f["fields/pressure_shear_rate"]
        del f["boundary/pressure_shear_rate"]
PY
$bagnold run $deck $common --set run.end_time=0.03 --restart "$work/snapshot_000001.h5" > "$work.log"
grep -q "restart from .*snapshot_000001.h5 at t = 0.01[0-9]* s" "$work.log"
/usr/bin/python3 tests/cli/check_xdmf.py "$work" 4
/usr/bin/python3 - "$work" <<'PY'
import sys
import h5py
d = sys.argv[1]
has = [("pressure_shear_rate" in h5py.File(f"{d}/snapshot_{i:06d}.h5", "r")["fields"]) for i in range(4)]
print("pressure_shear_rate in snapshots 0-3:", has)
sys.exit(0 if has == [False, False, True, True] else 1)
PY
