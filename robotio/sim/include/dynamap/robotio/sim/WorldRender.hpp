// A top-down picture of a world file (walls, doors, furniture, holes, steps, people
// paths, robot start and scripted path, scale bar), so a person can check what it says.
#pragma once

#include <string>

#include "dynamap/robotio/Expected.hpp"
#include "dynamap/robotio/sim/World.hpp"

namespace dynamap::robotio::sim {

struct WorldRenderConfig {
  double pixels_per_metre = 40.0;  // px/m.
  int margin_px = 40;              // px around the floor.
};

// Writes a PNG (world frame, x right, y up).
[[nodiscard]] Status RenderWorldPng(const World& world, const std::string& png_file,
                                    const WorldRenderConfig& config = {});

}  // namespace dynamap::robotio::sim
