#include "dynamap/robotio/hardware/XsensImu.hpp"

#include <Eigen/Geometry>
#include <cmath>

#include "dynamap/robotio/hardware/MonotonicClock.hpp"

namespace dynamap::robotio::hardware {
namespace {

constexpr std::chrono::milliseconds kPollInterval{20};

Eigen::Matrix3d RotationFromRpyDeg(const Eigen::Vector3d& rpy_deg) {
  const Eigen::Vector3d rpy = rpy_deg * M_PI / 180.0;
  return (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

}  // namespace

Expected<std::unique_ptr<XsensImu>> XsensImu::Open(const XsensImuConfig& config) {
  Expected<SerialPort> port = SerialPort::Open(config.device, config.baud);
  if (!port) return Error{"Xsens IMU: " + port.error().message};
  // A device left in config mode by another program sends nothing until told to measure.
  const std::vector<std::uint8_t> go = EncodeXsensMessage({kXsensGoToMeasurement, {}});
  const Status sent = port->Write(go, std::chrono::milliseconds(100));
  if (!sent) return Error{"Xsens IMU: " + sent.error().message};
  std::unique_ptr<XsensImu> imu(new XsensImu(config, std::move(port).value()));
  imu->thread_ = std::thread([raw = imu.get()] { raw->Run(); });
  return imu;
}

XsensImu::XsensImu(const XsensImuConfig& config, SerialPort port)
    : config_(config),
      port_(std::move(port)),
      R_base_imu_(RotationFromRpyDeg(config.mount_rpy_deg)),
      last_sample_ns_(MonotonicNanos()) {}

XsensImu::~XsensImu() {
  quit_ = true;
  if (thread_.joinable()) thread_.join();
}

Expected<std::vector<ImuReading>> XsensImu::ReadImu() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (pending_.empty() && fault_) return *fault_;
  std::vector<ImuReading> readings;
  readings.swap(pending_);
  return readings;
}

XsensLinkStats XsensImu::Stats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  XsensLinkStats stats = stats_;
  stats.messages = parser_.counters().messages;
  stats.checksum_errors = parser_.counters().checksum_errors;
  stats.skipped_bytes = parser_.counters().skipped_bytes;
  return stats;
}

void XsensImu::SetFault(const std::string& message) {
  if (!fault_) fault_ = Error{"Xsens IMU on " + config_.device + ": " + message};
}

void XsensImu::Handle(const XsensMessage& message, std::int64_t now_ns) {
  // Caller holds mutex_.
  if (message.mid == kXsensError) {
    ++stats_.device_errors;
    return;
  }
  if (message.mid != kXsensMtData2) return;
  const XsensDecodeResult decoded = DecodeXsensMtData2(message.data);
  if (decoded.problem) {
    SetFault(*decoded.problem);
    return;
  }
  const XsensSample& sample = decoded.sample;
  if (!sample.rate_of_turn) return;
  if (sample.packet_counter && last_counter_) {
    const auto gap = static_cast<std::uint16_t>(*sample.packet_counter - *last_counter_ - 1);
    stats_.lost_samples += gap;
  }
  if (sample.packet_counter) last_counter_ = sample.packet_counter;
  const Eigen::Vector3d w_imu((*sample.rate_of_turn)[0], (*sample.rate_of_turn)[1],
                              (*sample.rate_of_turn)[2]);
  const Eigen::Vector3d w_base = R_base_imu_ * w_imu;
  pending_.push_back(ImuReading{now_ns, w_base.x(), w_base.y(), w_base.z()});
  ++stats_.samples;
  last_sample_ns_ = now_ns;
}

void XsensImu::Run() {
  const std::int64_t silence_ns = std::int64_t{config_.silence_timeout_ms} * 1'000'000;
  while (!quit_) {
    Expected<std::vector<std::uint8_t>> bytes = port_.Read(kPollInterval);
    const std::int64_t now = MonotonicNanos();
    std::lock_guard<std::mutex> lock(mutex_);
    if (!bytes) {
      SetFault(bytes.error().message);
      return;
    }
    for (const XsensMessage& message : parser_.Feed(*bytes)) Handle(message, now);
    if (now - last_sample_ns_ > silence_ns) {
      SetFault("no rate-of-turn sample for " + std::to_string(config_.silence_timeout_ms) +
               " ms (device unplugged, or not configured for MTData2 output?)");
    }
    if (fault_) return;
  }
}

}  // namespace dynamap::robotio::hardware
