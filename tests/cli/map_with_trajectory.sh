#!/bin/sh
# dynamap map --trajectory: a recording mapped with poses from a TUM file gives the map the
# same poses give from the recording's own ground truth, reports how far the file is from
# the truth, and a malformed file is refused naming the file and the line.
# Usage: map_with_trajectory.sh DYNAMAP RESOURCES_DIR SCRATCH_DIR
set -eu
dynamap="$1"; resources="$2"; scratch="$3"
rm -rf "$scratch"; mkdir -p "$scratch"
"$dynamap" record --world "$resources/worlds/calibration_room.yaml" --width 80 \
  --duration 0.5 --seed 1 --out "$scratch/rec" 2>/dev/null

"$dynamap" map --log "$scratch/rec" --out "$scratch/truth" --poses groundtruth \
  2>/dev/null >/dev/null
cp "$scratch/rec/groundtruth.txt" "$scratch/same.tum"
"$dynamap" map --log "$scratch/rec" --out "$scratch/same" --trajectory "$scratch/same.tum" \
  2>/dev/null >/dev/null
cmp -s "$scratch/truth/static.bt" "$scratch/same/static.bt" || {
  echo "the ground truth as a trajectory file gave another static map" >&2; exit 1; }
grep -q '"poses": "trajectory"' "$scratch/same/report.json" || {
  echo "report.json does not say the poses came from a trajectory file" >&2; exit 1; }
grep -q '"ate_rmse_m": 0.0' "$scratch/same/report.json" || {
  echo "the ground truth as a trajectory is not 0 m from the truth" >&2; exit 1; }

# The same poses 1 m further along x: 1 m from the truth, and the map moves with them.
awk '/^#/ { print; next } { $2 = sprintf("%.9f", $2 + 1.0); print }' \
  "$scratch/rec/groundtruth.txt" > "$scratch/shifted.tum"
"$dynamap" map --log "$scratch/rec" --out "$scratch/shifted" \
  --trajectory "$scratch/shifted.tum" 2>/dev/null >/dev/null
ate=$(sed -n 's/.*"ate_rmse_m": \([0-9.e-]*\).*/\1/p' "$scratch/shifted/report.json")
awk -v a="$ate" 'BEGIN { exit !(a > 0.999 && a < 1.001) }' || {
  echo "a trajectory 1 m off reports ATE $ate" >&2; exit 1; }
if cmp -s "$scratch/truth/static.bt" "$scratch/shifted/static.bt"; then
  echo "a trajectory 1 m off gave the same static map" >&2; exit 1
fi

printf '0.0 0 0 0 0 0 0 1\n0.1 0 zero 0 0 0 0 1\n' > "$scratch/bad.tum"
set +e
err=$("$dynamap" map --log "$scratch/rec" --out "$scratch/bad" --trajectory "$scratch/bad.tum" \
  2>&1 >/dev/null)
code=$?
set -e
[ "$code" -ne 0 ] || { echo "a malformed trajectory was accepted" >&2; exit 1; }
case "$err" in
  *"bad.tum: line 2:"*) ;;
  *) echo "unexpected error: $err" >&2; exit 1 ;;
esac
[ ! -e "$scratch/bad/report.json" ] || { echo "a refused map wrote a report" >&2; exit 1; }

# --poses and --trajectory name two pose sources: refused rather than one silently ignored.
if "$dynamap" map --log "$scratch/rec" --out "$scratch/both" --poses odometry \
  --trajectory "$scratch/same.tum" >/dev/null 2>&1; then
  echo "--poses together with --trajectory was accepted" >&2; exit 1
fi
