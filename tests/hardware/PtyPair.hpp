// A pseudo-terminal for driver tests: the driver opens the slave path like a USB-serial
// device while a protocol emulator owns the master end, so every byte really crosses
// the kernel's tty layer. Closing the master is how a test unplugs the device.
#pragma once

#include <fcntl.h>
#include <poll.h>
#include <stdlib.h>
#include <termios.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace dynamap::robotio::hardware::test {

class PtyPair {
 public:
  PtyPair() {
    master_ = ::posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (master_ < 0 || ::grantpt(master_) != 0 || ::unlockpt(master_) != 0) {
      throw std::runtime_error("posix_openpt failed");
    }
    slave_path_ = ::ptsname(master_);
    termios tio{};
    ::tcgetattr(master_, &tio);
    ::cfmakeraw(&tio);
    ::tcsetattr(master_, TCSANOW, &tio);
  }
  ~PtyPair() { CloseMaster(); }
  PtyPair(const PtyPair&) = delete;
  PtyPair& operator=(const PtyPair&) = delete;

  [[nodiscard]] const std::string& slave_path() const { return slave_path_; }

  // Writes all bytes to the master end (what the device "sends"); false once unplugged.
  bool Write(const std::vector<std::uint8_t>& bytes) {
    std::lock_guard<std::mutex> lock(mutex_);
    std::size_t done = 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(1);
    while (master_ >= 0 && done < bytes.size() && std::chrono::steady_clock::now() < deadline) {
      const ssize_t n = ::write(master_, bytes.data() + done, bytes.size() - done);
      if (n > 0) {
        done += static_cast<std::size_t>(n);
      } else {
        pollfd pfd{master_, POLLOUT, 0};
        ::poll(&pfd, 1, 10);
      }
    }
    return done == bytes.size();
  }

  // Bytes the driver wrote, waiting at most `timeout_ms`.
  std::vector<std::uint8_t> Read(int timeout_ms) {
    int fd = -1;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      fd = master_;
    }
    if (fd < 0) return {};
    pollfd pfd{fd, POLLIN, 0};
    if (::poll(&pfd, 1, timeout_ms) <= 0 || (pfd.revents & POLLIN) == 0) return {};
    std::lock_guard<std::mutex> lock(mutex_);
    if (master_ < 0) return {};
    std::vector<std::uint8_t> bytes(4096);
    const ssize_t n = ::read(master_, bytes.data(), bytes.size());
    bytes.resize(n > 0 ? static_cast<std::size_t>(n) : 0);
    return bytes;
  }

  // Unplugs the device: the driver's end sees a hang-up.
  void CloseMaster() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (master_ >= 0) ::close(master_);
    master_ = -1;
  }

 private:
  std::mutex mutex_;
  int master_ = -1;
  std::string slave_path_;
};

// Polls `done` until it holds or `limit` passes; tests assert the result, never the time.
inline bool WaitUntil(const std::function<bool()>& done,
                      std::chrono::milliseconds limit = std::chrono::milliseconds(3000)) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < deadline) {
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return done();
}

}  // namespace dynamap::robotio::hardware::test
