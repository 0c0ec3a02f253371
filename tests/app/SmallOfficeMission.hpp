// The mission the runtime tests run: the small office (a corridor, three rooms, a door that
// closes, a chair that moves, a person walking) with Kinect images at 160 × 120.
#pragma once

#include <string>

#include "../robotio/TestPaths.hpp"
#include "dynamap/app/runtime/MissionConfig.hpp"

namespace dynamap::app::runtime {

inline MissionConfig SmallOfficeMission(const std::string& out) {
  MissionConfig config;
  config.world_file = test::Resource("worlds/small_office.yaml");
  config.out_dir = out;
  config.kinect_width = 160;
  config.kinect_height = 120;
  return config;
}

}  // namespace dynamap::app::runtime
