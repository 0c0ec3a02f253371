// Heading from walls that meet at right angles. Indoors most vertical structure runs
// along two perpendicular directions, the building's axes. Registration against the map
// holds the heading the map was built with, so its error stays for minutes; the walls in
// one scan say the heading modulo 90° afresh, independent of the map. The axes are learnt
// from the first scans (while odometry and the first registrations are still good) and
// from then on each scan with enough wall near the expected direction measures the
// heading. Structure off the axes (a room built at an angle, a door leaf ajar, a person)
// falls outside the gate and is ignored; a building without right angles gives no
// measurement.
#pragma once

#include <optional>
#include <vector>

#include "dynamap/robotio/ConfigReader.hpp"
#include "dynamap/robotio/DepthProjection.hpp"

namespace dynamap::mapping {

struct WallHeadingConfig {
  // On by default: in the office missions the walls held the heading SLAM otherwise lost
  // in turns (docs/RESULTS.md); a building without right angles gives no measurement and
  // SLAM runs as with them off.
  bool enabled = true;
  // One scan's heading noise, rad, for the fusion's Kalman update.
  double sigma_rad = 0.005;
  // A line found in the scan counts when it lies within this of the expected axis, rad.
  double gate_rad = 0.035;
  // Square cells (x/y, base frame) in which line pieces are fitted, m; each fit takes
  // the points of a cell and its eight neighbours.
  double cell_m = 0.1;
  // Base-frame height band of the points used, m: above the floor, below the ceiling.
  double min_height_m = 0.3;
  double max_height_m = 2.0;
  // A cell's neighbourhood is a line piece when the spread across it is at most this
  // share of the spread along it (standard deviations).
  double max_thickness_ratio = 0.15;
  // A scan measures when this many line pieces, and this share of all, lie on the axes.
  int min_aligned_cells = 20;
  double min_aligned_share = 0.3;
  // Scans with walls whose directions fix the building's axes before any measurement.
  int learn_scans = 60;
  // A scan's heading counts as measured (loop closure holds it) when the walls measured
  // within this long before it, s. On the office tour the walls measured 90 % of the
  // scans; the longest gap was 12.6 s.
  double holds_heading_s = 10.0;
};

// Reads a "wall_heading:" mapping; unknown keys are errors naming the file.
[[nodiscard]] WallHeadingConfig ParseWallHeadingConfig(robotio::ConfigNode& node);

// A straight piece of vertical structure in a scan: its direction modulo 90°, in
// [-45°, 45°) as radians, in the frame of the points.
struct LinePiece {
  double angle_rad = 0.0;
};

// The straight pieces of the points (base frame) within the height band, one per cell.
[[nodiscard]] std::vector<LinePiece> LinePieces(const robotio::PointList& points,
                                                const WallHeadingConfig& config);

// The mean direction (modulo 90°) of the pieces within `gate_rad` of `around`, the gate
// recentred on the mean three times; nullopt when fewer than the config's count or share lie there.
[[nodiscard]] std::optional<double> AlignedDirection(const std::vector<LinePiece>& pieces,
                                                     double around,
                                                     const WallHeadingConfig& config);

// The dominant direction (modulo 90°) of the pieces, with no expectation.
[[nodiscard]] std::optional<double> DominantDirection(const std::vector<LinePiece>& pieces,
                                                      const WallHeadingConfig& config);

// `angle` wrapped to [-45°, 45°).
[[nodiscard]] double WrapQuarter(double angle);

class WallHeading {
 public:
  explicit WallHeading(WallHeadingConfig config) : config_(config) {}

  // The heading (map frame) the walls of one scan say, given the current estimate;
  // nullopt while the axes are being learnt or when the scan shows too little wall on
  // them. `points` in the base frame.
  std::optional<double> Measure(const robotio::PointList& points, double estimated_heading);

  [[nodiscard]] bool axes_known() const { return learnt_ >= config_.learn_scans; }
  // The building's axis direction in the map frame, modulo 90°.
  [[nodiscard]] double axes_rad() const;
  [[nodiscard]] const WallHeadingConfig& config() const { return config_; }

 private:
  WallHeadingConfig config_;
  int learnt_ = 0;
  double sum_cos_ = 0.0;  // Of four times each learnt axis direction (period 90°).
  double sum_sin_ = 0.0;
};

}  // namespace dynamap::mapping
