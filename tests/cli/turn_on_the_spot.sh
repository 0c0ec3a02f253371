#!/bin/sh
# A robot turning on the spot in an empty room with true poses: nothing in the room moves,
# so nothing may end in the dynamic map. The floor just in front of the Kinects' view used
# to be cleared by the rays ending on the floor beyond it and, hit again from the next
# heading, turned dynamic in a ring round the robot.
# Usage: turn_on_the_spot.sh DYNAMAP SCRATCH_DIR
set -eu
dynamap="$1"; scratch="$2"
rm -rf "$scratch"; mkdir -p "$scratch"
cat > "$scratch/spin.yaml" <<'WORLD'
name: turn_on_the_spot
duration_s: 9
floor: {min: [0, 0], max: [10, 10]}
robot_start: {x: 5.0, y: 5.0, yaw_deg: 0}
walls:
  - {id: wall_south, from: [0, 0], to: [10, 0], thickness: 0.15, height: 2.6}
  - {id: wall_east, from: [10, 0], to: [10, 10], thickness: 0.15, height: 2.6}
  - {id: wall_north, from: [10, 10], to: [0, 10], thickness: 0.15, height: 2.6}
  - {id: wall_west, from: [0, 10], to: [0, 0], thickness: 0.15, height: 2.6}
teleop:
  - {v: 0, omega: 0, duration_s: 1}
  - {v: 0, omega: 0.8, duration_s: 7.854}
WORLD
"$dynamap" record --world "$scratch/spin.yaml" --width 160 --seed 1 --out "$scratch/rec" \
  2>/dev/null >/dev/null
"$dynamap" map --log "$scratch/rec" --out "$scratch/map" --poses groundtruth 2>/dev/null >/dev/null
report="$scratch/map/report.json"
dynamic=$(sed -n 's/.*"dynamic_occupied_voxels": \([0-9]*\).*/\1/p' "$report")
sa=$(sed -n 's/.*"static_accuracy": \([0-9.]*\).*/\1/p' "$report")
echo "dynamic voxels: $dynamic, static accuracy: $sa"
[ "$dynamic" -le 10 ] || { echo "$dynamic dynamic voxels in an empty room" >&2; exit 1; }
awk -v sa="$sa" 'BEGIN { exit !(sa >= 0.995) }' || { echo "static accuracy $sa < 0.995" >&2; exit 1; }
