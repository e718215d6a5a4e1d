#!/bin/sh
# Restart: a run from 0 to T and a run from 0 to T/2 restarted from its snapshot to T give
# identical fields on the same number of ranks, and agree to solver tolerance on another.
#   restart.sh BAGNOLD MPIRUN WORK_DIR DECK T RANKS_TOLERANCE [--set key=value ...]
set -eu
bagnold=$1; mpirun=$2; work=$3; deck=$4; end=$5; ranks_tolerance=$6
shift 6
half=$(/usr/bin/python3 -c "print(f'{$end / 2:g}')")
common="--set output.snapshot_interval=$half --set output.progress=never $*"
rm -rf "$work"; mkdir -p "$work"
$bagnold run $deck $common --set run.end_time=$end --set output.directory=$work/whole > $work/whole.log
$bagnold run $deck $common --set run.end_time=$half --set output.directory=$work/half > $work/half.log
cp -r $work/half $work/half_np2
$bagnold run $deck $common --set run.end_time=$end --set output.directory=$work/half --restart $work/half > $work/restart.log
grep -q "restart from .*snapshot_000001.h5 at t = $half s" $work/restart.log
echo "same number of ranks:"
/usr/bin/python3 tools/compare-snapshots $work/whole $work/half --tolerance 0
# The monitor continues without a gap or a repeated row.
cmp $work/whole/monitor.csv $work/half/monitor.csv
echo "restarted on 2 ranks:"
$mpirun --oversubscribe -np 2 $bagnold run $deck $common --set run.end_time=$end --set output.directory=$work/half_np2 --restart $work/half_np2 > $work/restart_np2.log
/usr/bin/python3 tools/compare-snapshots $work/whole $work/half_np2 --tolerance $ranks_tolerance
