#!/bin/sh
# dynamap explore --final-map: the mission records itself, maps that recording again along
# its loop-closed trajectory.tum into final_map/, and its report.json carries that map's
# figures as final_map/report.json has them.
# Usage: explore_final_map.sh DYNAMAP RESOURCES_DIR SCRATCH_DIR
set -eu
dynamap="$1"; resources="$2"; scratch="$3"
rm -rf "$scratch"; mkdir -p "$scratch"
run="$scratch/run"
"$dynamap" explore --world "$resources/worlds/small_office.yaml" --max-time 8 \
  --kinect-width 80 --final-map --headless --out "$run" > "$scratch/out.txt" 2>&1

for f in recording/depth.txt final_map/report.json final_map/map.ot final_map/static.bt \
         final_map/topdown.png; do
  [ -s "$run/$f" ] || { echo "no $f after explore --final-map" >&2; exit 1; }
done
grep -q "^final map ($run/final_map): SA " "$scratch/out.txt" || {
  echo "explore did not print the final map's figures" >&2; cat "$scratch/out.txt" >&2; exit 1; }

python3 - "$run" <<'PY'
import json, sys
run = sys.argv[1]
mission = json.load(open(run + "/report.json"))
final = json.load(open(run + "/final_map/report.json"))
assert final["poses"] == "trajectory", final["poses"]
assert final["trajectory"] == run + "/trajectory.tum", final["trajectory"]
recorded = sum(1 for name in ("depth.txt", "depth1.txt")
               for line in open(run + "/recording/" + name) if not line.startswith("#"))
assert final["frames"] == recorded, (final["frames"], recorded)
figures = mission["final_map"]
assert figures["dir"] == "final_map"
assert "final_map" in mission["files"], mission["files"]
for key in ("static_accuracy", "dynamic_accuracy", "static_map_precision",
            "static_map_completeness", "ate_rmse_m"):
    assert figures[key] == final[key], (key, figures[key], final[key])
# The same trajectory against the same truth: the mission's ATE.
assert abs(figures["ate_rmse_m"] - mission["ate_rmse_m"]) < 1e-6
assert 0.9 < figures["static_accuracy"] <= 1.0, figures["static_accuracy"]
PY
