// The mission runtime end to end on the small office (a corridor, three rooms, a door that
// closes, a chair that moves, a person walking): the reduced-scale version of the
// exploration issue's Must-show, plus bad input and the periodic map save.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "../robotio/TestPaths.hpp"
#include "SmallOfficeMission.hpp"
#include "dynamap/app/runtime/MissionRuntime.hpp"
#include "dynamap/mapping/MapFiles.hpp"

namespace dynamap::app::runtime {
namespace {

namespace fs = std::filesystem;

// Where the final static map kept the points labelled dynamic (accuracy_errors.csv),
// summed over 1 m squares of the map frame, the three largest: what a low DA came from.
void PrintWhereDynamicPointsWereKept(const std::string& out) {
  std::ifstream csv(out + "/accuracy_errors.csv");
  std::map<std::pair<int, int>, long long> kept;
  long long total = 0;
  std::string line;
  while (std::getline(csv, line)) {
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;
    long long lost = 0;
    long long dynamic_kept = 0;
    if (std::sscanf(line.c_str(), "%lf,%lf,%lf,%lld,%lld", &x, &y, &z, &lost, &dynamic_kept) != 5) {
      continue;  // The comment and the header.
    }
    kept[{static_cast<int>(std::floor(x)), static_cast<int>(std::floor(y))}] += dynamic_kept;
    total += dynamic_kept;
  }
  std::vector<std::pair<long long, std::pair<int, int>>> squares;
  for (const auto& [square, points] : kept) squares.push_back({points, square});
  std::sort(squares.rbegin(), squares.rend());
  std::printf("dynamic points kept: %lld", total);
  for (std::size_t i = 0; i < std::min<std::size_t>(3, squares.size()); ++i) {
    std::printf(", %lld in [%d, %d]", squares[i].first, squares[i].second.first,
                squares[i].second.second);
  }
  std::printf(" (1 m squares, map frame)\n");
}

// Creates, runs until the mission ends by itself, and scores.
robotio::Expected<MissionReport> RunToTheEnd(const MissionConfig& config) {
  auto runtime = MissionRuntime::Create(config);
  if (!runtime) return runtime.error();
  (*runtime)->Start();
  (*runtime)->Wait();
  return (*runtime)->Finish();
}

TEST(ExplorationMission, AWorldFileWithAnErrorStopsBeforeTheMissionStarts) {
  const std::string out = test::ScratchDir();
  const std::string world = out + "/broken.yaml";
  std::ofstream(world) << "name: broken\nfloor: {min: [0, 0], max: [nope, 6]}\n";
  MissionConfig config = SmallOfficeMission(out + "/run");
  config.world_file = world;
  const auto runtime = MissionRuntime::Create(config);
  ASSERT_FALSE(runtime);
  EXPECT_NE(runtime.error().message.find("broken.yaml"), std::string::npos)
      << runtime.error().message;
  EXPECT_FALSE(fs::exists(out + "/run/map.ot"));
}

TEST(ExplorationMission, AMissingRigFileIsNamed) {
  const std::string out = test::ScratchDir();
  MissionConfig config = SmallOfficeMission(out);
  config.rig_file = out + "/no_such_rig.yaml";
  const auto runtime = MissionRuntime::Create(config);
  ASSERT_FALSE(runtime);
  EXPECT_NE(runtime.error().message.find("no_such_rig.yaml"), std::string::npos)
      << runtime.error().message;
}

TEST(ExplorationMission, AFolderHoldingAnEarlierRunIsRefusedUntouched) {
  const std::string out = test::ScratchDir();
  for (const char* earlier : {"report.json", "map.ot", "recording"}) {
    const std::string run = out + "/" + earlier + "_run";
    fs::create_directories(run);
    if (std::string(earlier) == "recording") {
      fs::create_directories(run + "/recording");
    } else {
      std::ofstream(run + "/" + earlier) << "earlier";
    }
    const auto runtime = MissionRuntime::Create(SmallOfficeMission(run));
    ASSERT_FALSE(runtime) << earlier;
    EXPECT_EQ(runtime.error().message,
              run + ": already holds a mission's results (" + earlier +
                  "); give a new output folder");
    std::size_t entries = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(run)) ++entries;
    EXPECT_EQ(entries, 1u) << earlier;
  }
  std::string kept;
  std::getline(std::ifstream(out + "/report.json_run/report.json"), kept);
  EXPECT_EQ(kept, "earlier");
  // An empty folder made beforehand (as scripts/demo does) is fine.
  fs::create_directories(out + "/empty");
  EXPECT_TRUE(MissionRuntime::Create(SmallOfficeMission(out + "/empty")));
}

TEST(ExplorationMission, MapsAreSavedPeriodicallyWhileTheMissionRuns) {
  const std::string out = test::ScratchDir();
  MissionConfig config = SmallOfficeMission(out);
  config.poses = PoseSource::kGroundTruth;
  config.save_period_s = 5.0;
  config.max_time_s = 60.0;
  auto runtime = MissionRuntime::Create(config);
  ASSERT_TRUE(runtime) << runtime.error().message;
  (*runtime)->Start();
  // What a killed process leaves: the last periodic save, complete and readable.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(3);
  while ((*runtime)->Snapshot().sim_time_s < 12.0 && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  ASSERT_TRUE(fs::exists(out + "/map.ot"));
  const auto saved = mapping::LoadMap(out + "/map.ot");
  ASSERT_TRUE(saved) << saved.error().message;
  EXPECT_GT((*saved)->size(), 1000u);
  (*runtime)->Stop();
  const auto report = (*runtime)->Finish();
  ASSERT_TRUE(report) << report.error().message;
  EXPECT_FALSE(report->completed);
  EXPECT_LT(report->mission_time_s, 60.0);
  EXPECT_GT(report->wall_time_s, 0.0);
  // Every worker's CPU time is accounted for, and no more than the machine could give.
  const MissionCpu& cpu = report->cpu;
  EXPECT_GT(cpu.simulation_s, 0.0);
  EXPECT_GT(cpu.mapping_s, 0.0);
  EXPECT_GT(cpu.planning_s, 0.0);
  EXPECT_GT(cpu.control_s, 0.0);
  EXPECT_GE(cpu.other_s, 0.0);
  const double total =
      cpu.simulation_s + cpu.mapping_s + cpu.planning_s + cpu.control_s + cpu.other_s;
  EXPECT_LE(total, report->wall_time_s * std::thread::hardware_concurrency() * 1.05 + 0.1);
}

// The first 30 s of a mission with SLAM poses (the default): the Kinects' staggered frames
// arrive one at a time and must be registered in pairs (one scan per instant), nearly all
// registrations accepted. The ATE varies from run to run (0.008 to 0.060 m in four runs,
// odometry alone 0.040 to 0.053 m): only a loose bound is asserted.
TEST(ExplorationMission, SlamRegistersBothKinectsOfAnInstantAsOneScan) {
  const std::string out = test::ScratchDir();
  MissionConfig config = SmallOfficeMission(out);
  config.poses = PoseSource::kSlam;
  config.max_time_s = 30.0;
  const auto report = RunToTheEnd(config);
  ASSERT_TRUE(report) << report.error().message;
  const std::int64_t registered = report->registrations_accepted + report->registrations_rejected;
  std::printf("%lld frames, %lld registrations (%lld accepted), ATE %.3f m, odometry %.3f m\n",
              static_cast<long long>(report->frames_processed), static_cast<long long>(registered),
              static_cast<long long>(report->registrations_accepted), report->ate_rmse_m,
              report->odometry_ate_rmse_m);
  ASSERT_GT(report->frames_processed, 1000);  // Two Kinects at 30 Hz for 30 s.
  EXPECT_LE(registered, report->frames_processed / 2 + 5);
  EXPECT_GE(registered, report->frames_processed * 4 / 10);
  EXPECT_GE(report->registrations_accepted, registered * 9 / 10);
  EXPECT_LT(report->ate_rmse_m, 0.1);
  // Loop closure keeps keyframes as the robot goes and closes at the end (nothing is old
  // enough to close within 30 s): the poses as the mission had them and the revisits
  // tried lie beside the trajectory.
  EXPECT_TRUE(fs::exists(out + "/trajectory_online.tum"));
  std::ifstream csv(out + "/loop_closures.csv");
  ASSERT_TRUE(csv.good());
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  EXPECT_EQ(line.rfind("older_stamp_s,newer_stamp_s,", 0), 0u) << line;
  std::int64_t closed = 0;
  while (std::getline(csv, line)) closed += line.size() > 7 && line.substr(line.size() - 7) == ",closed";
  EXPECT_EQ(report->loop_closures, closed);  // The report counts what the file lists.
  if (report->loop_closures == 0) {
    EXPECT_DOUBLE_EQ(report->ate_rmse_m, report->online_ate_rmse_m);
  }
}

// The whole mission, frames placed at the true poses (in-mission SLAM is not yet good
// enough: docs/RESULTS.md): three to four minutes of wall time on two cores. The
// thresholds are well below the figures measured in docs/RESULTS.md (explored 0.998-1.000,
// surfaces 0.98-1.00, no collisions in 6 runs of this mission, three at a time). Before
// the planner waited for people in its way, runs now and then explored only 0.64-0.68: a
// person pacing in front of room A's door had every target beyond it blacklisted in turn.
// Completion is reported, not asserted: the planner is often still inspecting at 200 s.
// DA came out 0.968-0.983 in sixteen runs of this mission (three with seeds 2-4; alone,
// three at a time, and beside the GUI tests), but 0.80 and 0.83 in two full ctest runs
// (the second with 0.85 above the floor layer, where the other runs keep next to
// nothing), for a reason not found: the bound sits below those and well above the
// regular update's 0.53 on the same mission (docs/RESULTS.md), and the test prints where
// the points were kept.
TEST(ExplorationMission, ExploresTheSmallOffice) {
  const std::string out = test::ScratchDir();
  MissionConfig config = SmallOfficeMission(out);
  config.poses = PoseSource::kGroundTruth;
  config.max_time_s = 200.0;
  const auto report = RunToTheEnd(config);
  ASSERT_TRUE(report) << report.error().message;
  std::printf(
      "completed %d in %.0f s, collisions %lld, explored %.3f, surfaces %.3f, SA %.3f, DA %.3f "
      "(above the floor layer %.3f)\n",
      report->completed ? 1 : 0, report->mission_time_s,
      static_cast<long long>(report->collisions), report->explored_free_fraction,
      report->surface_coverage, report->static_accuracy, report->dynamic_accuracy,
      report->dynamic_accuracy_above_floor);
  std::printf("guard stops %lld, map guard stops %lld, stalls %lld, plans %lld (%lld waiting for "
              "people), unreachable targets %lld\n",
              static_cast<long long>(report->guard_stops),
              static_cast<long long>(report->map_guard_stops),
              static_cast<long long>(report->stall_stops), static_cast<long long>(report->plans),
              static_cast<long long>(report->blocked_plans),
              static_cast<long long>(report->unreachable_targets));
  PrintWhereDynamicPointsWereKept(out);
  EXPECT_LE(report->mission_time_s, config.max_time_s + 1.0);
  EXPECT_EQ(report->frames_dropped, 0);
  EXPECT_GT(report->path_length_m, 10.0);  // It leaves the start and visits the rooms.
  EXPECT_LE(report->ate_rmse_m, 0.05);
  EXPECT_GE(report->explored_free_fraction, 0.85);
  EXPECT_GE(report->surface_coverage, 0.4);
  EXPECT_GE(report->dynamic_accuracy, 0.75);
  EXPECT_LE(report->collisions, 1);  // None measured; one contact is a warning, two a bug.
  // True poses are not off the map: the path is never shifted.
  EXPECT_EQ(report->path_shifted_s, 0.0);
  EXPECT_EQ(report->path_shift_max_m, 0.0);
  // It replans as it goes (every 0.5 s unless it is waiting for a turn to finish).
  EXPECT_GE(report->plans, static_cast<std::int64_t>(report->mission_time_s / 2.0));
  for (const char* file : {"map.ot", "static.bt", "dynamic.bt", "trajectory.tum", "groundtruth.tum",
                           "map2d.png", "map2d.pgm", "map2d.yaml", "coverage.png", "accuracy.png",
                           "accuracy_errors.csv", "report.json"}) {
    EXPECT_TRUE(fs::exists(out + "/" + file)) << file;
  }
}

}  // namespace
}  // namespace dynamap::app::runtime
