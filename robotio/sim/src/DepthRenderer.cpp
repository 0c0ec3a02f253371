#include "dynamap/robotio/sim/DepthRenderer.hpp"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>

#include "dynamap/robotio/sim/SceneMesh.hpp"

namespace dynamap::robotio::sim {

namespace {

constexpr unsigned kFixedGeometry = 0;
constexpr unsigned kMovingGeometry = 1;
constexpr int kTile = 4;  // 4x4 pixel tiles: one coherent 16-ray packet.

RTCGeometry MakeGeometry(RTCDevice device, const TriangleMesh& mesh, RTCBuildQuality quality) {
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  rtcSetGeometryBuildQuality(geometry, quality);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
      mesh.vertices.size()));
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    for (int k = 0; k < 3; ++k) vertices[3 * i + k] = mesh.vertices[i][k];
  }
  auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
      mesh.triangles.size()));
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    for (int k = 0; k < 3; ++k) indices[3 * i + k] = mesh.triangles[i][k];
  }
  rtcCommitGeometry(geometry);
  return geometry;
}

// Runs body(i) for i in [0, n) on `threads` threads, handing out indices one at a time.
template <typename Body>
void ParallelFor(int n, int threads, const Body& body) {
  std::atomic<int> next{0};
  auto worker = [&] {
    for (int i = next++; i < n; i = next++) body(i);
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
}

}  // namespace

struct DepthRenderer::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<std::uint16_t> fixed_labels;
  std::vector<std::uint16_t> moving_labels;
  bool has_moving = false;
};

