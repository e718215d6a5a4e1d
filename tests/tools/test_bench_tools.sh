#!/bin/sh
# tools/bench-bin and tools/stability-map on the 10 mm bin with the plastic closure, a few
# milliseconds: each must print its table with one well-formed row per run, the bench row with a
# rate and a mass balance, the map row with an outcome. BAGNOLD = the program.
set -eu
BAGNOLD=$1
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

/usr/bin/python3 tools/bench-bin --closure plastic --end-time 0.12 --window-min 0.05 \
    --bagnold "$BAGNOLD" > "$out/bench.md"
cat "$out/bench.md"
grep -Eq '^\| 10mm \| plastic \| superbee \| 1e-4 \| 0.12 s \| [0-9]+ \([0-9]+\) \|.*\| [0-9.]+ ± [0-9.]+ \(.*\) \| [0-9.]+e-[0-9]+ \|$' "$out/bench.md" \
    || { echo "FAIL: no bench-bin row with a rate and a mass balance"; exit 1; }

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
