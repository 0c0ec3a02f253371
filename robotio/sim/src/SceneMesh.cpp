#include "dynamap/robotio/sim/SceneMesh.hpp"

#include <algorithm>
#include <cmath>

#include "dynamap/robotio/DepthFrame.hpp"

namespace dynamap::robotio::sim {

namespace {

constexpr int kCylinderSides = 16;

Eigen::Vector3f P(double x, double y, double z) {
  return {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)};
}

}  // namespace

std::uint16_t MakeLabel(int object_index, bool dynamic) {
  const auto id = static_cast<std::uint16_t>((object_index + 1) & LabelFrame::kIdMask);
  return dynamic ? static_cast<std::uint16_t>(id | LabelFrame::kDynamicBit) : id;
}

void TriangleMesh::AddTriangle(const Eigen::Vector3f& a, const Eigen::Vector3f& b,
                               const Eigen::Vector3f& c, std::uint16_t label) {
  const auto base = static_cast<std::uint32_t>(vertices.size());
  vertices.push_back(a);
  vertices.push_back(b);
  vertices.push_back(c);
  triangles.push_back({base, base + 1, base + 2});
  labels.push_back(label);
}

void TriangleMesh::AddQuad(const Eigen::Vector3f& a, const Eigen::Vector3f& b,
                           const Eigen::Vector3f& c, const Eigen::Vector3f& d,
                           std::uint16_t label) {
  const auto base = static_cast<std::uint32_t>(vertices.size());
  vertices.insert(vertices.end(), {a, b, c, d});
  triangles.push_back({base, base + 1, base + 2});
  triangles.push_back({base, base + 2, base + 3});
  labels.push_back(label);
  labels.push_back(label);
}

void TriangleMesh::AddSolid(const Solid& s) {
  const std::uint16_t label = MakeLabel(s.object_index, s.dynamic);
  const double z0 = s.z0;
  const double z1 = s.z0 + s.size.z();
  if (s.type == Solid::Type::kBox) {
    const double c = std::cos(s.pose.theta);
    const double sn = std::sin(s.pose.theta);
    const double hx = s.size.x() / 2.0;
    const double hy = s.size.y() / 2.0;
    std::array<Eigen::Vector2d, 4> corners;
    const double local[4][2] = {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
    for (int i = 0; i < 4; ++i) {
      corners[i] = {s.pose.x + c * local[i][0] - sn * local[i][1],
                    s.pose.y + sn * local[i][0] + c * local[i][1]};
    }
    for (int i = 0; i < 4; ++i) {
      const Eigen::Vector2d& a = corners[i];
      const Eigen::Vector2d& b = corners[(i + 1) % 4];
      AddQuad(P(a.x(), a.y(), z0), P(b.x(), b.y(), z0), P(b.x(), b.y(), z1), P(a.x(), a.y(), z1),
              label);
    }
    auto at = [&](int i, double z) { return P(corners[i].x(), corners[i].y(), z); };
    AddQuad(at(0, z1), at(1, z1), at(2, z1), at(3, z1), label);
    if (z0 > 1e-6) AddQuad(at(0, z0), at(3, z0), at(2, z0), at(1, z0), label);
    return;
  }
  const double r = s.size.x();
  for (int i = 0; i < kCylinderSides; ++i) {
    const double a0 = 2.0 * M_PI * i / kCylinderSides;
    const double a1 = 2.0 * M_PI * (i + 1) / kCylinderSides;
    const double x0 = s.pose.x + r * std::cos(a0);
    const double y0 = s.pose.y + r * std::sin(a0);
    const double x1 = s.pose.x + r * std::cos(a1);
    const double y1 = s.pose.y + r * std::sin(a1);
    AddQuad(P(x0, y0, z0), P(x1, y1, z0), P(x1, y1, z1), P(x0, y0, z1), label);
    AddTriangle(P(s.pose.x, s.pose.y, z1), P(x0, y0, z1), P(x1, y1, z1), label);
  }
}

void TriangleMesh::Append(const TriangleMesh& other) {
  const auto base = static_cast<std::uint32_t>(vertices.size());
  vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
  for (const auto& t : other.triangles) triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  labels.insert(labels.end(), other.labels.begin(), other.labels.end());
}

TriangleMesh FloorMesh(const World& world) {
  TriangleMesh mesh;
  // Split the floor rectangle along every hole edge and keep the cells outside holes.
  std::vector<double> xs{world.floor_min.x(), world.floor_max.x()};
  std::vector<double> ys{world.floor_min.y(), world.floor_max.y()};
  for (const Hole& h : world.holes) {
    xs.insert(xs.end(), {h.min.x(), h.max.x()});
    ys.insert(ys.end(), {h.min.y(), h.max.y()});
  }
  for (auto* v : {&xs, &ys}) {
    std::sort(v->begin(), v->end());
    v->erase(std::unique(v->begin(), v->end()), v->end());
  }
  const std::uint16_t floor_label = MakeLabel(0, false);
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
    for (std::size_t j = 0; j + 1 < ys.size(); ++j) {
      const Eigen::Vector2d mid((xs[i] + xs[i + 1]) / 2.0, (ys[j] + ys[j + 1]) / 2.0);
      const bool in_hole = std::any_of(world.holes.begin(), world.holes.end(), [&](const Hole& h) {
        return (mid - h.min).minCoeff() > 0.0 && (h.max - mid).minCoeff() > 0.0;
      });
      if (in_hole) continue;
      mesh.AddQuad(P(xs[i], ys[j], 0), P(xs[i + 1], ys[j], 0), P(xs[i + 1], ys[j + 1], 0),
                   P(xs[i], ys[j + 1], 0), floor_label);
    }
  }
  for (const Hole& h : world.holes) {
    const std::uint16_t label = MakeLabel(h.index, false);
    const double zb = -h.depth;
    const Eigen::Vector2d c[4] = {h.min, {h.max.x(), h.min.y()}, h.max, {h.min.x(), h.max.y()}};
    mesh.AddQuad(P(c[0].x(), c[0].y(), zb), P(c[1].x(), c[1].y(), zb), P(c[2].x(), c[2].y(), zb),
                 P(c[3].x(), c[3].y(), zb), label);
    for (int k = 0; k < 4; ++k) {
      const Eigen::Vector2d& a = c[k];
      const Eigen::Vector2d& b = c[(k + 1) % 4];
      mesh.AddQuad(P(a.x(), a.y(), zb), P(b.x(), b.y(), zb), P(b.x(), b.y(), 0.0),
                   P(a.x(), a.y(), 0.0), label);
    }
  }
  return mesh;
}

TriangleMesh SolidsMesh(const std::vector<Solid>& solids) {
  TriangleMesh mesh;
  for (const Solid& s : solids) mesh.AddSolid(s);
  return mesh;
}

}  // namespace dynamap::robotio::sim
