// Simulator speed (docs/BENCHMARKS.md, "Simulator (depth rendering)"):
//   1. rays per second of the depth renderer on office.yaml (640 x 480, Kinect model on);
//   2. a full two-Kinect 640 x 480 x 30 Hz simulation along office.yaml's teleop path,
//      as a multiple of real time (rendering, base, labels; no file writing).
// Usage: bench_sim [seconds_to_simulate (default 20)] [render_threads (default 2)]
#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "dynamap/robotio/Rig.hpp"
#include "dynamap/robotio/Time.hpp"
#include "dynamap/robotio/sim/DepthRenderer.hpp"
#include "dynamap/robotio/sim/Simulator.hpp"
#include "dynamap/robotio/sim/WorldLoader.hpp"

namespace sim = dynamap::robotio::sim;
using Clock = std::chrono::steady_clock;

int main(int argc, char** argv) {
  const double seconds = argc > 1 ? std::atof(argv[1]) : 20.0;
  const int threads = argc > 2 ? std::atoi(argv[2]) : 2;
  const std::string resources = DYNAMAP_RESOURCES_DIR;
  auto world = sim::LoadWorld(resources + "/worlds/office.yaml");
  auto rig = dynamap::robotio::LoadRig(resources + "/rigs/two_kinects.yaml");
  auto robot = sim::LoadRobotConfig(resources + "/robots/segway_rmp50.yaml");
  if (!world || !rig || !robot) {
    std::fprintf(stderr, "bench_sim: cannot load the office world, rig or robot\n");
    return 1;
  }

  // 1. Renderer alone: frames from poses along the corridor, both mounts.
  {
    sim::DepthRenderer renderer(*world, threads);
    renderer.SetMovingSolids(sim::MovingSolidsAt(*world, 0.0));
    sim::KinectModelConfig model;
    model.enabled = std::getenv("BENCH_SIM_EXACT") == nullptr;
    const int frames = 120;
    const auto start = Clock::now();
    const std::clock_t cpu_start = std::clock();
    std::uint64_t checksum = 0;
    for (int i = 0; i < frames; ++i) {
      const dynamap::robotio::Pose2D pose{1.5 + 0.2 * i, 7.7, 0.05 * i};
      const auto& mount = rig->kinects[i % rig->kinects.size()];
      const auto image = renderer.Render(pose.ToIsometry() * mount.T_base_kinect, mount.intrinsics,
                                         mount.min_range_m, model, i);
      checksum += image.depth.depth_mm[image.depth.depth_mm.size() / 2];
    }
    const double wall = std::chrono::duration<double>(Clock::now() - start).count();
    const double cpu = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    std::printf("renderer: %d frames 640x480 in %.3f s = %.1f frames/s, %.2f Mrays/s; "
                "%.2f Mrays per CPU-second (%d threads, Kinect model %s, checksum %llu)\n",
                frames, wall, frames / wall, renderer.rays_cast() / wall / 1e6,
                renderer.rays_cast() / cpu / 1e6, threads, model.enabled ? "on" : "off",
                static_cast<unsigned long long>(checksum));
  }

  // 2. Full simulation along the scripted path.
  {
    sim::SimulatorConfig config;
    config.render_threads = threads;
    sim::Simulator simulator(*world, *robot, *rig, config);
    const auto start = Clock::now();
    const std::clock_t cpu_start = std::clock();
    std::size_t frames = 0;
    const std::int64_t end = dynamap::robotio::SecondsToNanos(seconds);
    while (simulator.now_ns() < end) {
      const auto [v, omega] =
          sim::TeleopCommandAt(*world, dynamap::robotio::NanosToSeconds(simulator.now_ns()));
      simulator.SetCommand({simulator.now_ns(), v, omega});
      frames += simulator.Advance(0.05).frames.size();
    }
    const double wall = std::chrono::duration<double>(Clock::now() - start).count();
    const double cpu = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    std::printf("simulation: %.1f s simulated (2 Kinects 640x480 @ 30 Hz, %zu frames) in %.2f s "
                "= %.2fx real time; %.2f CPU-seconds per simulated second\n",
                seconds, frames, wall, seconds / wall, cpu / seconds);
  }
  return 0;
}
