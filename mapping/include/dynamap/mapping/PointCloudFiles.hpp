// Occupied voxel centres as point clouds for offline inspection (DESIGN.md, mapping):
// ASCII .ply and .pcd writers and the matching readers (the subset these writers produce).
#pragma once

#include <string>

#include "dynamap/robotio/DepthProjection.hpp"
#include "dynamap/robotio/Expected.hpp"

namespace dynamap::mapping {

// Written atomically; coordinates in metres (map frame) with 6 decimals.
[[nodiscard]] robotio::Status WritePly(const robotio::PointList& points, const std::string& file);
[[nodiscard]] robotio::Status WritePcd(const robotio::PointList& points, const std::string& file);

// Read ASCII x/y/z clouds; an unreadable or malformed file is an Error naming it.
[[nodiscard]] robotio::Expected<robotio::PointList> ReadPly(const std::string& file);
[[nodiscard]] robotio::Expected<robotio::PointList> ReadPcd(const std::string& file);

}  // namespace dynamap::mapping
