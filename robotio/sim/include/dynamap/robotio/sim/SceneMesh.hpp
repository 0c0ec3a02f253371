// Triangle meshes of a world's solids, floor and holes (world frame), each triangle
// carrying its ground-truth label, for the depth renderer and surface sampling.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "dynamap/robotio/sim/World.hpp"
#include "dynamap/robotio/sim/WorldTimeline.hpp"

namespace dynamap::robotio::sim {

// Label value of an object: index + 1, with LabelFrame::kDynamicBit when dynamic.
[[nodiscard]] std::uint16_t MakeLabel(int object_index, bool dynamic);

struct TriangleMesh {
  std::vector<Eigen::Vector3f> vertices;              // m, world frame.
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::uint16_t> labels;                  // One per triangle.

  void AddTriangle(const Eigen::Vector3f& a, const Eigen::Vector3f& b, const Eigen::Vector3f& c,
                   std::uint16_t label);
  // Quad a-b-c-d (in order around its edge) as two triangles.
  void AddQuad(const Eigen::Vector3f& a, const Eigen::Vector3f& b, const Eigen::Vector3f& c,
               const Eigen::Vector3f& d, std::uint16_t label);
  void AddSolid(const Solid& solid);
  void Append(const TriangleMesh& other);
};

// The floor with the holes cut out, and each hole's pit (walls and bottom).
[[nodiscard]] TriangleMesh FloorMesh(const World& world);
[[nodiscard]] TriangleMesh SolidsMesh(const std::vector<Solid>& solids);

}  // namespace dynamap::robotio::sim
