#include "cli/RecordingScans.hpp"

#include <algorithm>

#include "dynamap/mapping/SlamLoop.hpp"
#include "dynamap/robotio/Time.hpp"

namespace dynamap::app {

RecordingScans GroupRecordingIntoScans(const robotio::RecordingReader& reader,
                                       const robotio::Rig& rig) {
  const auto& entries = reader.depth_entries();
  std::vector<std::int64_t> capture_ns(entries.size(), 0);
  RecordingScans result;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const auto sensor = static_cast<std::size_t>(entries[i].sensor_id);
    if (entries[i].sensor_id < 0 || sensor >= rig.kinects.size()) continue;
    capture_ns[i] =
        entries[i].received_ns - robotio::SecondsToNanos(rig.kinects[sensor].latency_s);
    result.order.push_back(i);
  }
  std::stable_sort(result.order.begin(), result.order.end(),
                   [&](std::size_t a, std::size_t b) { return capture_ns[a] < capture_ns[b]; });
  std::vector<int> sensors;
  for (std::size_t i : result.order) {
    result.capture_ns.push_back(capture_ns[i]);
    sensors.push_back(entries[i].sensor_id);
  }
  double period_s = 1.0 / 30.0;
  for (const auto& mount : rig.kinects) period_s = std::max(period_s, 1.0 / mount.rate_hz);
  result.scans = mapping::GroupIntoScans(result.capture_ns, sensors,
                                         robotio::SecondsToNanos(period_s * 0.75));
  return result;
}

}  // namespace dynamap::app