DepthRenderer::DepthRenderer(const World& world, int threads)
    : impl_(std::make_unique<Impl>()), threads_(std::max(1, threads)) {
  impl_->device = rtcNewDevice("threads=2");
  if (impl_->device == nullptr) throw std::runtime_error("Embree: cannot create a device");
  impl_->scene = rtcNewScene(impl_->device);
  // Two-level scene: only the small moving geometry is rebuilt per frame.
  rtcSetSceneFlags(impl_->scene, RTC_SCENE_FLAG_DYNAMIC);
  rtcSetSceneBuildQuality(impl_->scene, RTC_BUILD_QUALITY_LOW);
  TriangleMesh fixed = FloorMesh(world);
  fixed.Append(SolidsMesh(FixedSolids(world)));
  impl_->fixed_labels = fixed.labels;
  RTCGeometry geometry = MakeGeometry(impl_->device, fixed, RTC_BUILD_QUALITY_HIGH);
  rtcAttachGeometryByID(impl_->scene, geometry, kFixedGeometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(impl_->scene);
}

DepthRenderer::~DepthRenderer() {
  rtcReleaseScene(impl_->scene);
  rtcReleaseDevice(impl_->device);
}

void DepthRenderer::SetMovingSolids(const std::vector<Solid>& solids) {
  if (impl_->has_moving) rtcDetachGeometry(impl_->scene, kMovingGeometry);
  impl_->has_moving = false;
  const TriangleMesh mesh = SolidsMesh(solids);
  impl_->moving_labels = mesh.labels;
  if (!mesh.triangles.empty()) {
    RTCGeometry geometry = MakeGeometry(impl_->device, mesh, RTC_BUILD_QUALITY_LOW);
    rtcAttachGeometryByID(impl_->scene, geometry, kMovingGeometry);
    rtcReleaseGeometry(geometry);
    impl_->has_moving = true;
  }
  rtcCommitScene(impl_->scene);
}

RenderedImage DepthRenderer::Render(const Eigen::Isometry3d& T_world_kinect,
                                    const Intrinsics& k, double min_range_m,
                                    const KinectModelConfig& model,
                                    std::uint64_t noise_key) const {
  const int w = k.width;
  const int h = k.height;
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  // Pass 1: true depth along the optical axis, incidence cosine and label per pixel.
  std::vector<float> z(n, std::numeric_limits<float>::infinity());
  std::vector<float> cos_incidence(n, 0.0f);
  std::vector<std::uint16_t> label(n, 0);
  const Eigen::Matrix3f R = T_world_kinect.linear().cast<float>();
  const Eigen::Vector3f origin = T_world_kinect.translation().cast<float>();
  // Ray direction = R * (xn, yn, 1): per-column and per-row terms computed once.
  std::vector<Eigen::Vector3f> column_term(static_cast<std::size_t>(w) + kTile);
  std::vector<Eigen::Vector3f> row_term(static_cast<std::size_t>(h) + kTile);
  for (int u = 0; u < w + kTile; ++u) {
    column_term[u] = R.col(0) * static_cast<float>((u - k.cx) / k.fx) + R.col(2);
  }
  for (int v = 0; v < h + kTile; ++v) row_term[v] = R.col(1) * static_cast<float>((v - k.cy) / k.fy);
  const int tiles_x = (w + kTile - 1) / kTile;
  const int tiles_y = (h + kTile - 1) / kTile;
  const float far = static_cast<float>(model.far_limit_m) * 1.01f;
  ParallelFor(tiles_y, threads_, [&](int ty) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    alignas(64) RTCRayHit16 packet;
    alignas(64) int valid[16];
    for (int tx = 0; tx < tiles_x; ++tx) {
      for (int i = 0; i < 16; ++i) {
        const int u = tx * kTile + i % kTile;
        const int v = ty * kTile + i / kTile;
        valid[i] = (u < w && v < h) ? -1 : 0;
        // Direction with optical z = 1, so the hit distance t is the depth z itself.
        const Eigen::Vector3f d = column_term[u] + row_term[v];
        packet.ray.org_x[i] = origin.x();
        packet.ray.org_y[i] = origin.y();
        packet.ray.org_z[i] = origin.z();
        packet.ray.dir_x[i] = d.x();
        packet.ray.dir_y[i] = d.y();
        packet.ray.dir_z[i] = d.z();
        packet.ray.tnear[i] = 0.0f;
        packet.ray.tfar[i] = far;
        packet.ray.time[i] = 0.0f;
        packet.ray.mask[i] = 0xffffffffu;
        packet.ray.id[i] = static_cast<unsigned>(i);
        packet.ray.flags[i] = 0;
        packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
        packet.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
      }
      rtcIntersect16(valid, impl_->scene, &context, &packet);
      for (int i = 0; i < 16; ++i) {
        if (valid[i] == 0 || packet.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID) continue;
        const int u = tx * kTile + i % kTile;
        const int v = ty * kTile + i / kTile;
        const std::size_t p = static_cast<std::size_t>(v) * w + u;
        z[p] = packet.ray.tfar[i];
        const Eigen::Vector3f ng(packet.hit.Ng_x[i], packet.hit.Ng_y[i], packet.hit.Ng_z[i]);
        const Eigen::Vector3f d(packet.ray.dir_x[i], packet.ray.dir_y[i], packet.ray.dir_z[i]);
        cos_incidence[p] = std::abs(ng.dot(d)) / (ng.norm() * d.norm() + 1e-20f);
        const auto& labels =
            packet.hit.geomID[i] == kFixedGeometry ? impl_->fixed_labels : impl_->moving_labels;
        label[p] = labels[packet.hit.primID[i]];
      }
    }
  });
  rays_cast_ += n;

  // Pass 2: the Kinect model, which needs each pixel's neighbours for discontinuities.
  RenderedImage out;
  out.depth.width = out.labels.width = w;
  out.depth.height = out.labels.height = h;
  out.depth.intrinsics = k;
  out.depth.depth_mm.assign(n, 0);
  out.labels.labels.assign(n, 0);
  const float ratio = static_cast<float>(model.edge_jump_ratio);
  ParallelFor(h, threads_, [&](int v) {
    for (int u = 0; u < w; ++u) {
      const std::size_t p = static_cast<std::size_t>(v) * w + u;
      const float zp = z[p];
      if (!(zp >= min_range_m) || !std::isfinite(zp)) continue;
      bool edge = false;
      const int du[4] = {-1, 1, 0, 0};
      const int dv[4] = {0, 0, -1, 1};
      for (int j = 0; j < 4 && !edge; ++j) {
        const int un = u + du[j];
        const int vn = v + dv[j];
        if (un < 0 || vn < 0 || un >= w || vn >= h) continue;
        const float zn = z[static_cast<std::size_t>(vn) * w + un];
        edge = !(std::abs(zn - zp) <= ratio * zp);
      }
      const std::uint16_t mm = MeasureDepth(model, zp, cos_incidence[p], edge,
                                            HashKey(noise_key, p));
      out.depth.depth_mm[p] = mm;
      if (mm != 0) out.labels.labels[p] = label[p];
    }
  });
  return out;
}

}  // namespace dynamap::robotio::sim
