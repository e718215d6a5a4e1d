#!/bin/sh
# The partitions by work, by phases and by layers give the answer of the partition by cells: the 10 mm bin
# on 2 ranks, 0.02 s, with numerics.partition_weights "cells", "work" (which moves cells between
# the ranks: the bed's rank gets fewer), "phases" (each rank half the bed) and "layers" (each rank
# half of every layer across gravity), the same monitor
# (but the linear iterations, which depend on the partition) and fields to the solver tolerance.
#   partition_weights.sh BAGNOLD MPIRUN WORK_DIR
set -eu
bagnold=$1; mpirun=$2; work=$3
common="--set run.end_time=0.02 --set output.progress=never --set models.solids_stress.model=plastic
        --set numerics.tolerance=1e-6 --set numerics.pressure_tolerance=1e-10
        --set numerics.momentum_tolerance=1e-10"
rm -rf "$work"; mkdir -p "$work"
for weights in cells work phases layers; do
  $mpirun --oversubscribe -np 2 $bagnold run cases/bin/bin-10mm.toml $common \
    --set numerics.partition_weights=\"$weights\" --set output.directory=$work/$weights > $work/$weights.log
done
# The weighted partition is another than the one by cells (800 fluid cells per rank).
grep "partition by work" $work/work.log | grep -v "fluid cells per rank 800..800"
! grep -q "partition by work" $work/cells.log
# By phases: every rank half the bed's cells (1600 fluid cells, 800 of them below the fill).
grep "partition by phases" $work/phases.log
# By layers: every rank half of each layer of 16 cells (x < 2 cm or x > 2 cm).
grep "partition by layers across z: fluid cells per rank 800..800" $work/layers.log
for weights in work phases layers; do
  /usr/bin/python3 tools/compare-monitors $work/cells $work/$weights --tolerance 1e-6 --ignore linear_iterations_
  /usr/bin/python3 tools/compare-snapshots $work/cells $work/$weights --tolerance 1e-6
done
