// A Kinect (or any OpenNI2 depth camera) behind DepthCameraInterface: live devices chosen by
// URI or serial number, and `.oni` recordings through OpenNI2's own file device. A missing
// device or driver is an Error that says which; every wait is bounded.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dynamap/robotio/Devices.hpp"
#include "dynamap/robotio/Intrinsics.hpp"

namespace dynamap::robotio::hardware {

struct OpenNiDeviceInfo {
  std::string uri;      // What OpenNI2 opens it by (e.g. "freenect://0", a USB path).
  std::string name;     // Model name as the driver reports it.
  std::string vendor;   // Vendor as the driver reports it.
  int usb_vendor_id = 0;
  int usb_product_id = 0;
};

struct OpenNiCameraConfig {
  // Which camera: "" = the only one connected; a URI from ListOpenNiDevices(); "serial:XYZ"
  // for the device whose serial number is XYZ; or a path ending in ".oni" to play a file.
  std::string device;
  int sensor_id = 0;   // Index of this camera in the rig (frames carry it).
  int width = 640;     // px, depth mode to select.
  int height = 480;    // px.
  int fps = 30;        // Hz (ignored for files, which keep their recorded mode).
  Intrinsics intrinsics;  // Calibrated pinhole model at 640×480; scaled to the mode.
};

// Devices OpenNI2 can see now. With none, an Error that names the drivers OpenNI2 has and
// whether the Kinect v1 driver is among them.
[[nodiscard]] Expected<std::vector<OpenNiDeviceInfo>> ListOpenNiDevices();

class OpenNiCamera final : public DepthCameraInterface {
 public:
  [[nodiscard]] static Expected<std::unique_ptr<OpenNiCamera>> Open(
      const OpenNiCameraConfig& config);
  ~OpenNiCamera() override;

  [[nodiscard]] int sensor_id() const override { return config_.sensor_id; }
  // nullopt on time-out; for a file, an Error "end of file" once every frame was read.
  [[nodiscard]] Expected<std::optional<DepthFrame>> Grab(
      std::chrono::milliseconds timeout) override;

  [[nodiscard]] const std::string& uri() const { return uri_; }
  [[nodiscard]] bool is_file() const { return frame_count_.has_value(); }
  // Frames in the file (files only).
  [[nodiscard]] std::optional<int> frame_count() const { return frame_count_; }

 private:
  struct Streams;
  OpenNiCamera(const OpenNiCameraConfig& config, std::unique_ptr<Streams> streams);

  OpenNiCameraConfig config_;
  std::unique_ptr<Streams> streams_;
  std::string uri_;
  std::optional<int> frame_count_;
  int frames_read_ = 0;
  // Offset from device clock to host clock, the smallest (host - device) seen so far: the
  // frame with the least transfer delay bounds the capture instant best.
  std::optional<std::int64_t> clock_offset_ns_;
};

}  // namespace dynamap::robotio::hardware
