#!/bin/sh
# SIGTERM (or SIGINT) during a run writes a final complete snapshot and exits with code 3; the
# run then continues from it with --restart.
#   signal.sh BAGNOLD SIGNAL WORK_DIR
set -u
bagnold=$1; signal=$2; work=$3
deck=tests/verification/lid_driven_cavity/re100.toml
rm -rf "$work"; mkdir -p "$work"
$bagnold run $deck --set run.end_time=1000 --set output.snapshot_interval=1000 \
  --set output.progress=never --set output.directory=$work/run > $work/run.log 2>&1 &
pid=$!
# Wait until the time loop runs (the monitor has rows after t = 0), at most 120 s.
for i in $(seq 1 240); do
  [ -f $work/run/monitor.csv ] && [ "$(wc -l < $work/run/monitor.csv)" -ge 4 ] && break
  sleep 0.5
done
kill -s "$signal" $pid
wait $pid
code=$?
cat $work/run.log | tail -3
[ "$code" -eq 3 ] || { echo "FAIL: exit code $code, expected 3"; exit 1; }
ls $work/run/snapshot_000001.h5 || { echo "FAIL: no final snapshot"; exit 1; }
ls $work/run/*.tmp 2>/dev/null && { echo "FAIL: a temporary file was left"; exit 1; }
grep -q "stopped by signal" $work/run.log || { echo "FAIL: no message"; exit 1; }
stop_time=$(/usr/bin/python3 -c "import h5py; print(h5py.File('$work/run/snapshot_000001.h5')['/'].attrs['time'])")
end=$(/usr/bin/python3 -c "print($stop_time + 0.5)")
$bagnold run $deck --set run.end_time=$end --set output.snapshot_interval=1000 \
  --set output.progress=never --set output.directory=$work/run --restart $work/run > $work/restart.log 2>&1 \
  || { echo "FAIL: restart after the signal failed"; cat $work/restart.log; exit 1; }
echo "stopped at t = $stop_time s by $signal, exit 3; restarted to t = $end s"
