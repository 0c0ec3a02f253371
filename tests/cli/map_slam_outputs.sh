#!/bin/sh
# dynamap map --poses slam writes one trajectory.tum pose and one slam_scans.csv row per
# scan, the rows saying what was registered against what.
# Usage: map_slam_outputs.sh DYNAMAP RESOURCES_DIR SCRATCH_DIR
set -eu
dynamap="$1"; resources="$2"; scratch="$3"
rm -rf "$scratch"; mkdir -p "$scratch"
"$dynamap" record --world "$resources/worlds/office.yaml" --width 80 --duration 2 \
  --seed 1 --out "$scratch/rec" 2>/dev/null
"$dynamap" map --log "$scratch/rec" --out "$scratch/map" 2>/dev/null >/dev/null
csv="$scratch/map/slam_scans.csv"
head -1 "$csv" | grep -q "^stamp_s,predicted_x,predicted_y,predicted_theta,x,y,theta,reference,accepted," || {
  echo "unexpected header in $csv" >&2; exit 1; }
rows=$(($(wc -l < "$csv") - 1))
poses=$(grep -vc '^#' "$scratch/map/trajectory.tum")
[ "$rows" -gt 20 ] || { echo "only $rows scans in $csv" >&2; exit 1; }
[ "$rows" -eq "$poses" ] || { echo "$rows rows but $poses poses" >&2; exit 1; }
# The first scan has nothing to register against; later ones use the map or the previous scan.
sed -n 2p "$csv" | grep -q ",none,0," || { echo "first scan was registered" >&2; exit 1; }
registered=$(grep -c ",map,\|,previous," "$csv")
[ "$registered" -ge $((rows - 1)) ] || { echo "$registered of $rows scans registered" >&2; exit 1; }
