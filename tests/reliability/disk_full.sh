#!/bin/sh
# A disk that fills during a run: the run stops with exit code 1 and a message naming the file;
# every snapshot left under a final name is complete and readable, and no temporary remains.
# On several ranks every rank must stop (within 120 s, or the test fails), not wait in a
# collective that another has left. Needs to mount a small tmpfs (root); skipped (exit 77) where
# that is not allowed.
#   disk_full.sh BAGNOLD WORK_DIR [MPIRUN RANKS]
set -u
bagnold=$1; work=$2
launcher=""
[ $# -ge 4 ] && launcher="$3 --oversubscribe -np $4"
mkdir -p "$work"
umount "$work" 2>/dev/null
mount -t tmpfs -o size=160k tmpfs "$work" 2>/dev/null || { echo "cannot mount a tmpfs here: skipped"; exit 77; }
trap 'umount "$work"' EXIT
# The channel from rest converges its first steps slowly at the deck's dt and tolerance (8 steps
# redone at t = 0: 16 s on 3 oversubscribed ranks, past 120 s under load); a short first step, a
# looser tolerance and an early second snapshot reach the full disk in about 20 steps.
timeout 120 $launcher $bagnold run tests/verification/poiseuille/channel.toml --set output.directory=$work/run \
  --set run.dt_initial=5e-5 --set numerics.tolerance=1e-5 \
  --set output.snapshot_interval=0.001 --set output.progress=never > $work/../disk_full.log 2>&1
code=$?
tail -1 $work/../disk_full.log
[ "$code" -eq 124 ] && { echo "FAIL: the ranks did not stop within 120 s"; exit 1; }
[ "$code" -eq 1 ] || { echo "FAIL: exit code $code, expected 1"; exit 1; }
grep -Eq "cannot (write|write the snapshot|append to the monitor) $work/run/[^ ]+ .*disk full" $work/../disk_full.log \
  || { echo "FAIL: the message does not name the file"; exit 1; }
ls $work/run/*.tmp 2>/dev/null && { echo "FAIL: a temporary file was left"; exit 1; }
/usr/bin/python3 - "$work/run" <<'PY' || exit 1
import glob, sys, h5py
files = sorted(glob.glob(sys.argv[1] + "/snapshot_*.h5"))
for name in files:
    with h5py.File(name, "r") as f:
        f["fields/gas_velocity_x"][:]
print(f"{len(files)} snapshot(s) left, all readable")
PY
