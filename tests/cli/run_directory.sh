#!/bin/sh
# The run directory (docs/reliability.md, "Run directories"; docs/output.md, "Provenance"), one
# scenario per call, each in a fresh WORK_DIR, on the lid-driven cavity at 16 x 16 (snapshots
# every 0.1 s; about 1 s of wall per run):
#
#   provenance       a run on 2 ranks records run.toml (which `check` loads back to the same
#                    resolved deck), provenance.toml, and the same record on every snapshot
#   refuse_changed   a restart with a changed physics key refuses (exit 2), lists the key with
#                    both values (not the run-control key it also changed) and touches nothing
#   force            the same restart with --force runs, into the snapshot's directory, and the
#                    record says what changed
#   own_directory    a restart continues in its snapshot's directory (given as the directory or
#                    the snapshot file) and not in the deck's output.directory, unless --set
#                    output.directory says otherwise
#   refuse_used      a fresh run into a directory holding a run (or only its monitor) refuses
#                    (exit 2), names the directory and --overwrite, and touches nothing
#   overwrite        --overwrite removes the earlier run's files first and nothing else
#
#   run_directory.sh BAGNOLD MPIEXEC WORK_DIR SCENARIO     (from the repository root)
set -eu
bagnold=$1; mpiexec=$2; work=$3; scenario=$4
deck=tests/verification/lid_driven_cavity/re100.toml
small="--set grid.x.cells=16 --set grid.z.cells=16 --set output.snapshot_interval=0.1 --set output.progress=never"
python=/usr/bin/python3
rm -rf "$work"; mkdir -p "$work"

fail() { echo "FAIL: $*"; exit 1; }
# Runs bagnold with the arguments, output to $work/last.log (shown); the exit code in $code.
try() {
  set +e
  "$bagnold" "$@" > "$work/last.log" 2>&1
  code=$?
  set -e
  cat "$work/last.log"
}
expect_line() { grep -Eq -- "$1" "$work/last.log" || fail "no line matching: $1"; }
# Every file below a directory with its checksum, to show that a refused run changed nothing.
contents() { (cd "$1" && find . -type f -exec md5sum {} + | sort); }
first_run() {  # DIR END_TIME
  "$bagnold" run $deck $small --set run.end_time="$2" --set output.directory="$1" > "$work/first.log" 2>&1 \
    || { cat "$work/first.log"; fail "the first run failed"; }
}

case $scenario in
provenance)
  out=$work/run
  "$mpiexec" --oversubscribe -np 2 "$bagnold" run $deck $small --set run.end_time=0.2 \
    --set output.directory="$out" --petsc-options "-options_left no" > "$work/run.log" 2>&1 \
    || { cat "$work/run.log"; fail "the run failed"; }
  cat "$work/run.log"
  grep -Eq '^build: bagnold [0-9]+\.[0-9]+\.[0-9]+, git [^ ,]+, 2 rank\(s\), started [0-9]{4}-[0-9]{2}-[0-9]{2}T[0-9:]{8}Z$' \
    "$work/run.log" || fail "no build line at start"
  grep -q '^solids: none (gas only)$' "$work/run.log" || fail "no model line at start"
  # run.toml loads as a deck, and resolves to the deck the run was given, key for key.
  try check "$out/run.toml"
  [ "$code" -eq 0 ] || fail "bagnold check run.toml: exit $code"
  sed -n '/^\[run\]/,/^# Geometry/p' "$work/last.log" > "$work/from_record.txt"
  try check $deck $small --set run.end_time=0.2 --set output.directory="$out"
  sed -n '/^\[run\]/,/^# Geometry/p' "$work/last.log" > "$work/from_deck.txt"
  [ -s "$work/from_deck.txt" ] || fail "no resolved deck printed"
  cmp "$work/from_deck.txt" "$work/from_record.txt" || fail "run.toml does not resolve to the run's deck"
  version=$("$bagnold" --version)
  $python - "$out" "$version" <<'PY'
import datetime, glob, re, sys, tomllib
import h5py
out, version = sys.argv[1], sys.argv[2]
with open(f"{out}/provenance.toml", "rb") as f:
    runs = tomllib.load(f)["run"]
