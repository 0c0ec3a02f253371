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
# Loop closure runs by default and says what it did (a 2 s drive closes no loop).
grep -q '"loop_closure": {' "$scratch/map/report.json" || {
  echo "report.json has no loop_closure summary" >&2; exit 1; }
grep -q '"closures": 0' "$scratch/map/report.json" || {
  echo "a 2 s drive closed a loop" >&2; exit 1; }
[ "$(cat "$scratch/map/loop_closures.csv")" = "older_stamp_s,newer_stamp_s,guess_x,guess_y,guess_theta,measured_x,measured_y,measured_theta,fitness_rmse_m,inlier_ratio,structure,outcome" ] || {
  echo "loop_closures.csv is not a header alone" >&2; exit 1; }
# What the SLAM pass gave is kept beside the corrected trajectory; nothing closed, so the two agree.
cmp -s "$scratch/map/trajectory_before_loop_closure.tum" "$scratch/map/trajectory.tum" || {
  echo "trajectory_before_loop_closure.tum missing or unlike trajectory.tum without closures" >&2; exit 1; }
grep -q '"ate_rmse_m_before_loop_closure": [0-9]' "$scratch/map/report.json" || {
  echo "report.json lacks the ATE before loop closure" >&2; exit 1; }
# The recording has ground truth: the error over time is drawn.
head -c 8 "$scratch/map/trajectory_error.png" | grep -q PNG || {
  echo "no trajectory_error.png" >&2; exit 1; }
grep -q '"trajectory_error_plot": ".*trajectory_error.png"' "$scratch/map/report.json" || {
  echo "report.json does not name the plot" >&2; exit 1; }
# The recording is labelled: where SA and DA were lost is listed voxel by voxel, and the
# static points lost there add up to what static_accuracy leaves out.
csv="$scratch/map/accuracy_errors.csv"
sed -n 2p "$csv" | grep -q "^x,y,z,static_points_lost,dynamic_points_kept$" || {
  echo "unexpected header in $csv" >&2; exit 1; }
lost=$(tail -n +3 "$csv" | awk -F, '{ s += $4 } END { print s + 0 }')
field() { sed -n "s/^ *\"$1\": \([0-9.e+-]*\),*$/\1/p" "$scratch/map/report.json"; }
expected=$(awk -v n="$(field static_points)" -v sa="$(field static_accuracy)" \
  'BEGIN { printf "%d", n * (1 - sa) + 0.5 }')
[ "$lost" -eq "$expected" ] || { echo "$lost static points lost in $csv, report says $expected" >&2; exit 1; }

# SLAM settings from a file, the registration fed ground truth as odometry.
printf 'reference: previous\nmax_correction_per_rad: 0.1\nloop_closure: {enabled: false}\n' \
  > "$scratch/slam.yaml"
"$dynamap" map --log "$scratch/rec" --out "$scratch/map2" --slam "$scratch/slam.yaml" \
  --slam-odometry groundtruth 2>/dev/null >/dev/null
grep -q '"reference": "previous"' "$scratch/map2/report.json" || {
  echo "the settings file's reference was not used" >&2; exit 1; }
grep -q '"slam_odometry": "groundtruth"' "$scratch/map2/report.json" || {
  echo "report.json does not say SLAM ran on ground truth" >&2; exit 1; }
if grep -q '"loop_closure"' "$scratch/map2/report.json"; then
  echo "loop closure ran although the settings file turned it off" >&2; exit 1
fi
# --reference wins over the file.
"$dynamap" map --log "$scratch/rec" --out "$scratch/map3" --slam "$scratch/slam.yaml" \
  --reference map 2>/dev/null >/dev/null
grep -q '"reference": "map"' "$scratch/map3/report.json" || {
  echo "--reference did not override the settings file" >&2; exit 1; }
printf 'max_correction_per_radian: 0.1\n' > "$scratch/bad_slam.yaml"
set +e
err=$("$dynamap" map --log "$scratch/rec" --out "$scratch/map4" --slam "$scratch/bad_slam.yaml" 2>&1 >/dev/null)
code=$?
set -e
[ "$code" -ne 0 ] || { echo "a misspelt SLAM setting was accepted" >&2; exit 1; }
case "$err" in
  *"bad_slam.yaml"*"max_correction_per_radian"*) ;;
  *) echo "unexpected error: $err" >&2; exit 1 ;;
esac
