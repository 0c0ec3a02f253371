#include "dynamap/planning/TargetPlanner.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "GridMask.hpp"
#include "dynamap/planning/CostToGo.hpp"
#include "dynamap/planning/TargetTour.hpp"
#include "dynamap/planning/Visibility.hpp"

namespace dynamap::planning {

namespace {

// Viewpoints tried per frontier region before it is given up (every strategy), and
// how far (m) the next one must be from those that saw too little.
constexpr int kMaxViewpointTries = 12;
constexpr double kWantingRadiusM = 0.3;
// Cells of an inspection region a viewpoint is sought for when none sees its centre.
constexpr int kInspectionAnchors = 6;
// Cells around an inspection viewpoint reached by squeezing that must be free as well.
constexpr int kFreeStandingCells = 2;

struct Region {
  std::vector<int> cells;
  GridIndex center;  // Region cell nearest the centroid.
};

// Connected components (8-connected) of a binary mask with at least `min_cells` cells.
std::vector<Region> Regions(const GridMap& map, const cv::Mat& mask, int min_cells, int* found) {
  cv::Mat labels;
  cv::Mat stats;
  cv::Mat centroids;
  const int n = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8, CV_32S);
  *found = n - 1;
  std::vector<Region> regions(static_cast<std::size_t>(n));
  for (int y = 0; y < map.height; ++y) {
    const int* row = labels.ptr<int>(y);
    for (int x = 0; x < map.width; ++x) {
      if (row[x] > 0) regions[row[x]].cells.push_back(y * map.width + x);
    }
  }
  std::vector<Region> kept;
  for (int label = 1; label < n; ++label) {
    Region& r = regions[label];
    if (static_cast<int>(r.cells.size()) < min_cells) continue;
    const double cx = centroids.at<double>(label, 0);
    const double cy = centroids.at<double>(label, 1);
    double best = kInfinity;
    for (const int i : r.cells) {
      const GridIndex c = map.Cell(i);
      const double d = (c.x - cx) * (c.x - cx) + (c.y - cy) * (c.y - cy);
      if (d < best) {
        best = d;
        r.center = c;
      }
    }
    kept.push_back(std::move(r));
  }
  return kept;
}

// The region's centre, then up to `count - 1` more of its cells, each the one farthest
// from those already taken: the ends and corners of a wall or a desk. A surface region's
// centre can lie where nothing sees it (a desk mapped as a speckled block: its centre is a
// speck inside, and the front edge, connected to it, would never be looked at).
std::vector<GridIndex> SpreadCells(const GridMap& map, const Region& region, int count) {
  std::vector<GridIndex> anchors{region.center};
  std::vector<double> nearest(region.cells.size(), kInfinity);
  while (static_cast<int>(anchors.size()) < count) {
    const GridIndex last = anchors.back();
    std::size_t farthest = 0;
    for (std::size_t k = 0; k < region.cells.size(); ++k) {
      const GridIndex c = map.Cell(region.cells[k]);
      const double d = (c.x - last.x) * (c.x - last.x) + (c.y - last.y) * (c.y - last.y);
      nearest[k] = std::min(nearest[k], d);
      if (nearest[k] > nearest[farthest]) farthest = k;
    }
    if (nearest[farthest] <= 0.0) break;  // Every cell taken.
    anchors.push_back(map.Cell(region.cells[farthest]));
  }
  return anchors;
}

// No obstacle cell on the segment between two cell centres (what a sensor at `a` sees).
bool ClearSight(const GridMap& map, GridIndex a, GridIndex b) {
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  const int steps = static_cast<int>(std::ceil(2.0 * std::max(std::abs(dx), std::abs(dy))));
  for (int i = 1; i < steps; ++i) {
    const double t = static_cast<double>(i) / steps;
    const GridIndex c{static_cast<int>(std::floor(a.x + 0.5 + t * dx)),
                      static_cast<int>(std::floor(a.y + 0.5 + t * dy))};
    if (c != b && map.At(c) == CellState::kObstacle) return false;
  }
  return true;
}

struct Viewpoint {
  bool found = false;
  GridIndex cell;
  double cost = kInfinity;
};

// Cells within `radius_cells` of a viewpoint already found wanting (it sees too little).
struct Excluded {
  std::vector<GridIndex> cells;
  double radius_cells = 0.0;

