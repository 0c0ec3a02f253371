#!/bin/sh
# Ctrl-C during `dynamap explore` stops the mission and still writes its results.
# Usage: interrupt_explore.sh DYNAMAP WORLD OUT_DIR
dynamap="$1"; world="$2"; out="$3"
rm -rf "$out"
"$dynamap" explore --world "$world" --out "$out" --max-time 600 --poses groundtruth \
  --kinect-width 80 >"$out.log" 2>&1 &
pid=$!
# Let the mission run a few seconds of wall time, then interrupt it once.
sleep 6
kill -INT "$pid"
wait "$pid"
code=$?
if [ "$code" -ne 0 ]; then
  echo "explore exited with $code after one interrupt" >&2; cat "$out.log" >&2; exit 1
fi
for file in report.json map.ot static.bt dynamic.bt map2d.png trajectory.tum; do
  if [ ! -s "$out/$file" ]; then
    echo "missing $out/$file after the interrupt" >&2; cat "$out.log" >&2; exit 1
  fi
done
grep -q '"completed": false' "$out/report.json" || {
  echo "report.json does not say the mission was not completed" >&2; exit 1; }
grep -q "interrupted: stopping the mission" "$out.log" || {
  echo "no interrupt message in the output" >&2; cat "$out.log" >&2; exit 1; }
exit 0
