#!/bin/sh
# Corrupted snapshots are refused before a restart reads them, and --restart DIR falls back to
# the newest good one: the 10 mm bin runs to 0.02 s (snapshots every 0.005 s); then
#   flipped  1 KB of random bytes inside the last snapshot's fields/solids_velocity_z data;
#   range    ε_s = 1.5 in one fluid cell of the last snapshot, its checksums removed (as a
#            snapshot written before checksums existed: the range check alone must catch it);
#   truncated the last snapshot cut to half its size.
# Restarting from that file is refused (exit 2) with its name and the bad dataset; restarting
# from the directory says so and continues from the snapshot before it, to 0.03 s.
#   corrupted_snapshot.sh BAGNOLD WORK_DIR CASE
set -u
bagnold=$1; work=$2; case=$3
deck=cases/bin/bin-10mm.toml
common="--set output.progress=never --set output.snapshot_interval=0.005"
rm -rf "$work"; mkdir -p "$work"
$bagnold run $deck $common --set run.end_time=0.02 --set output.directory=$work/run > $work/run.log 2>&1 \
  || { echo "FAIL: the first run failed"; cat $work/run.log; exit 1; }
last=$(ls $work/run/snapshot_*.h5 | tail -1)
before=$(ls $work/run/snapshot_*.h5 | tail -2 | head -1)
/usr/bin/python3 - "$last" "$case" <<'PY'
import os, sys
import h5py
path, case = sys.argv[1], sys.argv[2]
if case == "flipped":
    with h5py.File(path, "r") as f:
        ds = f["fields/solids_velocity_z"]
        offset, size = ds.id.get_offset(), ds.id.get_storage_size()
    with open(path, "r+b") as raw:
        raw.seek(offset + size // 2 - 512)
        raw.write(os.urandom(1024))
elif case == "range":
    with h5py.File(path, "a") as f:
        flags = f["grid/cell_flags"][...]
        eps = f["fields/solids_fraction"]
        k, j, i = [int(a[0]) for a in (flags == 1).nonzero()]
        values = eps[...]
        values[k, j, i] = 1.5
        eps[...] = values
        for group in ("fields", "boundary"):
            for name in f[group]:
                if "checksum" in f[group][name].attrs:
                    del f[group][name].attrs["checksum"]
elif case == "truncated":
    size = os.path.getsize(path)
    with open(path, "r+b") as raw:
        raw.truncate(size // 2)
PY
want_dataset=""
[ "$case" = flipped ] && want_dataset="fields/solids_velocity_z does not match its checksum"
[ "$case" = range ] && want_dataset="fields/solids_fraction holds 1.5 in fluid cell (i, j, k) = "
[ "$case" = truncated ] && want_dataset="cannot open it as HDF5"
$bagnold run $deck $common --set run.end_time=0.03 --restart "$last" > $work/file.log 2>&1
code=$?
cat $work/file.log | tail -2
[ "$code" -eq 2 ] || { echo "FAIL: restart from the bad file exited $code, expected 2"; exit 1; }
grep -q "snapshot $last refused: .*$want_dataset" $work/file.log || { echo "FAIL: no message naming $last and the dataset"; exit 1; }
$bagnold run $deck $common --set run.end_time=0.03 --restart "$work/run" > $work/dir.log 2>&1 \
  || { echo "FAIL: restart from the directory failed"; cat $work/dir.log; exit 1; }
grep -q "falling back to $before, the newest good snapshot" $work/dir.log || { echo "FAIL: no fall-back message"; cat $work/dir.log; exit 1; }
grep -q "restart from $before" $work/dir.log || { echo "FAIL: did not restart from $before"; exit 1; }
# The continuation is good: the final snapshot verifies and is at 0.03 s.
final=$(ls $work/run/snapshot_*.h5 | tail -1)
/usr/bin/python3 -c "
import h5py, math, sys
f = h5py.File('$final', 'r')
t = float(f.attrs['time'])
e = f['fields/solids_fraction'][...]
ok = abs(t - 0.03) < 1e-12 and float(e[e == e].max()) <= 1.0
print('final', '$final', 't =', t)
sys.exit(0 if ok else 1)" || { echo "FAIL: the continuation's final snapshot"; exit 1; }
echo "$case: refused from the file, fell back from the directory to $before"
