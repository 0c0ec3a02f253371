#include "RmpEmulator.hpp"

#include <chrono>

namespace dynamap::robotio::hardware::test {
namespace {

// Sum of bytes 0..16 folded into 8 bits; a valid frame's byte 17 brings it to 0 mod 256.
std::uint8_t FoldedSum(const std::vector<std::uint8_t>& f) {
  unsigned sum = 0;
  for (int i = 0; i < 17; ++i) sum += f[static_cast<std::size_t>(i)];
  sum = (sum & 0xFF) + (sum >> 8);
  sum = (sum & 0xFF) + (sum >> 8);
  return static_cast<std::uint8_t>(sum);
}

void PutWord(std::uint8_t (&data)[8], int at, std::uint16_t word) {
  data[at] = static_cast<std::uint8_t>(word >> 8);
  data[at + 1] = static_cast<std::uint8_t>(word & 0xFF);
}

}  // namespace

RmpEmulator::RmpEmulator(PtyPair& pty) : pty_(pty), thread_([this] { Run(); }) {}

RmpEmulator::~RmpEmulator() {
  quit_ = true;
  thread_.join();
}

std::vector<std::uint8_t> RmpEmulator::StatusFrame(std::uint16_t id, const std::uint8_t (&data)[8],
                                                   bool corrupt) {
  std::vector<std::uint8_t> f(18, 0);
  f[0] = 0xF0;
  f[1] = 0x55;
  f[2] = 0xAA;  // Channel A.
  f[4] = static_cast<std::uint8_t>(id >> 3);
  f[5] = static_cast<std::uint8_t>((id & 0x7) << 5);
  for (int i = 0; i < 8; ++i) f[static_cast<std::size_t>(9 + i)] = data[i];
  f[17] = static_cast<std::uint8_t>(0x100 - FoldedSum(f));
  if (corrupt) f[17] = static_cast<std::uint8_t>(f[17] ^ 0x5A);
  return f;
}

std::vector<std::uint8_t> RmpEmulator::WheelFrame(std::int32_t left, std::int32_t right,
                                                  bool corrupt) {
  std::uint8_t data[8] = {};
  const auto l = static_cast<std::uint32_t>(left);
  const auto r = static_cast<std::uint32_t>(right);
  // Low word first, each word big-endian.
  PutWord(data, 0, static_cast<std::uint16_t>(l & 0xFFFF));
  PutWord(data, 2, static_cast<std::uint16_t>(l >> 16));
  PutWord(data, 4, static_cast<std::uint16_t>(r & 0xFFFF));
  PutWord(data, 6, static_cast<std::uint16_t>(r >> 16));
  return StatusFrame(0x0403, data, corrupt);
}

void RmpEmulator::SetWheelCounts(std::int32_t left, std::int32_t right) {
  std::lock_guard<std::mutex> lock(mutex_);
  left_ = left;
  right_ = right;
}

void RmpEmulator::InjectRaw(const std::vector<std::uint8_t>& bytes) {
  std::lock_guard<std::mutex> lock(mutex_);
  injections_.push_back(bytes);
}

void RmpEmulator::InjectCorruptWheelFrame(std::int32_t left, std::int32_t right) {
  InjectRaw(WheelFrame(left, right, true));
}

void RmpEmulator::InjectTruncatedWheelFrame(std::int32_t left, std::int32_t right,
                                            std::size_t keep) {
  std::vector<std::uint8_t> frame = WheelFrame(left, right);
  frame.resize(keep);
  InjectRaw(frame);
}

void RmpEmulator::Unplug() { pty_.CloseMaster(); }

std::vector<ReceivedCommand> RmpEmulator::Commands() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return commands_;
}

void RmpEmulator::Send(const std::vector<std::uint8_t>& bytes) {
  if (!split_) {
    pty_.Write(bytes);
    return;
  }
  for (std::uint8_t byte : bytes) pty_.Write({byte});
}

void RmpEmulator::ParseCommands(const std::vector<std::uint8_t>& bytes) {
  rx_.insert(rx_.end(), bytes.begin(), bytes.end());
  while (rx_.size() >= 18) {
    if (rx_[0] != 0xF0 || rx_[1] != 0x55) {
      rx_.erase(rx_.begin());
      continue;
    }
    std::vector<std::uint8_t> f(rx_.begin(), rx_.begin() + 18);
    rx_.erase(rx_.begin(), rx_.begin() + 18);
    if (static_cast<std::uint8_t>(FoldedSum(f) + f[17]) != 0) {
      ++bad_command_frames_;
      continue;
    }
    const unsigned id = static_cast<unsigned>(f[6] << 8 | f[7]);
    if (id != 0x0413) continue;
    ReceivedCommand command;
    command.velocity_counts = static_cast<std::int16_t>(f[9] << 8 | f[10]);
    command.turn_counts = static_cast<std::int16_t>(f[11] << 8 | f[12]);
    commands_.push_back(command);
  }
}

void RmpEmulator::Run() {
  auto next_status = std::chrono::steady_clock::now();
  std::uint16_t frames = 0;
  while (!quit_) {
    const std::vector<std::uint8_t> bytes = pty_.Read(2);
    std::vector<std::vector<std::uint8_t>> injections;
    std::int32_t left = 0;
    std::int32_t right = 0;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!bytes.empty()) ParseCommands(bytes);
      injections.swap(injections_);
      left = left_;
      right = right_;
    }
    for (const auto& injection : injections) pty_.Write(injection);
    if (std::chrono::steady_clock::now() < next_status) continue;
    next_status += std::chrono::milliseconds(10);
    if (silent_) continue;
    ++frames;
    std::uint8_t velocities[8] = {};
    PutWord(velocities, 6, frames);
    std::uint8_t mode[8] = {};
    PutWord(mode, 0, 1);             // Tractor mode.
    PutWord(mode, 6, 72 * 4);        // 72 V powerbase battery.
    Send(StatusFrame(0x0402, velocities));
    Send(WheelFrame(left, right));
    Send(StatusFrame(0x0406, mode));
    ++status_cycles_;
  }
}

}  // namespace dynamap::robotio::hardware::test
