#!/bin/sh
# dynamap map --rig: a recording re-mapped with another rig's Kinect poses says so in its
# report, and a rig that lacks one of the recorded Kinects is refused naming file and id.
# Usage: map_with_other_rig.sh DYNAMAP RESOURCES_DIR SCRATCH_DIR
set -eu
dynamap="$1"; resources="$2"; scratch="$3"
rm -rf "$scratch"; mkdir -p "$scratch"
"$dynamap" record --world "$resources/worlds/calibration_room.yaml" --width 80 \
  --duration 0.5 --seed 1 --out "$scratch/rec" 2>/dev/null

"$dynamap" map --log "$scratch/rec" --out "$scratch/map" --poses groundtruth \
  --rig "$resources/rigs/two_kinects_guess.yaml" 2>/dev/null >/dev/null
grep -q "\"rig\": \"$resources/rigs/two_kinects_guess.yaml\"" "$scratch/map/report.json" || {
  echo "report.json does not name the rig the map was built with" >&2; exit 1; }

sed 's/id: kinect1/id: kinect9/' "$resources/rigs/two_kinects_guess.yaml" > "$scratch/other_rig.yaml"
set +e
err=$("$dynamap" map --log "$scratch/rec" --out "$scratch/map2" --poses groundtruth \
  --rig "$scratch/other_rig.yaml" 2>&1 >/dev/null)
code=$?
set -e
[ "$code" -ne 0 ] || { echo "a rig without kinect1 was accepted" >&2; exit 1; }
case "$err" in
  *"other_rig.yaml"*"'kinect1'"*) ;;
  *) echo "unexpected error: $err" >&2; exit 1 ;;
esac
[ ! -e "$scratch/map2/report.json" ] || { echo "a refused map wrote a report" >&2; exit 1; }
