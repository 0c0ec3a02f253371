// A Segway RMP on the far end of a pseudo-terminal, written from the protocol description
// (docs/HARDWARE.md) independently of the driver's encoder: it answers with 100 Hz status
// frames, records the motion commands it receives, and can misbehave on request (noise,
// bad checksums, split or truncated frames, silence, unplugging).
#pragma once

#include <atomic>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

#include "PtyPair.hpp"

namespace dynamap::robotio::hardware::test {

struct ReceivedCommand {
  int velocity_counts = 0;
  int turn_counts = 0;
};

class RmpEmulator {
 public:
  explicit RmpEmulator(PtyPair& pty);
  ~RmpEmulator();

  void SetWheelCounts(std::int32_t left, std::int32_t right);
  // Misbehaviour switches, applied from the next status cycle on.
  void SetSilent(bool silent) { silent_ = silent; }
  void SetSplitIntoSingleBytes(bool split) { split_ = split; }
  // Sends raw bytes between two status cycles.
  void InjectRaw(const std::vector<std::uint8_t>& bytes);
  // A wheel-count frame with the given counts and a wrong checksum.
  void InjectCorruptWheelFrame(std::int32_t left, std::int32_t right);
  // The first `keep` bytes of a wheel-count frame, then nothing more of it.
  void InjectTruncatedWheelFrame(std::int32_t left, std::int32_t right, std::size_t keep);
  void Unplug();

  [[nodiscard]] std::vector<ReceivedCommand> Commands() const;
  [[nodiscard]] int bad_command_frames() const { return bad_command_frames_; }
  [[nodiscard]] std::uint64_t status_cycles() const { return status_cycles_; }

  static std::vector<std::uint8_t> StatusFrame(std::uint16_t id, const std::uint8_t (&data)[8],
                                               bool corrupt = false);
  static std::vector<std::uint8_t> WheelFrame(std::int32_t left, std::int32_t right,
                                              bool corrupt = false);

 private:
  void Run();
  void ParseCommands(const std::vector<std::uint8_t>& bytes);
  void Send(const std::vector<std::uint8_t>& bytes);

  PtyPair& pty_;
  mutable std::mutex mutex_;
  std::int32_t left_ = 0;
  std::int32_t right_ = 0;
  std::vector<std::uint8_t> rx_;
  std::vector<ReceivedCommand> commands_;
  std::vector<std::vector<std::uint8_t>> injections_;
  std::atomic<int> bad_command_frames_{0};
  std::atomic<std::uint64_t> status_cycles_{0};
  std::atomic<bool> silent_{false};
  std::atomic<bool> split_{false};
  std::atomic<bool> quit_{false};
  std::thread thread_;
};

}  // namespace dynamap::robotio::hardware::test
