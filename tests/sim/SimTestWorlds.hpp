// Small worlds built in code for the simulator tests.
#pragma once

#include <string>

#include "dynamap/robotio/sim/WorldLoader.hpp"

namespace dynamap::robotio::sim::testing {

// A 20 x 20 m floor with one wall (id "wall") whose near face is at x = wall_x, facing -x.
inline std::string WallWorldYaml(double wall_x, const std::string& extra = "") {
  const double centre = wall_x + 0.1;
  return "name: wall_test\n"
         "floor: {min: [-10, -10], max: [10, 10]}\n"
         "robot_start: {x: 0, y: 0, yaw_deg: 0}\n"
         "walls:\n"
         "  - {id: wall, from: [" + std::to_string(centre) + ", -9], to: [" +
         std::to_string(centre) + ", 9], thickness: 0.2, height: 3}\n" + extra;
}

inline World MustParse(const std::string& yaml) {
  auto world = ParseWorld(yaml, "test.yaml");
  if (!world) throw std::runtime_error(world.error().message);
  return std::move(world).value();
}

}  // namespace dynamap::robotio::sim::testing
