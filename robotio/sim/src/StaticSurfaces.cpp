#include "dynamap/robotio/sim/StaticSurfaces.hpp"

#include <algorithm>
#include <cmath>

#include "dynamap/robotio/sim/SceneMesh.hpp"

namespace dynamap::robotio::sim {

namespace {

// Deterministic sampling of a triangle on a grid of barycentric steps.
void SampleTriangle(const Eigen::Vector3f& a, const Eigen::Vector3f& b, const Eigen::Vector3f& c,
                    double spacing, const Eigen::Isometry3f& T, PointList* out) {
  const double lab = (b - a).norm();
  const double lac = (c - a).norm();
  const int nb = std::max(1, static_cast<int>(std::ceil(lab / spacing)));
  const int nc = std::max(1, static_cast<int>(std::ceil(lac / spacing)));
  for (int i = 0; i <= nb; ++i) {
    for (int j = 0; j <= nc; ++j) {
      const float s = static_cast<float>(i) / nb;
      const float t = static_cast<float>(j) / nc;
      if (s + t > 1.0f + 1e-6f) continue;
      out->push_back(T * (a + s * (b - a) + t * (c - a)));
    }
  }
}

}  // namespace

PointList SampleStaticSurfaces(const World& world, double spacing_m) {
  TriangleMesh mesh;
  const std::uint16_t floor_label = MakeLabel(0, false);
  const TriangleMesh floor = FloorMesh(world);
  for (std::size_t i = 0; i < floor.triangles.size(); ++i) {
    if (floor.labels[i] != floor_label) continue;  // Hole pits.
    const auto& t = floor.triangles[i];
    mesh.AddTriangle(floor.vertices[t[0]], floor.vertices[t[1]], floor.vertices[t[2]],
                     floor_label);
  }
  mesh.Append(SolidsMesh(FixedSolids(world)));
  mesh.Append(SolidsMesh(FinalMovableSolids(world)));
  const Eigen::Isometry3f T_map_world = world.T_map_world().cast<float>();
  PointList points;
  for (const auto& t : mesh.triangles) {
    SampleTriangle(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], spacing_m,
                   T_map_world, &points);
  }
  // Shared triangle edges are sampled twice: drop exact duplicates.
  std::sort(points.begin(), points.end(), [](const Eigen::Vector3f& p, const Eigen::Vector3f& q) {
    return std::lexicographical_compare(p.data(), p.data() + 3, q.data(), q.data() + 3);
  });
  points.erase(std::unique(points.begin(), points.end(),
                           [](const Eigen::Vector3f& p, const Eigen::Vector3f& q) {
                             return (p - q).squaredNorm() < 1e-10f;
                           }),
               points.end());
  return points;
}

}  // namespace dynamap::robotio::sim
