#include "dynamap/robotio/hardware/SerialPort.hpp"

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <optional>
#include <utility>

namespace dynamap::robotio::hardware {
namespace {

std::optional<speed_t> BaudConstant(int baud) {
  switch (baud) {
    case 9600: return B9600;
    case 19200: return B19200;
    case 38400: return B38400;
    case 57600: return B57600;
    case 115200: return B115200;
    case 230400: return B230400;
    case 460800: return B460800;
    case 921600: return B921600;
    default: return std::nullopt;
  }
}

std::string Errno() { return std::strerror(errno); }

}  // namespace

Expected<SerialPort> SerialPort::Open(const std::string& path, int baud) {
  const std::optional<speed_t> speed = BaudConstant(baud);
  if (!speed) {
    return Error{"serial port " + path + ": unsupported baud rate " + std::to_string(baud) +
                 " (expected 9600, 19200, 38400, 57600, 115200, 230400, 460800 or 921600)"};
  }
  const int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    const std::string reason = Errno();
    std::string hint;
    if (errno == ENOENT) hint = " (is the device plugged in? see docs/HARDWARE.md, udev rules)";
    if (errno == EACCES) hint = " (add the user to the 'dialout' group, docs/HARDWARE.md)";
    return Error{"serial port " + path + ": cannot open: " + reason + hint};
  }
  SerialPort port(fd, path);
  termios tio{};
  if (::tcgetattr(fd, &tio) != 0) {
    return Error{"serial port " + path + ": not a terminal device: " + Errno()};
  }
  ::cfmakeraw(&tio);
  tio.c_cflag |= CLOCAL | CREAD;
  tio.c_cflag &= ~static_cast<tcflag_t>(CSTOPB | CRTSCTS);
  tio.c_cc[VMIN] = 0;
  tio.c_cc[VTIME] = 0;
  ::cfsetispeed(&tio, *speed);
  ::cfsetospeed(&tio, *speed);
  if (::tcsetattr(fd, TCSANOW, &tio) != 0) {
    return Error{"serial port " + path + ": cannot configure raw " + std::to_string(baud) +
                 " baud: " + Errno()};
  }
  ::tcflush(fd, TCIOFLUSH);
  return port;
}

SerialPort::SerialPort(SerialPort&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)), path_(std::move(other.path_)) {}

SerialPort& SerialPort::operator=(SerialPort&& other) noexcept {
  if (this != &other) {
    Close();
    fd_ = std::exchange(other.fd_, -1);
    path_ = std::move(other.path_);
  }
  return *this;
}

SerialPort::~SerialPort() { Close(); }

void SerialPort::Close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

Expected<std::vector<std::uint8_t>> SerialPort::Read(std::chrono::milliseconds timeout) {
  pollfd pfd{fd_, POLLIN, 0};
  const int ready = ::poll(&pfd, 1, static_cast<int>(timeout.count()));
  if (ready < 0) {
    if (errno == EINTR) return std::vector<std::uint8_t>{};
    return Error{"serial port " + path_ + ": poll failed: " + Errno()};
  }
  if (ready == 0) return std::vector<std::uint8_t>{};
  if ((pfd.revents & POLLIN) == 0) {
    // Hang-up or error without data: the device went away (USB unplug, pty closed).
    return Error{"serial port " + path_ + ": link lost (device unplugged or closed)"};
  }
  std::vector<std::uint8_t> bytes(4096);
  const ssize_t n = ::read(fd_, bytes.data(), bytes.size());
  if (n > 0) {
    bytes.resize(static_cast<std::size_t>(n));
    return bytes;
  }
  if (n < 0 && (errno == EAGAIN || errno == EINTR)) return std::vector<std::uint8_t>{};
  const std::string reason = n == 0 ? std::string("end of stream") : Errno();
  return Error{"serial port " + path_ + ": link lost (" + reason + ")"};
}

Status SerialPort::Write(const std::vector<std::uint8_t>& bytes,
                         std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd_, bytes.data() + written, bytes.size() - written);
    if (n > 0) {
      written += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno != EAGAIN && errno != EINTR) {
      return Error{"serial port " + path_ + ": write failed: " + Errno()};
    }
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      return Error{"serial port " + path_ + ": write timed out after " +
                   std::to_string(timeout.count()) + " ms (device not reading)"};
    }
    pollfd pfd{fd_, POLLOUT, 0};
    if (::poll(&pfd, 1, static_cast<int>(left.count())) > 0 &&
        (pfd.revents & (POLLERR | POLLHUP | POLLNVAL)) != 0) {
      return Error{"serial port " + path_ + ": link lost while writing"};
    }
  }
  return Ok{};
}

}  // namespace dynamap::robotio::hardware