assert len(runs) == 1, runs
p = runs[0]
print("provenance.toml:", p)
m = re.fullmatch(r"bagnold (\S+) \(git (\S+)\)", version)
assert m, version
assert p["version"] == m[1] and p["git_hash"] == m[2] and p["git_hash"], (p, version)
assert p["ranks"] == 2 and p["petsc_options"] == "-options_left no" and p["restart_from"] == "", p
assert "--petsc-options '-options_left no'" in p["command_line"], p["command_line"]
assert "--set run.end_time=0.2" in p["command_line"] and " run " in p["command_line"], p["command_line"]
start = p["start_time"]
assert isinstance(start, datetime.datetime) and start.utcoffset() == datetime.timedelta(0), start
assert abs((datetime.datetime.now(datetime.timezone.utc) - start).total_seconds()) < 600, start
deck = open(f"{out}/run.toml", encoding="utf-8").read()
tomllib.loads(deck)
snapshots = sorted(glob.glob(f"{out}/snapshot_*.h5"))
assert len(snapshots) == 3, snapshots
for path in snapshots:
    a = h5py.File(path, "r").attrs
    for name in ("deck", "command_line", "git_hash", "petsc_options", "start_time", "restart_from"):
        assert isinstance(a[name], str), (path, name, type(a[name]))  # variable-length UTF-8
    assert a["deck"] == deck, path
    assert a["command_line"] == p["command_line"] and a["git_hash"] == p["git_hash"], path
    assert a["petsc_options"] == p["petsc_options"] and a["restart_from"] == "", path
    assert int(a["ranks"]) == 2 and a["bagnold_version"] == p["version"], path
    assert a["start_time"] == start.strftime("%Y-%m-%dT%H:%M:%SZ"), (a["start_time"], start)
print(f"run.toml, provenance.toml and the record on {len(snapshots)} snapshots agree")
PY
  # In a git checkout the hash names a commit of it (the build may be older than the tree).
  hash=$($python -c "import sys; print(sys.argv[1].split('(git ')[1].rstrip(')'))" "$version")
  if git rev-parse --git-dir > /dev/null 2>&1; then
    [ "$hash" != unknown ] || fail "git hash 'unknown' in a git checkout"
    commit=$(echo "$hash" | sed -e 's/-dirty$//' -e 's/.*-g\([0-9a-f]*\)$/\1/')
    git cat-file -e "$commit^{commit}" || fail "git hash $hash names no commit"
  fi
  ;;
refuse_changed)
  first_run "$work/run" 0.2
  before=$(contents "$work/run")
  try run $deck $small --set run.end_time=0.4 --set gas.viscosity=0.02 --set 'physics.gravity=[0, 0, -1]' \
    --restart "$work/run"
  [ "$code" -eq 2 ] || fail "exit $code, expected 2 (bad input)"
  expect_line "the deck differs from the one $work/run/snapshot_000002.h5 was written with"
  expect_line '^  gas\.viscosity: 0\.01 in the snapshot, 0\.02 now$'
  expect_line '^  physics\.gravity: \[0\.0, 0\.0, 0\.0\] in the snapshot, \[0\.0, 0\.0, -1\.0\] now$'
  expect_line 'give --force to restart'
  if grep -q 'end_time' "$work/last.log"; then fail "run control (run.end_time) was listed"; fi
  [ "$(grep -c '^  [a-z_.]*: .* in the snapshot, ' "$work/last.log")" -eq 2 ] || fail "more than the 2 keys listed"
  [ "$(contents "$work/run")" = "$before" ] || fail "the refused restart changed the run directory"
  ;;
force)
  first_run "$work/run" 0.2
  try run $deck $small --set run.end_time=0.4 --set gas.viscosity=0.02 --restart "$work/run" --force
  [ "$code" -eq 0 ] || fail "exit $code with --force"
  expect_line '^  gas\.viscosity: 0\.01 in the snapshot, 0\.02 now$'
  expect_line 'restarting with the new values anyway \(--force\)'
  $python - "$work/run" <<'PY'
import sys, tomllib
import h5py
out = sys.argv[1]
runs = tomllib.load(open(f"{out}/provenance.toml", "rb"))["run"]
assert len(runs) == 2 and runs[0]["restart_from"] == "", runs
assert runs[1]["restart_from"] == f"{out}/snapshot_000002.h5" and "--force" in runs[1]["command_line"], runs[1]
record = tomllib.load(open(f"{out}/run.toml", "rb"))
assert record["gas"]["viscosity"] == 0.02 and record["run"]["end_time"] == 0.4, record["gas"]
old, new = (h5py.File(f"{out}/snapshot_{i:06d}.h5", "r").attrs for i in (2, 4))
assert tomllib.loads(old["deck"])["gas"]["viscosity"] == 0.01, "the earlier snapshots keep their deck"
assert tomllib.loads(new["deck"])["gas"]["viscosity"] == 0.02
assert new["restart_from"] == runs[1]["restart_from"] and abs(new["time"] - 0.4) < 1e-12
print("the forced restart ran on, and provenance.toml, run.toml and the snapshots record it")
PY
  ;;
