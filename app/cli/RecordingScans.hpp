// A recording's depth frames in capture order, grouped into scans of one instant (both
// Kinects of the rig, which are unsynchronised and up to a frame apart).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "dynamap/robotio/RecordingReader.hpp"
#include "dynamap/robotio/Rig.hpp"

namespace dynamap::app {

struct RecordingScans {
  // Indices into reader.depth_entries() sorted by capture stamp (receive stamp minus the
  // sensor's latency); entries of sensors the rig does not have are left out.
  std::vector<std::size_t> order;
  std::vector<std::int64_t> capture_ns;         // Per position in `order`.
  std::vector<std::vector<std::size_t>> scans;  // Positions in `order`, one group per instant.
};

[[nodiscard]] RecordingScans GroupRecordingIntoScans(const robotio::RecordingReader& reader,
                                                     const robotio::Rig& rig);

}  // namespace dynamap::app
