#!/bin/sh
# Restart: a run from 0 to T, and the same run restarted from its middle snapshot (the first
# step past T/2) to T, give identical fields and monitor on the same number of ranks, and agree
# to solver tolerance on another. In two parts, so that only the second holds two cores:
#   restart.sh same BAGNOLD MPIRUN WORK_DIR DECK T RANKS_TOLERANCE [--set key=value ...]
#     the run on 1 rank, the restart on 1 rank, compared; leaves the copy for the second part
#   restart.sh ranks BAGNOLD MPIRUN WORK_DIR DECK T RANKS_TOLERANCE [--set key=value ...]
#     the restart on 2 ranks from that copy, compared with the run on 1 (needs the first part)
set -eu
part=$1; bagnold=$2; mpirun=$3; work=$4; deck=$5; end=$6; ranks_tolerance=$7
shift 7
half=$(/usr/bin/python3 -c "print(f'{$end / 2:g}')")
common="--set output.snapshot_interval=$half --set output.progress=never $*"
if [ "$part" = ranks ]; then
  echo "restarted on 2 ranks:"
  rm -rf $work/half_np2; mkdir $work/half_np2
  cp $work/copy_np2/* $work/half_np2/
  $mpirun --oversubscribe -np 2 $bagnold run $deck $common --set run.end_time=$end --set output.directory=$work/half_np2 --restart $work/half_np2/snapshot_000001.h5 > $work/restart_np2.log
  /usr/bin/python3 tools/compare-snapshots $work/whole $work/half_np2 --tolerance $ranks_tolerance
  exit 0
fi
[ "$part" = same ] || { echo "restart.sh: the first argument is same or ranks, not '$part'"; exit 2; }
rm -rf "$work"; mkdir -p "$work"
$bagnold run $deck $common --set run.end_time=$end --set output.directory=$work/whole > $work/whole.log
# The copies keep the whole run up to its middle snapshot only: what follows must be recomputed.
for copy in half copy_np2; do
  mkdir $work/$copy
  cp $work/whole/snapshot_000000.h5 $work/whole/snapshot_000001.h5 $work/$copy/
  /usr/bin/python3 - "$work/whole" "$work/$copy" <<'PY'
import sys, h5py
whole, copy = sys.argv[1], sys.argv[2]
with h5py.File(f"{whole}/snapshot_000001.h5", "r") as f:
    t = float(f.attrs["time"])
with open(f"{whole}/monitor.csv") as src, open(f"{copy}/monitor.csv", "w") as dst:
    for line in src:
        if line[0].isdigit() and float(line.split(",")[0]) > t * (1 + 1e-12):
            break
        dst.write(line)
PY
done
$bagnold run $deck $common --set run.end_time=$end --set output.directory=$work/half --restart $work/half/snapshot_000001.h5 > $work/restart.log
grep -q "restart from .*snapshot_000001.h5 at t = " $work/restart.log
echo "same number of ranks:"
/usr/bin/python3 tools/compare-snapshots $work/whole $work/half --tolerance 0
# The monitor continues without a gap or a repeated row.
cmp $work/whole/monitor.csv $work/half/monitor.csv
