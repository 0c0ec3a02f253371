// Gamepad teleop fed real js_event records through a pipe.
#include <gtest/gtest.h>
#include <linux/joystick.h>
#include <unistd.h>

#include "dynamap/robotio/hardware/GamepadTeleop.hpp"

namespace dynamap::robotio::hardware {
namespace {

class GamepadTeleopTest : public ::testing::Test {
 protected:
  void SetUp() override {
    int fds[2];
    ASSERT_EQ(::pipe(fds), 0);
    write_fd_ = fds[1];
    config_.device = "test-pad";
    teleop_.emplace(GamepadTeleop::FromDescriptor(fds[0], config_));
  }
  void TearDown() override {
    if (write_fd_ >= 0) ::close(write_fd_);
  }
  void Send(std::uint8_t type, std::uint8_t number, std::int16_t value) {
    js_event event{};
    event.time = 1234;
    event.type = type;
    event.number = number;
    event.value = value;
    ASSERT_EQ(::write(write_fd_, &event, sizeof event), static_cast<ssize_t>(sizeof event));
  }
  TeleopState Update() {
    auto state = teleop_->Update(std::chrono::milliseconds(50));
    EXPECT_TRUE(state.ok());
    return state.ok() ? *state : TeleopState{};
  }

  int write_fd_ = -1;
  GamepadConfig config_;
  std::optional<GamepadTeleop> teleop_;
};

TEST_F(GamepadTeleopTest, SticksDoNothingWithoutTheDeadManButton) {
  Send(JS_EVENT_AXIS, 1, -32767);
  Send(JS_EVENT_AXIS, 3, 32767);
  const TeleopState state = Update();
  EXPECT_FALSE(state.deadman_held);
  EXPECT_EQ(state.command.v, 0.0);
  EXPECT_EQ(state.command.omega, 0.0);
}

TEST_F(GamepadTeleopTest, FullStickWithDeadManGivesTheConfiguredMaxima) {
  Send(JS_EVENT_BUTTON, 4, 1);
  Send(JS_EVENT_AXIS, 1, -32767);  // Forward.
  Send(JS_EVENT_AXIS, 3, -32767);  // Left.
  const TeleopState state = Update();
  EXPECT_TRUE(state.deadman_held);
  EXPECT_DOUBLE_EQ(state.command.v, config_.max_velocity_mps);
  EXPECT_DOUBLE_EQ(state.command.omega, config_.max_omega_radps);
}

TEST_F(GamepadTeleopTest, ReleasingTheDeadManStopsAtOnce) {
  Send(JS_EVENT_BUTTON, 4, 1);
  Send(JS_EVENT_AXIS, 1, -32767);
  ASSERT_GT(Update().command.v, 0.0);
  Send(JS_EVENT_BUTTON, 4, 0);
  const TeleopState state = Update();
  EXPECT_FALSE(state.deadman_held);
  EXPECT_EQ(state.command.v, 0.0);
}

TEST_F(GamepadTeleopTest, DeadZoneIsZeroAndTheRestIsRescaled) {
  Send(JS_EVENT_BUTTON, 4, 1);
  Send(JS_EVENT_AXIS, 1, -3000);  // Under 10 % of full scale.
  EXPECT_EQ(Update().command.v, 0.0);
  Send(JS_EVENT_AXIS, 1, static_cast<std::int16_t>(-0.55 * 32767));  // Halfway past the zone.
  EXPECT_NEAR(Update().command.v, 0.5 * config_.max_velocity_mps, 1e-4);
}

TEST_F(GamepadTeleopTest, InitialStateEventsDoNotCountAsAFinishPress) {
  Send(JS_EVENT_BUTTON | JS_EVENT_INIT, 7, 1);
  EXPECT_FALSE(Update().finish_requested);
  Send(JS_EVENT_BUTTON, 7, 0);
  Send(JS_EVENT_BUTTON, 7, 1);
  EXPECT_TRUE(Update().finish_requested);
}

TEST_F(GamepadTeleopTest, EventSplitAcrossReadsIsReassembled) {
  js_event event{};
  event.type = JS_EVENT_BUTTON;
  event.number = 4;
  event.value = 1;
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(&event);
  ASSERT_EQ(::write(write_fd_, bytes, 3), 3);
  EXPECT_FALSE(Update().deadman_held);
  ASSERT_EQ(::write(write_fd_, bytes + 3, sizeof event - 3), static_cast<ssize_t>(sizeof event - 3));
  EXPECT_TRUE(Update().deadman_held);
}

TEST_F(GamepadTeleopTest, UnpluggedPadIsAnErrorNamingIt) {
  Send(JS_EVENT_BUTTON, 4, 1);
  ::close(write_fd_);
  write_fd_ = -1;
  Expected<TeleopState> state = teleop_->Update(std::chrono::milliseconds(50));
  if (state.ok()) state = teleop_->Update(std::chrono::milliseconds(50));
  ASSERT_FALSE(state.ok());
  EXPECT_NE(state.error().message.find("test-pad"), std::string::npos);
}

TEST(GamepadTeleop, MissingDeviceNamesIt) {
  GamepadConfig config;
  config.device = "/dev/input/js-none";
  const auto pad = GamepadTeleop::Open(config);
  ASSERT_FALSE(pad.ok());
  EXPECT_NE(pad.error().message.find("/dev/input/js-none"), std::string::npos);
}

}  // namespace
}  // namespace dynamap::robotio::hardware
