#!/bin/sh
# What a run writes without a terminal (stdout and stderr into one file, output.progress = auto):
# no "\r" and no escape sequence; a line per snapshot, naming each snapshot file of the run once;
# at most one dt summary line per snapshot interval, right after its snapshot's line, and no
# line per dt change; plain progress lines (output.progress_interval = 0: one per step). The
# same run with --verbose logs every change of dt instead, as many as the summaries counted,
# and no summary.
#   run_log.sh BAGNOLD WORK_DIR
set -eu
bagnold=$1; work=$2
deck=tests/verification/lid_driven_cavity/re100.toml
run="--set grid.x.cells=16 --set grid.z.cells=16 --set run.end_time=2 --set run.dt_initial=0.01
     --set output.snapshot_interval=0.5 --set output.progress=auto --set output.progress_interval=0"
rm -rf "$work"
mkdir -p "$work"
$bagnold run $deck $run --set output.directory=$work/summary > "$work/summary.log" 2>&1
$bagnold run $deck $run --set output.directory=$work/verbose --verbose > "$work/verbose.log" 2>&1
/usr/bin/python3 - "$work" <<'PY'
import os, re, sys
work = sys.argv[1]
SNAPSHOT = re.compile(r"t = (\S+) s: snapshot (snapshot_\d+\.h5) written")
SUMMARY = re.compile(r"t = (\S+) s: dt \S+ m?s over the last snapshot interval, (\d+) changes?")
CHANGE = re.compile(r"t = \S+ s: .*; dt \S+ s -> \S+ s")
PROGRESS = re.compile(r"t = \S+ s / \S+ s  dt = \S+ s  it = \d+  ETA \d\d:\d\d:\d\d")
failures = []
def check(ok, what):
    if not ok:
        failures.append(what)

def read(name):
    raw = open(os.path.join(work, name + ".log"), encoding="utf-8").read()
    check("\r" not in raw and "\x1b" not in raw, f"{name}.log: a carriage return or an escape")
    lines = raw.splitlines()
    snapshots = [SNAPSHOT.fullmatch(l) for l in lines]
    names = [m.group(2) for m in snapshots if m]
    files = sorted(f for f in os.listdir(os.path.join(work, name)) if f.startswith("snapshot_"))
    check(names == files, f"{name}.log: snapshot lines {names}, files {files}")
    check(len(files) == 5, f"{name}: {len(files)} snapshots, expected 5 (t = 0, 0.5, ..., 2 s)")
    return lines

summary = read("summary")
counted = 0
for i, line in enumerate(summary):
    m = SUMMARY.fullmatch(line)
    if m:
        before = SNAPSHOT.fullmatch(summary[i - 1]) if i else None
        check(before is not None and before.group(1) == m.group(1),
              f"summary.log: dt summary not right after its snapshot's line: {line}")
        counted += int(m.group(2))
    check(not CHANGE.fullmatch(line), f"summary.log: a dt change logged without --verbose: {line}")
check(counted > 0, "summary.log: no dt summary (the run's dt changes)")
progress = sum(bool(PROGRESS.fullmatch(l)) for l in summary)
check(progress > 0, "summary.log: no plain progress line")

verbose = read("verbose")
changes = sum(bool(CHANGE.fullmatch(l)) for l in verbose)
check(changes == counted, f"verbose.log: {changes} dt changes, the summaries counted {counted}")
check(not any(SUMMARY.fullmatch(l) for l in verbose), "verbose.log: a dt summary line")
print(f"{counted} dt changes in {sum(bool(SUMMARY.fullmatch(l)) for l in summary)} summary lines, "
      f"{progress} progress lines")
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
PY