  [[nodiscard]] bool Contains(GridIndex c) const {
    return std::any_of(cells.begin(), cells.end(), [&](GridIndex e) {
      return (c.x - e.x) * (c.x - e.x) + (c.y - e.y) * (c.y - e.y) <= radius_cells * radius_cells;
    });
  }
};

// The reachable cell between `min_cells` and `max_cells` from `center`, not excluded, that
// sees it and has the smallest key(squared distance to the centre, cost to reach it).
template <typename Key>
Viewpoint BestViewpoint(const GridMap& map, const std::vector<double>& cost_to_go, GridIndex center,
                        double min_cells, double max_cells, const Excluded& excluded, Key key) {
  Viewpoint best;
  double best_key = kInfinity;
  const int r = static_cast<int>(std::ceil(max_cells));
  for (int y = std::max(0, center.y - r); y <= std::min(map.height - 1, center.y + r); ++y) {
    for (int x = std::max(0, center.x - r); x <= std::min(map.width - 1, center.x + r); ++x) {
      const double dx = x - center.x;
      const double dy = y - center.y;
      const double d2 = dx * dx + dy * dy;
      if (d2 > max_cells * max_cells || d2 < min_cells * min_cells) continue;
      const double c = cost_to_go[static_cast<std::size_t>(y) * map.width + x];
      if (c >= kInfinity) continue;
      const double k = key(d2, c);
      if (k >= best_key) continue;
      const GridIndex cell{x, y};
      if (!ClearSight(map, cell, center) || excluded.Contains(cell)) continue;
      best = {true, cell, c};
      best_key = k;
    }
  }
  return best;
}

// The cheapest to reach.
Viewpoint FindViewpoint(const GridMap& map, const std::vector<double>& cost_to_go, GridIndex center,
                        double min_cells, double max_cells, const Excluded& excluded) {
  return BestViewpoint(map, cost_to_go, center, min_cells, max_cells, excluded,
                       [](double, double cost) { return cost; });
}

// The nearest to the region: for a region seen only through a doorway from afar, the place
// in front of the doorway (no cell near the region itself is reachable yet).
Viewpoint FindNearestViewpoint(const GridMap& map, const std::vector<double>& cost_to_go,
                               GridIndex center, double max_cells, const Excluded& excluded) {
  return BestViewpoint(map, cost_to_go, center, 0.0, max_cells, excluded,
                       [](double d2, double) { return d2; });
}

// Unknown area (m²) seen from `from` within the cone.
double UnknownSeen(const GridMap& map, GridIndex from, const ViewCone& cone) {
  int unknown_seen = 0;
  for (const int i : VisibleCells(map, from, cone)) {
    unknown_seen += map.cells[i] == CellState::kUnknown ? 1 : 0;
  }
  return unknown_seen * map.resolution_m * map.resolution_m;
}

// A start cell for the cost-to-go: the robot's, or the nearest free one when the robot
// stands inside the inflated zone (after a collision-guard stop, say).
GridIndex FreeCellNear(const TraversalGrid& grid, GridIndex robot, int radius) {
  if (!grid.Blocked(robot)) return robot;
  GridIndex best = robot;
  double best_d = kInfinity;
  for (int dy = -radius; dy <= radius; ++dy) {
    for (int dx = -radius; dx <= radius; ++dx) {
      const GridIndex c{robot.x + dx, robot.y + dy};
      const double d = dx * dx + dy * dy;
      if (d < best_d && !grid.Blocked(c)) {
        best_d = d;
        best = c;
      }
    }
  }
  return best;
}

}  // namespace

