// Manual driving with a gamepad (the thesis's Xbox controller, appendix B.4) through the
// Linux joystick API (/dev/input/jsN, struct js_event): a dead-man button must be held
// for any motion; releasing it, or losing the pad, commands a stop.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "dynamap/robotio/Expected.hpp"
#include "dynamap/robotio/Readings.hpp"

namespace dynamap::robotio::hardware {

// Defaults follow the Linux xpad driver's Xbox 360 layout.
struct GamepadConfig {
  std::string device = "/dev/input/js0";  // Joystick device node.
  int forward_axis = 1;        // Left stick vertical (pushed forward = negative values).
  int turn_axis = 3;           // Right stick horizontal (pushed left = negative values).
  int deadman_button = 4;      // LB: motion only while held.
  int finish_button = 7;       // Start: ends a manual recording.
  double max_velocity_mps = 0.5;   // m/s at full stick.
  double max_omega_radps = 0.8;    // rad/s at full stick.
  double dead_zone = 0.1;          // Stick fraction (0..1) read as zero.
};

struct TeleopState {
  VelocityCommand command;       // What the base should do now (zero without dead-man).
  bool deadman_held = false;
  bool finish_requested = false;  // The finish button was pressed since opening.
};

class GamepadTeleop {
 public:
  // Opens the joystick node; the Error names it and suggests the likely cause.
  [[nodiscard]] static Expected<GamepadTeleop> Open(const GamepadConfig& config);
  // Reads from an already open descriptor (a pipe in tests); takes ownership.
  [[nodiscard]] static GamepadTeleop FromDescriptor(int fd, const GamepadConfig& config);

  GamepadTeleop(GamepadTeleop&& other) noexcept;
  GamepadTeleop& operator=(GamepadTeleop&& other) noexcept;
  GamepadTeleop(const GamepadTeleop&) = delete;
  GamepadTeleop& operator=(const GamepadTeleop&) = delete;
  ~GamepadTeleop();

  // Applies every event that arrives within `timeout` and returns the resulting state.
  // Error when the pad is gone (unplugged, out of range); the caller must stop the base.
  [[nodiscard]] Expected<TeleopState> Update(std::chrono::milliseconds timeout);

 private:
  GamepadTeleop(int fd, const GamepadConfig& config);
  void Apply(std::uint8_t type, std::uint8_t number, std::int16_t value);
  [[nodiscard]] double Stick(int axis) const;
  void Close();

  int fd_ = -1;
  GamepadConfig config_;
  std::vector<std::int16_t> axes_;
  std::vector<bool> buttons_;
  bool finish_requested_ = false;
  std::vector<std::uint8_t> partial_;  // Bytes of an event split across reads.
};

}  // namespace dynamap::robotio::hardware
