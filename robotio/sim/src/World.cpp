#include "dynamap/robotio/sim/World.hpp"

namespace dynamap::robotio::sim {

Eigen::Isometry3d World::T_map_world() const { return robot_start.ToIsometry().inverse(); }

Pose2D World::ToMap(const Pose2D& world_pose) const { return robot_start.Between(world_pose); }

Pose2D World::ToWorld(const Pose2D& map_pose) const { return robot_start.Compose(map_pose); }

int World::FindObject(const std::string& id) const {
  for (std::size_t i = 0; i < objects.size(); ++i) {
    if (objects[i].id == id) return static_cast<int>(i);
  }
  return -1;
}

std::pair<double, double> TeleopCommandAt(const World& world, double t_s) {
  double start = 0.0;
  for (const TeleopSegment& segment : world.teleop) {
    if (t_s < start + segment.duration_s) return {segment.v, segment.omega};
    start += segment.duration_s;
  }
  return {0.0, 0.0};
}

}  // namespace dynamap::robotio::sim
