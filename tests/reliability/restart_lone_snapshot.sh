#!/bin/sh
# A restart from a snapshot copied alone into a fresh directory numbers its snapshots after it,
# so the one it started from is never overwritten: the cavity runs to t = 0.1 s (steps and
# snapshots every 0.02 s: snapshot_000005.h5 at 0.1 s), that file alone is copied to a new directory and
# restarted there to 0.16 s, beside stray files no run writes (snapshot_+00007.h5,
# snapshot_00009.h5, snapshot_000010.h5.tmp: not snapshots, ignored). The directory must then
# hold 000005 (still at t = 0.1 s) and 000006-000008 (0.12-0.16 s), and run.xmf must list all four.
#   restart_lone_snapshot.sh BAGNOLD WORK_DIR
set -eu
bagnold=$1; work=$2
deck=tests/verification/lid_driven_cavity/re100.toml
grid="--set grid.x.cells=16 --set grid.z.cells=16 --set output.progress=never --set output.snapshot_interval=0.02 --set run.dt_initial=0.02 --set run.dt_max=0.02"
rm -rf "$work"
$bagnold run $deck $grid --set run.end_time=0.1 --set output.directory=$work/first > /dev/null
mkdir -p "$work/second"
cp "$work/first/snapshot_000005.h5" "$work/second/"
for stray in snapshot_+00007.h5 snapshot_00009.h5 snapshot_000010.h5.tmp; do
  echo "not a snapshot" > "$work/second/$stray"
done
$bagnold run $deck $grid --set run.end_time=0.16 --set output.directory=$work/second \
  --restart "$work/second/snapshot_000005.h5" > /dev/null
/usr/bin/python3 - "$work/second" <<'PY'
import os, sys
import h5py
d = sys.argv[1]
stray = {"snapshot_+00007.h5", "snapshot_00009.h5", "snapshot_000010.h5.tmp"}
names = sorted(n for n in os.listdir(d) if n.startswith("snapshot_") and n not in stray)
times = [float(h5py.File(os.path.join(d, n), "r").attrs["time"]) for n in names]
print(", ".join(f"{n} at t = {t:.3g} s" for n, t in zip(names, times)))
xmf = open(os.path.join(d, "run.xmf")).read()
want = [f"snapshot_{i:06d}.h5" for i in range(5, 9)]
ok = (names == want and abs(times[0] - 0.1) < 1e-9 and all(n in xmf for n in want))
sys.exit(0 if ok else 1)
PY