own_directory)
  # The deck's own output.directory is $work/deck_directory: nothing may ever go there.
  printf 'extends = "%s/%s"\n[output]\ndirectory = "%s/deck_directory"\n' "$PWD" "$deck" "$work" > "$work/deck.toml"
  deck=$work/deck.toml
  first_run "$work/first" 0.2
  try run $deck $small --set run.end_time=0.3 --restart "$work/first"
  [ "$code" -eq 0 ] || fail "restart from the directory: exit $code"
  expect_line "^restart: writing into $work/first, the snapshot's run directory"
  try run $deck $small --set run.end_time=0.4 --restart "$work/first/snapshot_000003.h5"
  [ "$code" -eq 0 ] || fail "restart from the snapshot file: exit $code"
  [ ! -e "$work/deck_directory" ] || fail "a restart wrote into the deck's output.directory"
  try run $deck $small --set run.end_time=0.5 --restart "$work/first" --set output.directory="$work/other"
  [ "$code" -eq 0 ] || fail "restart into another directory: exit $code"
  if grep -q "^restart: writing into" "$work/last.log"; then fail "claimed to write into the snapshot's directory"; fi
  $python - "$work" <<'PY'
import csv, glob, os, sys
import h5py
work = sys.argv[1]
times = lambda d: [round(float(h5py.File(p, "r").attrs["time"]), 9) for p in sorted(glob.glob(f"{d}/snapshot_*.h5"))]
assert times(f"{work}/first") == [0.0, 0.1, 0.2, 0.3, 0.4], times(f"{work}/first")
assert times(f"{work}/other") == [0.5], times(f"{work}/other")
rows = [float(r["time"]) for r in csv.DictReader(open(f"{work}/first/monitor.csv"))]
assert rows == sorted(rows) and len(set(rows)) == len(rows) and abs(rows[-1] - 0.4) < 1e-9, rows
assert not os.path.exists(f"{work}/deck_directory")
print("the restarts continued in first/ (0.3 s, 0.4 s) and, when told, in other/ (0.5 s)")
PY
  ;;
refuse_used)
  first_run "$work/run" 0.2
  before=$(contents "$work/run")
  try run $deck $small --set run.end_time=0.2 --set output.directory="$work/run"
  [ "$code" -eq 2 ] || fail "exit $code, expected 2 (bad input)"
  expect_line "the output directory $work/run already holds a run"
  expect_line 'Give --overwrite to remove'
  [ "$(contents "$work/run")" = "$before" ] || fail "the refused run changed the directory"
  # A monitor alone is a run too (its snapshots moved away).
  mkdir "$work/monitor_only"
  cp "$work/run/monitor.csv" "$work/monitor_only/"
  try run $deck $small --set run.end_time=0.2 --set output.directory="$work/monitor_only"
  [ "$code" -eq 2 ] || fail "a directory holding only monitor.csv: exit $code, expected 2"
  # Other files are no run: a directory holding only them is used as before.
  mkdir "$work/notes_only"
  echo "notes" > "$work/notes_only/notes.txt"
  try run $deck $small --set run.end_time=0 --set output.directory="$work/notes_only"
  [ "$code" -eq 0 ] || fail "a directory with only notes.txt: exit $code"
  ;;
overwrite)
  first_run "$work/run" 0.4
  echo "keep me" > "$work/run/notes.txt"
  mkdir "$work/run/plots"
  echo "png" > "$work/run/plots/mass.png"
  echo "stale" > "$work/run/diagnostic.h5"
  try run $deck $small --set run.end_time=0.2 --set output.directory="$work/run" --overwrite
  [ "$code" -eq 0 ] || fail "--overwrite: exit $code"
  expect_line "^bagnold run: --overwrite: removed the earlier run in $work/run \(10 files\)"
  $python tests/cli/check_xdmf.py "$work/run" 3
  $python - "$work/run" <<'PY'
import csv, os, sys, tomllib
out = sys.argv[1]
names = sorted(os.listdir(out))
want = sorted(["monitor.csv", "notes.txt", "plots", "provenance.toml", "run.toml", "run.xmf",
               "snapshot_000000.h5", "snapshot_000001.h5", "snapshot_000002.h5"])
assert names == want, names
assert open(f"{out}/notes.txt").read() == "keep me\n" and os.path.exists(f"{out}/plots/mass.png")
rows = [float(r["time"]) for r in csv.DictReader(open(f"{out}/monitor.csv"))]
assert abs(rows[-1] - 0.2) < 1e-9 and rows == sorted(rows), rows
assert len(tomllib.load(open(f"{out}/provenance.toml", "rb"))["run"]) == 1
print("--overwrite removed snapshots 0-4, the monitor, the index, the record and diagnostic.h5; kept the rest")
PY
  # Never for a restart that continues in its own directory: it would remove its own snapshot.
  try run $deck $small --set run.end_time=0.3 --restart "$work/run" --overwrite
  [ "$code" -eq 2 ] || fail "--overwrite with a restart into its own directory: exit $code, expected 2"
  expect_line 'would remove the snapshot this restart continues from'
  ;;
*)
  fail "unknown scenario '$scenario'"
  ;;
esac
echo "PASS: $scenario"
