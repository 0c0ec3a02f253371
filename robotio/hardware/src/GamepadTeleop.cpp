#include "dynamap/robotio/hardware/GamepadTeleop.hpp"

#include <fcntl.h>
#include <linux/joystick.h>
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <utility>

#include "dynamap/robotio/hardware/MonotonicClock.hpp"

namespace dynamap::robotio::hardware {

Expected<GamepadTeleop> GamepadTeleop::Open(const GamepadConfig& config) {
  const int fd = ::open(config.device.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    const std::string reason = std::strerror(errno);
    std::string hint;
    if (errno == ENOENT) hint = " (pad not connected, or the joydev/xpad module is not loaded)";
    if (errno == EACCES) hint = " (add the user to the 'input' group, docs/HARDWARE.md)";
    return Error{"gamepad " + config.device + ": cannot open: " + reason + hint};
  }
  return GamepadTeleop(fd, config);
}

GamepadTeleop GamepadTeleop::FromDescriptor(int fd, const GamepadConfig& config) {
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
  return GamepadTeleop(fd, config);
}

GamepadTeleop::GamepadTeleop(int fd, const GamepadConfig& config) : fd_(fd), config_(config) {}

GamepadTeleop::GamepadTeleop(GamepadTeleop&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)),
      config_(std::move(other.config_)),
      axes_(std::move(other.axes_)),
      buttons_(std::move(other.buttons_)),
      finish_requested_(other.finish_requested_),
      partial_(std::move(other.partial_)) {}

GamepadTeleop& GamepadTeleop::operator=(GamepadTeleop&& other) noexcept {
  if (this != &other) {
    Close();
    fd_ = std::exchange(other.fd_, -1);
    config_ = std::move(other.config_);
    axes_ = std::move(other.axes_);
    buttons_ = std::move(other.buttons_);
    finish_requested_ = other.finish_requested_;
    partial_ = std::move(other.partial_);
  }
  return *this;
}

GamepadTeleop::~GamepadTeleop() { Close(); }

void GamepadTeleop::Close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

void GamepadTeleop::Apply(std::uint8_t type, std::uint8_t number, std::int16_t value) {
  // JS_EVENT_INIT marks the synthetic events that report the state at open time; they
  // set the state like real ones but never count as a fresh press.
  const bool init = (type & JS_EVENT_INIT) != 0;
  const std::uint8_t kind = type & static_cast<std::uint8_t>(~JS_EVENT_INIT);
  if (kind == JS_EVENT_AXIS) {
    if (axes_.size() <= number) axes_.resize(number + 1U, 0);
    axes_[number] = value;
  } else if (kind == JS_EVENT_BUTTON) {
    if (buttons_.size() <= number) buttons_.resize(number + 1U, false);
    buttons_[number] = value != 0;
    if (!init && value != 0 && number == config_.finish_button) finish_requested_ = true;
  }
}

double GamepadTeleop::Stick(int axis) const {
  if (axis < 0 || static_cast<std::size_t>(axis) >= axes_.size()) return 0.0;
  const double x = std::clamp(axes_[static_cast<std::size_t>(axis)] / 32767.0, -1.0, 1.0);
  if (std::abs(x) <= config_.dead_zone) return 0.0;
  // Rescale so the command starts from zero at the edge of the dead zone.
  return std::copysign((std::abs(x) - config_.dead_zone) / (1.0 - config_.dead_zone), x);
}

Expected<TeleopState> GamepadTeleop::Update(std::chrono::milliseconds timeout) {
  auto deadline = std::chrono::steady_clock::now() + timeout;
  while (true) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    pollfd pfd{fd_, POLLIN, 0};
    const int ready = ::poll(&pfd, 1, static_cast<int>(std::max<std::int64_t>(0, left.count())));
    if (ready < 0 && errno != EINTR) {
      return Error{"gamepad " + config_.device + ": poll failed: " + std::strerror(errno)};
    }
    if (ready <= 0) break;
    std::uint8_t buffer[64 * sizeof(js_event)];
    const ssize_t n = ::read(fd_, buffer, sizeof buffer);
    if (n < 0 && (errno == EAGAIN || errno == EINTR)) break;
    if (n <= 0) {
      return Error{"gamepad " + config_.device + ": disconnected (" +
                   (n == 0 ? std::string("end of stream") : std::string(std::strerror(errno))) +
                   ")"};
    }
    partial_.insert(partial_.end(), buffer, buffer + n);
    std::size_t pos = 0;
    for (; pos + sizeof(js_event) <= partial_.size(); pos += sizeof(js_event)) {
      js_event event{};
      std::memcpy(&event, partial_.data() + pos, sizeof event);
      Apply(event.type, event.number, event.value);
    }
    partial_.erase(partial_.begin(), partial_.begin() + static_cast<std::ptrdiff_t>(pos));
    // Something arrived: drain what is already queued, but wait no longer.
    deadline = std::chrono::steady_clock::now();
  }
  TeleopState state;
  state.finish_requested = finish_requested_;
  const auto deadman = static_cast<std::size_t>(config_.deadman_button);
  state.deadman_held = deadman < buttons_.size() && buttons_[deadman];
  state.command.stamp_ns = MonotonicNanos();
  if (state.deadman_held) {
    // Stick forward and stick left give negative axis values.
    state.command.v = -Stick(config_.forward_axis) * config_.max_velocity_mps;
    state.command.omega = -Stick(config_.turn_axis) * config_.max_omega_radps;
  }
  return state;
}

}  // namespace dynamap::robotio::hardware
