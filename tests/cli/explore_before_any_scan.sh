#!/bin/sh
# A mission stopped before its first scan is mapped still ends normally: exit 0, the map
# files and report.json written, no picture of an empty 3D map.
# Usage: explore_before_any_scan.sh DYNAMAP RESOURCES_DIR SCRATCH_DIR
set -eu
dynamap="$1"; resources="$2"; scratch="$3"
rm -rf "$scratch"
"$dynamap" explore --world "$resources/worlds/small_office.yaml" --poses groundtruth \
  --kinect-width 80 --max-time 0.05 --headless --out "$scratch" >/dev/null 2>&1 || {
  echo "explore failed when stopped before its first scan" >&2; exit 1; }
for f in report.json map.ot static.bt map2d.png map2d.pgm trajectory.tum; do
  [ -s "$scratch/$f" ] || { echo "$f was not written" >&2; exit 1; }
done
[ ! -e "$scratch/map3d_topdown.png" ] || { echo "an empty map was pictured" >&2; exit 1; }
grep -q '"completed": false' "$scratch/report.json" || {
  echo "report.json does not say the mission is incomplete" >&2; exit 1; }