void TargetPlanner::ScoreByTour(TargetDecision* decision, const TraversalGrid& grid,
                                GridIndex home, double resolution_m) const {
  std::vector<TargetCandidate>& candidates = decision->candidates;
  if (candidates.empty()) return;
  TourCosts costs;
  std::vector<GridIndex> stops;
  for (const TargetCandidate& c : candidates) {
    stops.push_back(c.viewpoint);
    costs.from_robot.push_back(c.path_cost_m);
  }
  const int factor = std::max(1, static_cast<int>(std::lround(config_.tour_cell_m / resolution_m)));
  std::vector<GridIndex> ends = stops;
  ends.push_back(home);
  std::vector<std::vector<double>> distances = CoarseDistances(grid, stops, ends, factor, resolution_m);
  for (std::vector<double>& row : distances) {
    costs.to_end.push_back(row.back());
    row.pop_back();
  }
  costs.between = std::move(distances);
  const std::vector<double> lengths = TourLengthsByFirstStop(costs);
  const double shortest = *std::min_element(lengths.begin(), lengths.end());
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    candidates[i].tour_length_m = lengths[i];
    candidates[i].score = std::exp(-(lengths[i] - shortest) / config_.tour_scale_m);
  }
}

const char* TargetKindName(TargetKind kind) {
  switch (kind) {
    case TargetKind::kFrontier:
      return "frontier";
    case TargetKind::kInspection:
      return "inspection";
    case TargetKind::kReturnToStart:
      return "return-to-start";
    case TargetKind::kDone:
      return "done";
  }
  return "done";
}

TargetPlanner::TargetPlanner(TargetPlannerConfig config, double resolution_m)
    : config_(std::move(config)), blacklist_(config_.blacklist, resolution_m) {}

