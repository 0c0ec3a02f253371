#include "dynamap/planning/TargetBlacklist.hpp"

namespace dynamap::planning {

bool TargetBlacklist::Near(GridIndex a, GridIndex b) const {
  const double dx = a.x - b.x;
  const double dy = a.y - b.y;
  return dx * dx + dy * dy <= radius_cells_ * radius_cells_;
}

void TargetBlacklist::ReportFailure(GridIndex cell, double now_s) {
  for (Entry& e : entries_) {
    if (!Near(e.cell, cell)) continue;
    if (++e.failures >= config_.max_failures) {
      e.until_s = now_s + config_.duration_s;
      e.failures = 0;
    }
    return;
  }
  entries_.push_back({cell, 1, -1.0});
  if (config_.max_failures <= 1) Blacklist(cell, now_s);
}

void TargetBlacklist::Blacklist(GridIndex cell, double now_s) {
  for (Entry& e : entries_) {
    if (Near(e.cell, cell)) {
      e.until_s = now_s + config_.duration_s;
      e.failures = 0;
      return;
    }
  }
  entries_.push_back({cell, 0, now_s + config_.duration_s});
}

bool TargetBlacklist::IsBlacklisted(GridIndex cell, double now_s) const {
  for (const Entry& e : entries_) {
    if (now_s < e.until_s && Near(e.cell, cell)) return true;
  }
  return false;
}

int TargetBlacklist::ActiveCount(double now_s) const {
  int n = 0;
  for (const Entry& e : entries_) n += now_s < e.until_s ? 1 : 0;
  return n;
}

}  // namespace dynamap::planning
