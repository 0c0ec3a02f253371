// CPU time of the calling thread and of the whole process (Linux clocks), for the per-thread
// load of a mission (report.json "cpu_s", docs/BENCHMARKS.md).
#pragma once

namespace dynamap::app::runtime {

// CPU seconds the calling thread has used since it started.
[[nodiscard]] double ThreadCpuSeconds();
// CPU seconds the process has used, finished threads included.
[[nodiscard]] double ProcessCpuSeconds();

// Where a mission's CPU time went.
struct MissionCpu {
  double simulation_s = 0.0;  // Simulator stepping, collision checks, Kinect noise, frame
                              // delivery, and one of the renderer's threads.
  double mapping_s = 0.0;     // SLAM / pose placement, dual-map insertion, projection.
  double planning_s = 0.0;    // Grid preparation, target planning, D* Lite.
  double control_s = 0.0;     // Path follower, collision and map guards.
  double other_s = 0.0;       // The rest of the process while the mission ran: the
                              // renderer's other threads and the front end.
};

}  // namespace dynamap::app::runtime
