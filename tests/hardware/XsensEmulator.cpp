#include "XsensEmulator.hpp"

#include <chrono>
#include <cstring>

namespace dynamap::robotio::hardware::test {
namespace {

void PutBigEndian(std::vector<std::uint8_t>& out, std::uint64_t value, int bytes) {
  for (int i = bytes - 1; i >= 0; --i) out.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
}

}  // namespace

XsensEmulator::XsensEmulator(PtyPair& pty) : pty_(pty), thread_([this] { Run(); }) {}

XsensEmulator::~XsensEmulator() {
  quit_ = true;
  thread_.join();
}

std::vector<std::uint8_t> XsensEmulator::Message(std::uint8_t mid,
                                                 const std::vector<std::uint8_t>& data) {
  std::vector<std::uint8_t> m = {0xFA, 0xFF, mid};
  if (data.size() < 255) {
    m.push_back(static_cast<std::uint8_t>(data.size()));
  } else {
    m.push_back(0xFF);
    PutBigEndian(m, data.size(), 2);
  }
  m.insert(m.end(), data.begin(), data.end());
  unsigned sum = 0;
  for (std::size_t i = 1; i < m.size(); ++i) sum += m[i];
  m.push_back(static_cast<std::uint8_t>((0x100 - (sum & 0xFF)) & 0xFF));
  return m;
}

std::vector<std::uint8_t> XsensEmulator::MtData2(std::uint16_t counter,
                                                 const std::array<float, 3>& rate,
                                                 bool double_precision, bool fixed_point) {
  std::vector<std::uint8_t> d;
  PutBigEndian(d, 0x1020, 2);
  d.push_back(2);
  PutBigEndian(d, counter, 2);
  PutBigEndian(d, 0x1060, 2);
  d.push_back(4);
  PutBigEndian(d, std::uint64_t{counter} * 100U, 4);
  if (fixed_point) {
    PutBigEndian(d, 0x8021, 2);
    d.push_back(12);
    for (float r : rate) PutBigEndian(d, static_cast<std::uint32_t>(static_cast<std::int32_t>(r * 1048576.0F)), 4);
  } else if (double_precision) {
    PutBigEndian(d, 0x8023, 2);
    d.push_back(24);
    for (float r : rate) {
      const double value = r;
      std::uint64_t bits = 0;
      std::memcpy(&bits, &value, sizeof bits);
      PutBigEndian(d, bits, 8);
    }
  } else {
    PutBigEndian(d, 0x8020, 2);
    d.push_back(12);
    for (float r : rate) {
      std::uint32_t bits = 0;
      std::memcpy(&bits, &r, sizeof bits);
      PutBigEndian(d, bits, 4);
    }
  }
  return Message(0x36, d);
}

void XsensEmulator::SetRate(float x, float y, float z) {
  std::lock_guard<std::mutex> lock(mutex_);
  rate_ = {x, y, z};
}

void XsensEmulator::InjectRaw(const std::vector<std::uint8_t>& bytes) {
  std::lock_guard<std::mutex> lock(mutex_);
  injections_.push_back(bytes);
}

std::vector<std::uint8_t> XsensEmulator::ReceivedMids() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return mids_;
}

void XsensEmulator::Run() {
  auto next_sample = std::chrono::steady_clock::now();
  std::uint16_t counter = 0;
  while (!quit_) {
    const std::vector<std::uint8_t> bytes = pty_.Read(2);
    std::vector<std::vector<std::uint8_t>> injections;
    std::array<float, 3> rate{};
    bool ack = false;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      rx_.insert(rx_.end(), bytes.begin(), bytes.end());
      // Host messages here are all short-form: FA FF mid len data cs.
      while (rx_.size() >= 5) {
        if (rx_[0] != 0xFA) {
          rx_.erase(rx_.begin());
          continue;
        }
        const std::size_t total = 5 + rx_[3];
        if (rx_.size() < total) break;
        mids_.push_back(rx_[2]);
        ack = ack || rx_[2] == 0x10;
        rx_.erase(rx_.begin(), rx_.begin() + static_cast<std::ptrdiff_t>(total));
      }
      injections.swap(injections_);
      rate = rate_;
    }
    if (ack) pty_.Write(Message(0x11, {}));
    for (const auto& injection : injections) pty_.Write(injection);
    if (std::chrono::steady_clock::now() < next_sample) continue;
    next_sample += std::chrono::milliseconds(10);
    if (silent_) continue;
    counter = static_cast<std::uint16_t>(counter + 1 + skip_.exchange(0));
    pty_.Write(MtData2(counter, rate, double_precision_, fixed_point_));
    ++samples_sent_;
  }
}

}  // namespace dynamap::robotio::hardware::test
