// A raw byte link to a serial device (USB-serial adapter or pseudo-terminal) with bounded
// waits, shared by the Segway RMP and the gyro drivers: no call blocks longer than asked.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "dynamap/robotio/Expected.hpp"

namespace dynamap::robotio::hardware {

class SerialPort {
 public:
  // Opens `path` in raw 8N1 mode at `baud` (one of the standard termios rates); the
  // Error names the path and the reason (missing device, permissions, unsupported rate).
  [[nodiscard]] static Expected<SerialPort> Open(const std::string& path, int baud);

  SerialPort(SerialPort&& other) noexcept;
  SerialPort& operator=(SerialPort&& other) noexcept;
  SerialPort(const SerialPort&) = delete;
  SerialPort& operator=(const SerialPort&) = delete;
  ~SerialPort();

  // Bytes that arrived within `timeout` (empty when none did). An Error means the link is
  // gone: device unplugged, hang-up or I/O error.
  [[nodiscard]] Expected<std::vector<std::uint8_t>> Read(std::chrono::milliseconds timeout);
  // Writes all of `bytes`, waiting at most `timeout` for the device to accept them.
  [[nodiscard]] Status Write(const std::vector<std::uint8_t>& bytes,
                             std::chrono::milliseconds timeout);

  [[nodiscard]] const std::string& path() const { return path_; }

 private:
  SerialPort(int fd, std::string path) : fd_(fd), path_(std::move(path)) {}
  void Close();

  int fd_ = -1;
  std::string path_;
};

}  // namespace dynamap::robotio::hardware
