#!/bin/sh
# A disk that fills between the room check and the snapshot's write, on several ranks: every
# rank stops within 120 s with exit code 1, the message names the snapshot, no .tmp remains and
# every snapshot under a final name is readable. The room check is skipped (test-only
# BAGNOLD_TEST_SKIP_ROOM_CHECK), so with MODE reservation the disk is found full by the
# reservation of the snapshot's room. With MODE hdf5-data or hdf5-flush the reservation is
# skipped too (BAGNOLD_TEST_SKIP_RESERVATION), so the disk fills inside the snapshot's HDF5 calls:
# in the data writes (H5Dwrite) or in HDF5's final metadata flush (H5Fflush, H5Fclose), depending
# on the tmpfs SIZE. The channel has X_CELLS cells along x (10 in the deck): with 10 its fields
# (1.6 kB each) stay in HDF5's buffers until the flush; with 1000 (160 kB each) they are written
# at once. A size large enough for the first snapshot fills the disk in the next write, the index
# or the monitor, and the message names that file. Every size is tried and reported; the test
# fails if any size failed, or if none stopped where MODE says.
#   disk_full_in_write.sh BAGNOLD WORK_DIR MPIRUN RANKS MODE X_CELLS SIZE...
set -u
bagnold=$1; work=$2; mpirun=$3; ranks=$4; mode=$5; x_cells=$6; shift 6
mkdir -p "$work"
umount "$work" 2>/dev/null
mount -t tmpfs -o size=16k tmpfs "$work" 2>/dev/null || { echo "cannot mount a tmpfs here: skipped"; exit 77; }
umount "$work"
trap 'umount "$work" 2>/dev/null' EXIT
export BAGNOLD_TEST_SKIP_ROOM_CHECK=1
case $mode in
  reservation) where="cannot reserve" ;;
  hdf5-data) where="H5Dwrite[^;]* failed"; export BAGNOLD_TEST_SKIP_RESERVATION=1 ;;
  hdf5-flush) where="H5F(flush|close) failed"; export BAGNOLD_TEST_SKIP_RESERVATION=1 ;;
  *) echo "unknown MODE $mode"; exit 2 ;;
esac
log=$work/../disk_full_in_write.log
failed=""
stopped_there=0
# One size: nothing printed and status 0 when the run stopped as it must.
check_size() {
  timeout 120 $mpirun --oversubscribe -np $ranks $bagnold run tests/verification/poiseuille/channel.toml \
    --set output.directory=$work/run --set output.snapshot_interval=0.05 --set output.progress=never \
    --set grid.x.cells=$x_cells > $log 2>&1
  code=$?
  echo "$1: exit $code: $(grep 'bagnold run: failed' $log | head -1)"
  [ "$code" -eq 124 ] && { echo "FAIL ($1): the ranks did not stop within 120 s"; tail -5 $log; return 1; }
  [ "$code" -eq 1 ] || { echo "FAIL ($1): exit code $code, expected 1"; cat $log; return 1; }
  grep -Eq "bagnold run: failed: cannot write the snapshot $work/run/snapshot_[0-9]+\.h5 .*disk full" $log ||
    { [ -f $work/run/snapshot_000000.h5 ] &&
      grep -Eq "bagnold run: failed: cannot (write|append to the monitor) $work/run/(run\.xmf|monitor\.csv) .*disk full" $log; } \
    || { echo "FAIL ($1): the message does not name the snapshot (nor, after a whole one, the index or monitor)"; cat $log; return 1; }
  ls $work/run/*.tmp 2>/dev/null && { echo "FAIL ($1): a temporary file was left"; return 1; }
  /usr/bin/python3 - "$work/run" <<'PY' || { echo "FAIL ($1): a snapshot is unreadable"; return 1; }
import glob, sys, h5py
for name in sorted(glob.glob(sys.argv[1] + "/snapshot_*.h5")):
    with h5py.File(name, "r") as f:
        f["fields/gas_velocity_x"][:]
PY
}
for size in "$@"; do
  mount -t tmpfs -o size=$size tmpfs "$work" || { echo "FAIL: cannot mount a $size tmpfs"; exit 1; }
  check_size $size || failed="$failed $size"
  grep -Eq "cannot write the snapshot .*($where)" $log && stopped_there=$((stopped_there + 1))
  umount "$work"
done
[ -n "$failed" ] && { echo "FAIL at$failed"; exit 1; }
[ $stopped_there -eq 0 ] && { echo "FAIL: no size stopped the snapshot with '$where'"; exit 1; }
echo "$stopped_there size(s) stopped the snapshot with '$where'"
echo "every size: all ranks stopped with exit 1 and the file named, no .tmp left"
