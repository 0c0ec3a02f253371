// Where to go next (thesis 6.2, "based on image processing"): frontier regions (Yamauchi
// 1997) and inspection targets found on the projected map with OpenCV imgproc, each with a
// reachable viewpoint, scored by expected gain over path cost; blacklisting of failing
// targets and "return to start" when nothing worth reaching remains.
#pragma once

#include <string>
#include <vector>

#include "dynamap/planning/GridMap.hpp"
#include "dynamap/planning/SurfaceCoverage.hpp"
#include "dynamap/planning/TargetBlacklist.hpp"
#include "dynamap/planning/TraversalGrid.hpp"

namespace dynamap::planning {

struct TargetPlannerConfig {
  std::string strategy = "tour";         // "gain": gain over path cost; "tour": first stop
                                         // of the shortest tour through all targets to the
                                         // start (TargetTour.hpp); "nearest-frontier":
                                         // Yamauchi's closest reachable frontier (baseline).
  double min_frontier_length_m = 0.3;    // m, frontier regions with fewer cells·resolution drop.
  double sensor_range_m = 4.5;           // m, range within which unknown area counts as gain.
  double viewpoint_radius_m = 1.5;       // m, farthest a frontier viewpoint may be from it,
                                         // beyond min_view_distance_m.
  double min_view_distance_m = 0.0;      // m, nearest a frontier viewpoint should be: the
                                         // unseen side of a frontier is mostly floor, which
                                         // the Kinects see only beyond their floor blind
                                         // radius (the runtime sets it from the rig).
  double min_gain_m2 = 0.2;              // m², frontier targets revealing less are not worth it
                                         // (up to 12 further viewpoints are tried first).
  double path_cost_offset_m = 1.0;       // m added to path cost in score = gain / (cost + offset),
                                         // so targets next to the robot do not win by ~1/0.
  bool inspection = true;                // Also plan inspection targets.
  bool frontiers_first = false;          // Inspection targets only once no frontier target
                                         // is left: the floor plan first, then the walls.
                                         // Explores the office faster; on the small office
                                         // the robot went to and fro in the corridor
                                         // between two rooms' frontiers (surfaces 0.35
                                         // instead of 0.61; docs/RESULTS.md).
  double inspection_weight = 1.0;        // Score per m of unseen surface, relative to per m².
  double min_inspection_m = 0.5;         // m of unseen surface below which a region is ignored.
  double home_tolerance_m = 0.3;         // m, within this of the start the mission is done.
  double tour_scale_m = 7.5;             // "tour": score = exp(-(tour - shortest tour) / this),
                                         // so with the selection's switch ratio of 1.5 a
                                         // new target must shorten the tour by 3 m.
  double tour_cell_m = 0.2;              // "tour": cell of the coarse grid the distances
                                         // between viewpoints are measured on.
  TargetBlacklistConfig blacklist;       // How failures turn into blacklisted places.
};

enum class TargetKind { kFrontier, kInspection, kReturnToStart, kDone };

[[nodiscard]] const char* TargetKindName(TargetKind kind);

struct TargetCandidate {
  TargetKind kind = TargetKind::kFrontier;
  GridIndex viewpoint;        // Where the robot should go.
  GridIndex region_center;    // The region cell nearest the region's centroid.
  int region_cells = 0;
  double gain = 0.0;          // m² unknown area (frontier) or weighted m of surface (inspection).
  double path_cost_m = 0.0;   // Planner cost to the viewpoint, m (proximity cost included).
  double score = 0.0;
  double tour_length_m = 0.0; // "tour": the shortest tour found that visits this target first.
};

struct TargetDecision {
  TargetKind kind = TargetKind::kDone;
  GridIndex cell;                          // Goal cell (viewpoint or start).
  TargetCandidate chosen;                  // Meaningful for kFrontier / kInspection.
  std::vector<TargetCandidate> candidates; // Every scored region (for display).
  int frontier_regions = 0;                // Regions found before dropping small ones.
  int unreachable_regions = 0;             // Kept regions without a reachable viewpoint.
  int blacklisted_regions = 0;             // Regions skipped for the blacklist.
  // The frontier regions among those two (their centre cells): what a "done" leaves
  // unexplored, for the operator to look at.
  std::vector<GridIndex> unreachable_frontiers;
  std::vector<GridIndex> blacklisted_frontiers;
};

class TargetPlanner {
 public:
  // `resolution_m` is the projected map's (blacklist radii are converted with it).
  TargetPlanner(TargetPlannerConfig config, double resolution_m);

  // `grid` is the traversal grid built from `map`; `home` the start cell; `coverage` may be
  // null (no inspection targets then). `squeeze`, when given, is the map inflated by the
  // squeeze radius (BuildSqueezeGrid): a region with no viewpoint reachable on `grid` takes
  // one reachable on it, since the path planner squeezes where the full radius leaves no
  // way (a doorway whose open leaf was mapped a cell thick). Inspection viewpoints taken
  // that way must stand free at the full radius: a surface is looked at from the room
  // beyond a squeezed doorway, never from inside a squeeze.
  [[nodiscard]] TargetDecision Plan(const GridMap& map, const TraversalGrid& grid, GridIndex robot,
                                    GridIndex home, const SurfaceCoverage* coverage,
                                    double now_s, const TraversalGrid* squeeze = nullptr) const;

  // The runtime reports that reaching `target` failed (path blocked, timeout) or that the
  // path planner found it unreachable; repeated failures blacklist the region for a while
  // (by its centre, so another viewpoint of the same region is not tried right away).
  void ReportFailure(const TargetCandidate& target, double now_s) {
    blacklist_.ReportFailure(target.region_center, now_s);
  }
  void ReportUnreachable(const TargetCandidate& target, double now_s) {
    blacklist_.Blacklist(target.region_center, now_s);
  }
  // `decision` found nothing left but blacklisted regions: with `blacklist.last_try`, lifts
  // the bans for a last try (TargetBlacklist::LiftBansForALastTry) and returns how many, so
  // the caller plans again. A region that failed early (a door shut while the robot looked
  // in) would otherwise stay unexplored when its ban outlasts everything else. Never for
  // the nearest frontier, the plain baseline the other strategies are compared with.
  int LiftBansForALastTry(const TargetDecision& decision, double now_s) {
    if (!config_.blacklist.last_try || config_.strategy == "nearest-frontier" ||
        !decision.candidates.empty() || decision.blacklisted_regions == 0) {
      return 0;
    }
    return blacklist_.LiftBansForALastTry(now_s);
  }

  [[nodiscard]] const TargetBlacklist& blacklist() const { return blacklist_; }
  [[nodiscard]] const TargetPlannerConfig& config() const { return config_; }

 private:
  // "tour": scores every candidate by the shortest tour found that visits it first and
  // ends at `home` (distances between viewpoints on `grid`, coarsened).
  void ScoreByTour(TargetDecision* decision, const TraversalGrid& grid, GridIndex home,
                   double resolution_m) const;

  TargetPlannerConfig config_;
  TargetBlacklist blacklist_;
};

}  // namespace dynamap::planning
