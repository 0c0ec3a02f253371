#include "dynamap/calibration/CaptureReplay.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dynamap::calibration {

CaptureReplay::CaptureReplay(const robotio::RecordingReader& reader) : reader_(reader) {}

bool CaptureReplay::done() const {
  return next_odometry_ >= reader_.odometry().size() && next_imu_ >= reader_.imu().size() &&
         next_depth_ >= reader_.depth_entries().size();
}

double CaptureReplay::fraction() const {
  const std::size_t total = reader_.depth_entries().size();
  return total == 0 ? (done() ? 1.0 : 0.0)
                    : static_cast<double>(next_depth_) / static_cast<double>(total);
}

robotio::Status CaptureReplay::FeedUntil(CalibrationSession& session, std::int64_t until_ns,
                                         std::vector<robotio::DepthFrame>* newest_depth) {
  constexpr std::int64_t kNever = std::numeric_limits<std::int64_t>::max();
  const auto& odometry = reader_.odometry();
  const auto& imu = reader_.imu();
  const auto& depth = reader_.depth_entries();
  for (;;) {
    const std::int64_t to = next_odometry_ < odometry.size() ? odometry[next_odometry_].stamp_ns : kNever;
    const std::int64_t ti = next_imu_ < imu.size() ? imu[next_imu_].stamp_ns : kNever;
    const std::int64_t td = next_depth_ < depth.size() ? depth[next_depth_].received_ns : kNever;
    const std::int64_t next = std::min({to, ti, td});
    if (next == kNever || next > until_ns) return robotio::Ok{};
    if (to == next) {
      const std::size_t i = next_odometry_++;
      // The floor step lasts while the robot stands still at the start of the recording.
      if (session.step() == SessionStep::kFloor && i > 0 &&
          std::abs(odometry[i].left_m - odometry[i - 1].left_m) +
                  std::abs(odometry[i].right_m - odometry[i - 1].right_m) > 1e-3) {
        session.Skip();
      }
      session.AddOdometry(odometry[i]);
    } else if (ti == next) {
      session.AddImu(imu[next_imu_++]);
    } else {
      auto frame = reader_.LoadDepth(depth[next_depth_++]);
      if (!frame) return frame.error();
      session.AddDepth(*frame);
      if (newest_depth != nullptr) {
        const auto sensor = static_cast<std::size_t>(frame->sensor_id);
        if (sensor >= newest_depth->size()) newest_depth->resize(sensor + 1);
        (*newest_depth)[sensor] = std::move(*frame);
      }
    }
  }
}

}  // namespace dynamap::calibration
