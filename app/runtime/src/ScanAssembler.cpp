#include "dynamap/app/runtime/ScanAssembler.hpp"

#include <algorithm>
#include <utility>

#include "dynamap/mapping/SlamLoop.hpp"

namespace dynamap::app::runtime {

std::vector<std::vector<CapturedFrame>> ScanAssembler::Add(std::vector<CapturedFrame> frames) {
  for (CapturedFrame& f : frames) held_.push_back(std::move(f));
  std::sort(held_.begin(), held_.end(),
            [](const auto& a, const auto& b) { return a.depth.stamp_ns < b.depth.stamp_ns; });
  std::vector<std::int64_t> stamps;
  std::vector<int> ids;
  for (const CapturedFrame& f : held_) {
    stamps.push_back(f.depth.stamp_ns);
    ids.push_back(f.depth.sensor_id);
  }
  const auto groups = mapping::GroupIntoScans(stamps, ids, max_span_ns_);
  std::vector<std::vector<CapturedFrame>> scans;
  std::vector<CapturedFrame> still_held;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const bool last = g + 1 == groups.size();
    const bool complete = static_cast<int>(groups[g].size()) >= sensors_;
    std::vector<CapturedFrame> scan;
    for (const std::size_t i : groups[g]) scan.push_back(std::move(held_[i]));
    if (last && !complete) {
      still_held = std::move(scan);
    } else {
      scans.push_back(std::move(scan));
    }
  }
  held_ = std::move(still_held);
  return scans;
}

}  // namespace dynamap::app::runtime
