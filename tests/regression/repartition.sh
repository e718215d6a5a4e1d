#!/bin/sh
# Repartitioning during a run (numerics.repartition_imbalance): the 10 mm bin on 2 ranks to
# 0.02 s, snapshots every 0.005 s, starting from the partition by cells (one rank holds the bed,
# its work 9.1 % above the mean). With the limit at 0.05 the run repartitions by work at the
# first snapshot and continues from it: the log says so once, the run directory holds one
# complete record (every snapshot indexed, one monitor row per step), and monitor and fields
# agree with the run that never repartitions to the solver tolerance.
#   repartition.sh BAGNOLD MPIRUN WORK_DIR
set -eu
bagnold=$1; mpirun=$2; work=$3
common="--set run.end_time=0.02 --set output.progress=never --set output.snapshot_interval=0.005
        --set models.solids_stress.model=plastic --set numerics.tolerance=1e-6
        --set numerics.pressure_tolerance=1e-10 --set numerics.momentum_tolerance=1e-10
        --set numerics.partition_weights=cells"
rm -rf "$work"; mkdir -p "$work"
for limit in 0 0.05; do
  $mpirun --oversubscribe -np 2 $bagnold run cases/bin/bin-10mm.toml $common \
    --set numerics.repartition_imbalance=$limit --set output.directory=$work/limit$limit > $work/limit$limit.log
done
test "$(grep -c "repartitioning from .*snapshot_000001.h5" $work/limit0.05.log)" -eq 1
grep "partition by work" $work/limit0.05.log | grep -v "fluid cells per rank 800..800"
! grep -q "repartitioning" $work/limit0.log
test "$(ls $work/limit0.05/snapshot_*.h5 | wc -l)" -eq 5
test "$(grep -o "snapshot_[0-9]*.h5" $work/limit0.05/run.xmf | sort -u | wc -l)" -eq 5
test "$(wc -l < $work/limit0.05/monitor.csv)" -eq "$(wc -l < $work/limit0/monitor.csv)"
/usr/bin/python3 tools/compare-monitors $work/limit0 $work/limit0.05 --tolerance 1e-6 --ignore linear_iterations_
/usr/bin/python3 tools/compare-snapshots $work/limit0 $work/limit0.05 --tolerance 1e-6
echo "repartitioned once; the same answer to 1e-6"
