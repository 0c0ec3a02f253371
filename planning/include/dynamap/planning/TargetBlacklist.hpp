// Places the target planner must avoid for a while: targets found unreachable, or whose
// approach failed repeatedly (thesis 6.2), matched by distance in cells.
#pragma once

#include <vector>

#include "dynamap/planning/GridMap.hpp"

namespace dynamap::planning {

struct TargetBlacklistConfig {
  double duration_s = 60.0;  // s a place stays blacklisted the first time; each later
                             // time twice as long as the one before, up to the maximum,
                             // so a place that keeps failing stops luring the robot back.
  double max_duration_s = 600.0;
  double radius_m = 0.5;     // m, targets this close to a blacklisted place count as it.
  int max_failures = 2;      // Failed approaches before a place is blacklisted.
  bool last_try = true;      // When nothing else is left, every banned place is tried once
                             // more before the robot goes home (LiftBansForALastTry).
};

class TargetBlacklist {
 public:
  TargetBlacklist(TargetBlacklistConfig config, double resolution_m)
      : config_(config), radius_cells_(config.radius_m / resolution_m) {}

  void ReportFailure(GridIndex cell, double now_s);
  void Blacklist(GridIndex cell, double now_s);
  [[nodiscard]] bool IsBlacklisted(GridIndex cell, double now_s) const;
  [[nodiscard]] int ActiveCount(double now_s) const;
  // Ends the bans running at `now_s` of places never let off before, so each place gets
  // one more try when nothing else is left; returns how many. A place banned since it was
  // let off stays banned.
  int LiftBansForALastTry(double now_s);

 private:
  struct Entry {
    GridIndex cell;
    int failures = 0;
    double until_s = -1.0;  // Blacklisted while now < until_s.
    int times = 0;          // How often it has been blacklisted.
    bool let_off = false;   // Its ban was lifted for a last try.
  };
  void Ban(Entry& e, double now_s) const;
  [[nodiscard]] bool Near(GridIndex a, GridIndex b) const;

  TargetBlacklistConfig config_;
  double radius_cells_;
  std::vector<Entry> entries_;
};

}  // namespace dynamap::planning
