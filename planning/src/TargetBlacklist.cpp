#include "dynamap/planning/TargetBlacklist.hpp"

#include <algorithm>
#include <cmath>

namespace dynamap::planning {

bool TargetBlacklist::Near(GridIndex a, GridIndex b) const {
  const double dx = a.x - b.x;
  const double dy = a.y - b.y;
  return dx * dx + dy * dy <= radius_cells_ * radius_cells_;
}

void TargetBlacklist::Ban(Entry& e, double now_s) const {
  const double duration =
      std::min(config_.max_duration_s, config_.duration_s * std::pow(2.0, e.times));
  e.until_s = now_s + duration;
  e.failures = 0;
  ++e.times;
}

void TargetBlacklist::ReportFailure(GridIndex cell, double now_s) {
  for (Entry& e : entries_) {
    if (!Near(e.cell, cell)) continue;
    if (++e.failures >= config_.max_failures) Ban(e, now_s);
    return;
  }
  entries_.push_back({cell, 1, -1.0, 0, false});
  if (config_.max_failures <= 1) Ban(entries_.back(), now_s);
}

void TargetBlacklist::Blacklist(GridIndex cell, double now_s) {
  for (Entry& e : entries_) {
    if (Near(e.cell, cell)) {
      if (now_s >= e.until_s) Ban(e, now_s);  // Already banned: the ban stands as it is.
      return;
    }
  }
  entries_.push_back({cell, 0, -1.0, 0, false});
  Ban(entries_.back(), now_s);
}

bool TargetBlacklist::IsBlacklisted(GridIndex cell, double now_s) const {
  for (const Entry& e : entries_) {
    if (now_s < e.until_s && Near(e.cell, cell)) return true;
  }
  return false;
}

int TargetBlacklist::LiftBansForALastTry(double now_s) {
  int lifted = 0;
  for (Entry& e : entries_) {
    if (now_s >= e.until_s || e.let_off) continue;
    e.until_s = now_s;
    e.failures = 0;
    e.let_off = true;
    ++lifted;
  }
  return lifted;
}

int TargetBlacklist::ActiveCount(double now_s) const {
  int n = 0;
  for (const Entry& e : entries_) n += now_s < e.until_s ? 1 : 0;
  return n;
}

}  // namespace dynamap::planning