TargetDecision TargetPlanner::Plan(const GridMap& map, const TraversalGrid& grid, GridIndex robot,
                                   GridIndex home, const SurfaceCoverage* coverage,
                                   double now_s, const TraversalGrid* squeeze) const {
  TargetDecision decision;
  const double res = map.resolution_m;
  const int near_robot = static_cast<int>(std::ceil(0.5 / res));
  const std::vector<double> cost_to_go = CostToGo(grid, FreeCellNear(grid, robot, near_robot));
  // Costs to go on the squeeze grid, computed once a region needs them.
  std::vector<double> squeeze_cost_to_go;
  auto squeezed_costs = [&]() -> const std::vector<double>* {
    if (squeeze == nullptr) return nullptr;
    if (squeeze_cost_to_go.empty()) {
      squeeze_cost_to_go = CostToGo(*squeeze, FreeCellNear(*squeeze, robot, near_robot));
    }
    return &squeeze_cost_to_go;
  };
  // The same, but only to cells where the full radius stands free with room to spare
  // (the cells within kFreeStandingCells of them free too): a surface is looked at from a
  // room the robot squeezed into through its doorway, never from inside a squeeze (the
  // 0.75 m between a desk and a wall leaves the 0.72 m base no room to steer, a speckled
  // desk edge leaves single free cells in it, and looking at a surface is not worth
  // touching it).
  std::vector<double> free_standing_squeeze_costs;
  auto free_standing_squeezed_costs = [&]() -> const std::vector<double>& {
    if (free_standing_squeeze_costs.empty()) {
      cv::Mat free(grid.height, grid.width, CV_8UC1);
      for (int i = 0; i < static_cast<int>(grid.penalty.size()); ++i) {
        free.at<std::uint8_t>(i / grid.width, i % grid.width) = grid.Blocked(i) ? 0 : 255;
      }
      const int side = 2 * kFreeStandingCells + 1;
      cv::erode(free, free, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(side, side)),
                cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
      free_standing_squeeze_costs = *squeezed_costs();
      for (int i = 0; i < static_cast<int>(free_standing_squeeze_costs.size()); ++i) {
        if (free.at<std::uint8_t>(i / grid.width, i % grid.width) == 0) {
          free_standing_squeeze_costs[i] = kInfinity;
        }
      }
    }
    return free_standing_squeeze_costs;
  };
  const bool nearest = config_.strategy == "nearest-frontier";

  // Frontier pixels: navigable cells 4-adjacent to unknown (dilate unknown by a cross).
  cv::Mat unknown = MaskOf(map, CellState::kUnknown);
  cv::Mat frontier;
  cv::dilate(unknown, frontier, cv::getStructuringElement(cv::MORPH_CROSS, cv::Size(3, 3)));
  cv::bitwise_and(frontier, MaskOf(map, CellState::kNavigable), frontier);
  const int min_frontier =
      std::max(1, static_cast<int>(std::ceil(config_.min_frontier_length_m / res)));
  ViewCone cone;
  cone.range_m = config_.sensor_range_m;
  cone.min_range_m = config_.min_view_distance_m;
  for (const Region& region : Regions(map, frontier, min_frontier, &decision.frontier_regions)) {
    if (blacklist_.IsBlacklisted(region.center, now_s)) {
      ++decision.blacklisted_regions;
      decision.blacklisted_frontiers.push_back(region.center);
      continue;
    }
    // Far enough to see the unseen floor beyond the frontier; nearer only where there is
    // no such place (a narrow dead end).
    const double min_view = config_.min_view_distance_m / res;
    Excluded wanting{{}, kWantingRadiusM / res};
    Viewpoint vp;
    double gain = 0.0;
    auto search = [&](const std::vector<double>& costs) {
      for (int tries = 0; tries < kMaxViewpointTries; ++tries) {
        vp = FindViewpoint(map, costs, region.center, min_view,
                           min_view + config_.viewpoint_radius_m / res, wanting);
        if (!vp.found && min_view > 0.0) {
          vp = FindViewpoint(map, costs, region.center, 0.0, config_.viewpoint_radius_m / res,
                             wanting);
        }
        if (!vp.found) return;
        gain = UnknownSeen(map, vp.cell, cone);
        // A viewpoint that sees next to none of the unknown beyond it (the centre glimpsed
        // past a door jamb) would be driven to, looked from and blacklisted by the nearest
        // frontier, which weighs no gain, and would drop the region for gain and tour, which
        // do: the cheapest viewpoint that sees enough stands in for it.
        if (gain >= config_.min_gain_m2) return;
        wanting.cells.push_back(vp.cell);
        vp.found = false;
      }
    };
    search(cost_to_go);
    if (!vp.found && squeezed_costs() != nullptr) search(*squeezed_costs());
    bool approach = false;
    if (!vp.found) {
      // Seen from afar through a doorway: go as near as the known floor allows and look.
      // Standing there makes the threshold known floor (AssumeFloorAround), which opens
      // the room, so this viewpoint is worth reaching even when it sees little itself.
      vp = FindNearestViewpoint(map, cost_to_go, region.center, config_.sensor_range_m / res,
                                wanting);
      approach = vp.found;
      gain = vp.found ? UnknownSeen(map, vp.cell, cone) : 0.0;
    }
    if (!vp.found) {
      ++decision.unreachable_regions;
      decision.unreachable_frontiers.push_back(region.center);
      continue;
    }
    TargetCandidate c;
    c.kind = TargetKind::kFrontier;
    c.viewpoint = vp.cell;
    c.region_center = region.center;
    c.region_cells = static_cast<int>(region.cells.size());
    c.path_cost_m = vp.cost * res;
    c.gain = gain;
    c.score = nearest ? 1.0 / (c.path_cost_m + config_.path_cost_offset_m)
                      : c.gain / (c.path_cost_m + config_.path_cost_offset_m);
    if (c.gain >= config_.min_gain_m2 || (nearest && approach)) decision.candidates.push_back(c);
  }

  // Inspection: surfaces not yet seen from within the inspection distance.
  const bool frontier_left = !decision.candidates.empty();
  if (!nearest && config_.inspection && coverage != nullptr &&
      !(config_.frontiers_first && frontier_left)) {
    const double inspect_cells = coverage->config().inspection_distance_m / res;
    cv::Mat unseen(map.height, map.width, CV_8UC1, cv::Scalar(0));
    for (int i = 0; i < static_cast<int>(map.cells.size()); ++i) {
      const GridIndex c = map.Cell(i);
      if (SurfaceCoverage::IsSurface(map, c) && !coverage->InspectedNear(map, c)) {
        unseen.at<std::uint8_t>(c.y, c.x) = 255;
      }
    }
    int found = 0;
    const int min_cells = std::max(1, static_cast<int>(std::ceil(config_.min_inspection_m / res)));
    ViewCone near_cone;
    near_cone.range_m = coverage->config().inspection_distance_m;
    // 4 cm apart at 2.5 m, so every cell of a wall seen at a slant counts: with 90 rays
    // the count of a half-metre region jumped across min_inspection_m as the viewpoint
    // moved by a cell, and the robot turned back and forth between the region and home.
    near_cone.rays = 360;
    for (const Region& region : Regions(map, unseen, min_cells, &found)) {
      if (blacklist_.IsBlacklisted(region.center, now_s)) {
        ++decision.blacklisted_regions;
        continue;
      }
      // Well inside the inspection distance, so the surface counts once seen from there.
      // The cell looked at is the target's region centre, which failures blacklist: a
      // blacklisted one is passed over for the next (office seed 5 looked at a desk's
      // corner for 280 s, each look a failure, while only the centroid was checked).
      Viewpoint vp;
      GridIndex anchor = region.center;
      bool blacklisted = false;
      for (const GridIndex& a : SpreadCells(map, region, kInspectionAnchors)) {
        if (blacklist_.IsBlacklisted(a, now_s)) {
          blacklisted = true;
          continue;
        }
        vp = FindViewpoint(map, cost_to_go, a, 0.0, 0.8 * inspect_cells, Excluded{});
        if (!vp.found && squeezed_costs() != nullptr) {
          vp = FindViewpoint(map, free_standing_squeezed_costs(), a, 0.0, 0.8 * inspect_cells,
                             Excluded{});
        }
        anchor = a;
        if (vp.found) break;
      }
      if (!vp.found) {
        if (blacklisted) ++decision.blacklisted_regions;
        continue;
      }
      TargetCandidate c;
      c.kind = TargetKind::kInspection;
      c.viewpoint = vp.cell;
      c.region_center = anchor;
      c.region_cells = static_cast<int>(region.cells.size());
      c.path_cost_m = vp.cost * res;
      int surface_seen = 0;
      for (const int i : VisibleCells(map, vp.cell, near_cone)) {
        surface_seen += unseen.at<std::uint8_t>(i / map.width, i % map.width) != 0 ? 1 : 0;
      }
      c.gain = config_.inspection_weight * surface_seen * res;
      c.score = c.gain / (c.path_cost_m + config_.path_cost_offset_m);
      if (surface_seen * res >= config_.min_inspection_m) decision.candidates.push_back(c);
    }
  }

  if (config_.strategy == "tour") ScoreByTour(&decision, squeeze != nullptr ? *squeeze : grid, home, res);

  const auto best = std::max_element(
      decision.candidates.begin(), decision.candidates.end(),
      [](const TargetCandidate& a, const TargetCandidate& b) { return a.score < b.score; });
  if (best != decision.candidates.end()) {
    decision.kind = best->kind;
    decision.cell = best->viewpoint;
    decision.chosen = *best;
    return decision;
  }
  const double home_distance = std::hypot(robot.x - home.x, robot.y - home.y) * res;
  decision.kind =
      home_distance > config_.home_tolerance_m ? TargetKind::kReturnToStart : TargetKind::kDone;
  decision.cell = home;
  return decision;
}

}  // namespace dynamap::planning
