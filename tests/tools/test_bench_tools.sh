#!/bin/sh
# tools/bench-bin, tools/compare-rates and tools/stability-map on the 10 mm bin with the plastic
# closure, a few milliseconds: each must print its table with one well-formed row per run, the
# bench row with a rate and a mass balance, the map row with an outcome; compare-rates its mean
# and a PNG. BAGNOLD = the program.
set -eu
BAGNOLD=$1
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

/usr/bin/python3 tools/bench-bin --closure plastic --end-time 0.12 --window-min 0.05 \
    --bagnold "$BAGNOLD" --keep "$out/runs" > "$out/bench.md"
cat "$out/bench.md"
grep -Eq '^\| 10mm \| plastic \| superbee \| 1e-4 \| 0.12 s \| [0-9]+ \([0-9]+\) \|.*\| [0-9.]+ ± [0-9.]+ \(.*\) \| [0-9.]+e-[0-9]+ \|$' "$out/bench.md" \
    || { echo "FAIL: no bench-bin row with a rate and a mass balance"; exit 1; }

/usr/bin/python3 tools/compare-rates "plastic=$out/runs/10mm-plastic-superbee-1e-4" \
    --reference experiment=165 --output "$out/rates.png" > "$out/rates.txt"
cat "$out/rates.txt"
grep -Eq '^plastic: 2 blocks to 0.12 s, mean after 0.1 s [0-9.]+ g/s' "$out/rates.txt" && [ -s "$out/rates.png" ] \
    || { echo "FAIL: compare-rates printed no mean or wrote no PNG"; exit 1; }
if /usr/bin/python3 tools/compare-rates "$out/runs/10mm-plastic-superbee-1e-4" --output "$out/x.png" 2> "$out/err"; then
  echo "FAIL: a run without a label was accepted"; exit 1
fi
grep -q "expected LABEL=RUN_DIR" "$out/err" || { echo "FAIL: compare-rates message"; cat "$out/err"; exit 1; }

/usr/bin/python3 tools/stability-map --closure plastic --only deck,"dt 10x" --end-time 0.02 \
    --bagnold "$BAGNOLD" > "$out/map.md"
cat "$out/map.md"
[ "$(grep -Ec '^\| plastic \| (deck|dt 10x) \| (completed|recovered) \|' "$out/map.md")" -eq 2 ] \
    || { echo "FAIL: stability-map did not report both runs as completed or recovered"; exit 1; }

# Bad input is refused with a message.
if /usr/bin/python3 tools/stability-map --only nonsense --bagnold "$BAGNOLD" 2> "$out/err"; then
  echo "FAIL: an unknown variation was accepted"; exit 1
fi
grep -q "unknown variation 'nonsense'" "$out/err" || { echo "FAIL: message"; cat "$out/err"; exit 1; }
echo PASS
