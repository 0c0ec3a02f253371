// An Xsens MTi on the far end of a pseudo-terminal, framing its messages from the protocol
// description independently of the driver's encoder: 100 Hz MTData2 with packet counter,
// fine sample time and rate of turn, and misbehaviour on request.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

#include "PtyPair.hpp"

namespace dynamap::robotio::hardware::test {

class XsensEmulator {
 public:
  explicit XsensEmulator(PtyPair& pty);
  ~XsensEmulator();

  void SetRate(float x, float y, float z);
  void SetSilent(bool silent) { silent_ = silent; }
  // Rate of turn as 64-bit floats instead of 32-bit ones.
  void SetDoublePrecision(bool on) { double_precision_ = on; }
  // Rate of turn in the fixed-point 12.20 format, which the driver refuses.
  void SetFixedPoint(bool on) { fixed_point_ = on; }
  // Skips this many packet counter values once (samples lost on the device side).
  void SkipCounter(int n) { skip_ += n; }
  void InjectRaw(const std::vector<std::uint8_t>& bytes);
  void Unplug() { pty_.CloseMaster(); }

  [[nodiscard]] std::vector<std::uint8_t> ReceivedMids() const;
  [[nodiscard]] std::uint64_t samples_sent() const { return samples_sent_; }

  // A whole message: FA FF mid len [ext] data checksum.
  static std::vector<std::uint8_t> Message(std::uint8_t mid, const std::vector<std::uint8_t>& data);
  static std::vector<std::uint8_t> MtData2(std::uint16_t counter, const std::array<float, 3>& rate,
                                           bool double_precision = false,
                                           bool fixed_point = false);

 private:
  void Run();

  PtyPair& pty_;
  mutable std::mutex mutex_;
  std::array<float, 3> rate_{};
  std::vector<std::uint8_t> rx_;
  std::vector<std::uint8_t> mids_;
  std::vector<std::vector<std::uint8_t>> injections_;
  std::atomic<bool> silent_{false};
  std::atomic<bool> double_precision_{false};
  std::atomic<bool> fixed_point_{false};
  std::atomic<int> skip_{0};
  std::atomic<std::uint64_t> samples_sent_{0};
  std::atomic<bool> quit_{false};
  std::thread thread_;
};

}  // namespace dynamap::robotio::hardware::test
