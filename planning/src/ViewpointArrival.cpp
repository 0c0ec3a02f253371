#include "dynamap/planning/ViewpointArrival.hpp"

#include <cmath>

namespace dynamap::planning {

bool ViewpointArrival::StillFacing(const GridMap& map, const std::optional<TargetCandidate>& target,
                                   const robotio::Pose2D& pose, double now_s) {
  if (!target) {
    arrived_s_.reset();
    return false;
  }
  const GridIndex vp = target->viewpoint;
  const GridIndex look = target->region_center;
  if (std::hypot(map.CenterX(vp.x) - pose.x, map.CenterY(vp.y) - pose.y) > config_.arrived_m) {
    arrived_s_.reset();
    return false;
  }
  if (!arrived_s_) arrived_s_ = now_s;
  const double error = robotio::WrapAngle(
      std::atan2(map.CenterY(look.y) - pose.y, map.CenterX(look.x) - pose.x) - pose.theta);
  return std::abs(error) > config_.face_tolerance_rad && now_s - *arrived_s_ < config_.face_timeout_s;
}

}  // namespace dynamap::planning
