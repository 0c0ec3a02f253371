#include "dynamap/planning/TargetSelection.hpp"

#include <cmath>

namespace dynamap::planning {

namespace {

double DistanceM(const GridMap& map, GridIndex a, GridIndex b) {
  return std::hypot(a.x - b.x, a.y - b.y) * map.resolution_m;
}

}  // namespace

TargetSelection SelectTarget(const std::vector<TargetCandidate>& candidates,
                             const std::optional<TargetCandidate>& current, const GridMap& map,
                             GridIndex robot, const TargetSelectionConfig& config) {
  TargetSelection selection;
  const TargetCandidate* best = nullptr;
  const TargetCandidate* same = nullptr;
  const TargetCandidate* same_region = nullptr;  // Its viewpoint moved, its region did not.
  // A current target whose viewpoint the robot has reached is done, not kept.
  const bool current_open =
      current && DistanceM(map, current->viewpoint, robot) > config.near_m;
  for (const TargetCandidate& c : candidates) {
    if (!std::isfinite(c.score)) continue;
    if (DistanceM(map, c.viewpoint, robot) <= config.near_m) {
      selection.too_near.push_back(c);
      continue;
    }
    if (best == nullptr || c.score > best->score) best = &c;
    if (current_open && c.kind == current->kind &&
        DistanceM(map, c.viewpoint, current->viewpoint) <= config.same_target_m &&
        (same == nullptr || DistanceM(map, c.viewpoint, current->viewpoint) <
                                DistanceM(map, same->viewpoint, current->viewpoint))) {
      same = &c;
    }
    if (current_open && c.kind == current->kind &&
        DistanceM(map, c.region_center, current->region_center) <= config.same_target_m &&
        (same_region == nullptr || c.score > same_region->score)) {
      same_region = &c;
    }
  }
  if (best == nullptr) return selection;
  if (same != nullptr && best->score < config.switch_ratio * same->score) {
    // Keep driving to the same place: the goal cell stays, so the path search only repairs.
    TargetCandidate kept = *same;
    kept.viewpoint = current->viewpoint;
    selection.chosen = kept;
    selection.kept_current = true;
    return selection;
  }
  if (same == nullptr && same_region != nullptr &&
      best->score < config.switch_ratio * same_region->score) {
    // The region is still there, seen from elsewhere now (a region shrinks as the robot
    // approaches and sees part of it): go on with it rather than across the map.
    selection.chosen = *same_region;
    selection.kept_current = true;
    return selection;
  }
  selection.chosen = *best;
  return selection;
}

}  // namespace dynamap::planning
