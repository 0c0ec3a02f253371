#include "dynamap/planning/TargetSelection.hpp"

#include <algorithm>
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
  // The current target, re-scored: same kind, its viewpoint or its region centre near.
  const auto same_viewpoint = [&](const TargetCandidate& c) {
    return current && c.kind == current->kind &&
           DistanceM(map, c.viewpoint, current->viewpoint) <= config.same_target_m;
  };
  const auto same_region_center = [&](const TargetCandidate& c) {
    return current && c.kind == current->kind &&
           DistanceM(map, c.region_center, current->region_center) <= config.same_target_m;
  };
  for (const TargetCandidate& c : candidates) {
    if (!std::isfinite(c.score)) continue;
    if (DistanceM(map, c.viewpoint, robot) <= config.near_m) {
      selection.too_near.push_back(c);
      if (same_viewpoint(c) || same_region_center(c)) selection.looked_from_here.push_back(c);
      continue;
    }
    if (best == nullptr || c.score > best->score) best = &c;
    if (current_open && same_viewpoint(c) &&
        (same == nullptr || DistanceM(map, c.viewpoint, current->viewpoint) <
                                DistanceM(map, same->viewpoint, current->viewpoint))) {
      same = &c;
    }
    if (current_open && same_region_center(c) &&
        (same_region == nullptr || c.score > same_region->score)) {
      same_region = &c;
    }
  }
  if (best == nullptr) {
    selection.looked_from_here = selection.too_near;  // The robot stays and looks.
    return selection;
  }
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

std::optional<TargetCandidate> DroppedTargetKeeper::Keep(
    const std::optional<TargetCandidate>& previous, const std::optional<TargetCandidate>& next,
    const std::vector<TargetCandidate>& candidates, const GridMap& map, GridIndex robot,
    double now_s) {
  const auto same = [&](GridIndex a, GridIndex b) {
    return DistanceM(map, a, b) <= config_.same_region_m;
  };
  const bool open = previous && DistanceM(map, previous->viewpoint, robot) > config_.arrived_m;
  const bool still_there =
      open && std::any_of(candidates.begin(), candidates.end(), [&](const TargetCandidate& c) {
        return same(c.region_center, previous->region_center);
      });
  if (!open || still_there || (next && same(next->region_center, previous->region_center))) {
    dropped_since_s_.reset();
    return std::nullopt;
  }
  if (!dropped_since_s_) dropped_since_s_ = now_s;
  if (now_s - *dropped_since_s_ > config_.grace_s) return std::nullopt;
  if (next && next->score >= config_.better_ratio * previous->score) return std::nullopt;
  return previous;
}

}  // namespace dynamap::planning
