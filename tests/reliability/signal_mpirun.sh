#!/bin/sh
# A signal during a step that takes seconds, on 2 ranks under mpirun: the ranks abandon the step
# in progress after their current outer iteration and write the last completed step's state at
# once. Signalled itself, mpirun forwards the signal and returns 1 (its own status, whatever the
# ranks return); signalled directly, the ranks exit 3 and so does mpirun. Either way the final
# snapshot is complete and a restart from it continues bit-identically to a run never stopped.
#   signal_mpirun.sh BAGNOLD MPIRUN SIGNAL TARGET(mpirun|ranks) WORK_DIR
set -u
bagnold=$1; mpirun=$2; signal=$3; target=$4; work=$5
deck=cases/bin/bin-5mm.toml
# A tolerance of 1e-9: about 25 outer iterations, over a second, per step. The pressure
# preconditioner built every step (the default; the deck keeps it 20 steps): the final snapshot
# would otherwise make the restart build it where the run never stopped did not.
common="--set output.progress=never --set output.snapshot_interval=100 --set numerics.tolerance=1e-9 --set numerics.max_outer_iterations=400 --set numerics.pressure_preconditioner_steps=1"
rm -rf "$work"; mkdir -p "$work"
$mpirun --oversubscribe -np 2 $bagnold run $deck $common --set run.end_time=1 \
  --set output.directory=$work/run > $work/run.log 2>&1 &
pid=$!
for i in $(seq 1 480); do
  [ -f $work/run/monitor.csv ] && [ "$(wc -l < $work/run/monitor.csv)" -ge 4 ] && break
  sleep 0.25
done
sleep 0.5  # inside a step
if [ "$target" = mpirun ]; then kill -s "$signal" $pid; want=1; else pkill -s "$signal" -f "^$bagnold run" 2>/dev/null || pkill -"$signal" -f "^$bagnold run"; want=3; fi
wait $pid
code=$?
tail -3 $work/run.log
[ "$code" -eq "$want" ] || { echo "FAIL: exit code $code, expected $want"; exit 1; }
grep -q "that step was abandoned; final snapshot written" $work/run.log || { echo "FAIL: the step was not abandoned"; exit 1; }
ls $work/run/*.tmp 2>/dev/null && { echo "FAIL: a temporary file was left"; exit 1; }
last=$(ls $work/run/snapshot_*.h5 | tail -1)
stop_time=$(/usr/bin/python3 -c "import h5py; print(repr(float(h5py.File('$last')['/'].attrs['time'])))")
end=$(/usr/bin/python3 -c "print(repr($stop_time + 0.0005))")
$mpirun --oversubscribe -np 2 $bagnold run $deck $common --set run.end_time=$end \
  --set output.directory=$work/run --restart $work/run > $work/restart.log 2>&1 \
  || { echo "FAIL: restart after the signal failed"; cat $work/restart.log; exit 1; }
$mpirun --oversubscribe -np 2 $bagnold run $deck $common --set run.end_time=$end \
  --set output.directory=$work/whole > $work/whole.log 2>&1 || { echo "FAIL: the run never stopped failed"; exit 1; }
/usr/bin/python3 tools/compare-snapshots $work/whole $work/run --tolerance 0 || { echo "FAIL: the continuation differs"; exit 1; }
echo "stopped at t = $stop_time s by $signal to $target, exit $code; the continuation to $end s is bit-identical"
