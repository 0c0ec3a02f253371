#!/bin/sh
# dynamap map --mapping FILE: map settings from a file over the defaults, the command
# line's --resolution winning, both in report.json; a misspelt key is an error naming the
# file and the key; a recording whose world is gone stops before the mapping.
# Usage: map_settings_file.sh DYNAMAP RESOURCES_DIR SCRATCH_DIR
set -eu
dynamap="$1"; resources="$2"; scratch="$3"
rm -rf "$scratch"; mkdir -p "$scratch"
"$dynamap" record --world "$resources/worlds/office.yaml" --width 80 --duration 1 \
  --seed 1 --out "$scratch/rec" 2>/dev/null >/dev/null
printf 'mapping:\n  persistence_observations: 450\n  resolution_m: 0.2\n  update: regular\n' \
  > "$scratch/mapping.yaml"
"$dynamap" map --log "$scratch/rec" --out "$scratch/map" --poses groundtruth \
  --mapping "$scratch/mapping.yaml" --resolution 0.1 2>/dev/null >/dev/null
report="$scratch/map/report.json"
grep -q '"persistence_observations": 450' "$report" || {
  echo "the file's persistence_observations is not in $report" >&2; exit 1; }
grep -q '"update": "regular"' "$report" || { echo "the file's update was not used" >&2; exit 1; }
grep -q '"resolution_m": 0.1' "$report" || { echo "--resolution did not win" >&2; exit 1; }

printf 'mapping:\n  persistence_observation: 450\n' > "$scratch/bad_mapping.yaml"
"$(dirname "$0")/expect_failure.sh" 2 "bad_mapping.yaml: key 'mapping.persistence_observation'" \
  "$dynamap" map --log "$scratch/rec" --out "$scratch/map2" --poses groundtruth \
  --mapping "$scratch/bad_mapping.yaml"
[ ! -e "$scratch/map2/report.json" ] || { echo "a report was written after the error" >&2; exit 1; }

# A recording whose world cannot be found stops before the mapping, naming the recording.
cp -r "$scratch/rec" "$scratch/rec-lost-world"
sed -i 's#^world: .*#world: /nonexistent/office.yaml#' "$scratch/rec-lost-world/meta.yaml"
"$(dirname "$0")/expect_failure.sh" 2 "rec-lost-world: the world it was recorded in" \
  "$dynamap" map --log "$scratch/rec-lost-world" --out "$scratch/map3" --poses groundtruth
[ ! -e "$scratch/map3/map.ot" ] || { echo "the map was made before the error" >&2; exit 1; }
