#include "dynamap/robotio/hardware/OpenNiCamera.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <OpenNI.h>

#include "dynamap/robotio/hardware/MonotonicClock.hpp"

namespace dynamap::robotio::hardware {
namespace {

constexpr const char* kKinectDriver = "libFreenectDriver.so";

// OpenNI2 is one process-wide context: initialize() may be called again and again, but
// its shutdown() is not reference-counted (it tears down streams other cameras still use
// and crashes their closing), so it is never called; the context ends with the process.
bool InitializeOpenNi() { return openni::OpenNI::initialize() == openni::STATUS_OK; }

std::string LastOpenNiError() {
  const std::string text = openni::OpenNI::getExtendedError();
  return text.empty() ? std::string("no further detail from OpenNI2") : text;
}

// OpenNI2 loads drivers from OpenNI2/Drivers beside its own library (unless OpenNI.ini
// says otherwise), so that is where to look for the Kinect v1 driver.
std::filesystem::path DriverDirectory() {
  Dl_info info{};
  if (::dladdr(reinterpret_cast<void*>(&oniInitialize), &info) == 0 || info.dli_fname == nullptr) {
    return {};
  }
  return std::filesystem::path(info.dli_fname).parent_path() / "OpenNI2" / "Drivers";
}

std::string NoDeviceMessage() {
  const std::filesystem::path dir = DriverDirectory();
  std::vector<std::string> drivers;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.size() > 3 && name.compare(name.size() - 3, 3, ".so") == 0) drivers.push_back(name);
  }
  std::sort(drivers.begin(), drivers.end());
  std::string list;
  for (const std::string& d : drivers) list += (list.empty() ? "" : ", ") + d;
  const bool has_kinect = std::find(drivers.begin(), drivers.end(), kKinectDriver) != drivers.end();
  std::string message = "OpenNI2 found no depth camera. ";
  if (has_kinect) {
    message += "The Kinect v1 driver (" + std::string(kKinectDriver) + ") is installed in " +
               dir.string() + ": check the USB cable, the Kinect's power supply and the udev " +
               "permissions (docs/HARDWARE.md).";
  } else {
    message += "No driver: the Kinect v1 needs " + std::string(kKinectDriver) +
               " (libfreenect's OpenNI2 driver) in " + dir.string() + ", which has only [" +
               list + "] (docs/HARDWARE.md, Kinect).";
  }
  return message;
}

std::string ModeText(const openni::VideoMode& mode) {
  return std::to_string(mode.getResolutionX()) + "x" + std::to_string(mode.getResolutionY()) +
         "@" + std::to_string(mode.getFps()) + "Hz format " +
         std::to_string(static_cast<int>(mode.getPixelFormat()));
}

bool IsDepthFormat(openni::PixelFormat format) {
  return format == openni::PIXEL_FORMAT_DEPTH_1_MM || format == openni::PIXEL_FORMAT_DEPTH_100_UM;
}

}  // namespace

struct OpenNiCamera::Streams {
  openni::Device device;
  openni::VideoStream depth;
  ~Streams() {
    depth.stop();
    depth.destroy();
    device.close();
  }
};

Expected<std::vector<OpenNiDeviceInfo>> ListOpenNiDevices() {
  if (!InitializeOpenNi()) return Error{"OpenNI2 failed to initialise: " + LastOpenNiError()};
  openni::Array<openni::DeviceInfo> list;
  openni::OpenNI::enumerateDevices(&list);
  if (list.getSize() == 0) return Error{NoDeviceMessage()};
  std::vector<OpenNiDeviceInfo> devices;
  for (int i = 0; i < list.getSize(); ++i) {
    devices.push_back({list[i].getUri(), list[i].getName(), list[i].getVendor(),
                       list[i].getUsbVendorId(), list[i].getUsbProductId()});
  }
  return devices;
}

namespace {

// The URI to open for `wanted` ("", a URI, or "serial:XYZ"); files are handled by the caller.
Expected<std::string> ResolveUri(const std::string& wanted) {
  openni::Array<openni::DeviceInfo> list;
  openni::OpenNI::enumerateDevices(&list);
  std::string known;
  for (int i = 0; i < list.getSize(); ++i) known += std::string(known.empty() ? "" : ", ") + list[i].getUri();
  const std::string kSerial = "serial:";
  if (wanted.empty()) {
    if (list.getSize() == 0) return Error{NoDeviceMessage()};
    if (list.getSize() > 1) {
      return Error{"OpenNI2 sees several cameras (" + known +
                   "); name one by URI or serial in the rig's camera config"};
    }
    return std::string(list[0].getUri());
  }
  if (wanted.compare(0, kSerial.size(), kSerial) == 0) {
    const std::string serial = wanted.substr(kSerial.size());
    for (int i = 0; i < list.getSize(); ++i) {
      openni::Device probe;
      if (probe.open(list[i].getUri()) != openni::STATUS_OK) continue;
      char text[128] = {};
      int size = sizeof text;
      const bool read = probe.getProperty(ONI_DEVICE_PROPERTY_SERIAL_NUMBER, text, &size) ==
                        openni::STATUS_OK;
      probe.close();
      if (read && serial == std::string(text, strnlen(text, sizeof text))) return std::string(list[i].getUri());
    }
    if (list.getSize() == 0) return Error{NoDeviceMessage()};
    return Error{"no OpenNI2 camera with serial number " + serial + " (connected: " + known + ")"};
  }
  // A URI the enumeration does not list may still open (OpenNI2's built-in "Dummy" device).
  return wanted;
}

}  // namespace

Expected<std::unique_ptr<OpenNiCamera>> OpenNiCamera::Open(const OpenNiCameraConfig& config) {
  if (!InitializeOpenNi()) return Error{"OpenNI2 failed to initialise: " + LastOpenNiError()};
  const std::string& wanted = config.device;
  const bool is_file = wanted.size() > 4 && wanted.compare(wanted.size() - 4, 4, ".oni") == 0;
  std::string uri = wanted;
  if (is_file) {
    if (!std::filesystem::is_regular_file(wanted)) {
      return Error{"OpenNI2 recording " + wanted + ": no such file"};
    }
  } else {
    Expected<std::string> resolved = ResolveUri(wanted);
    if (!resolved) return resolved.error();
    uri = *resolved;
  }
  auto streams = std::make_unique<Streams>();
  const std::string what = is_file ? "OpenNI2 recording " + uri : "OpenNI2 camera " + uri;
  if (streams->device.open(uri.c_str()) != openni::STATUS_OK) {
    return Error{what + ": cannot open: " + LastOpenNiError()};
  }
  const openni::SensorInfo* info = streams->device.getSensorInfo(openni::SENSOR_DEPTH);
  if (info == nullptr || streams->depth.create(streams->device, openni::SENSOR_DEPTH) != openni::STATUS_OK) {
    return Error{what + ": has no depth stream: " + LastOpenNiError()};
  }
  if (!is_file) {
    const auto& modes = info->getSupportedVideoModes();
    std::optional<openni::VideoMode> chosen;
    std::string offered;
    for (int i = 0; i < modes.getSize(); ++i) {
      offered += (offered.empty() ? "" : ", ") + ModeText(modes[i]);
      if (modes[i].getResolutionX() == config.width && modes[i].getResolutionY() == config.height &&
          modes[i].getFps() == config.fps && IsDepthFormat(modes[i].getPixelFormat())) {
        chosen = modes[i];
      }
    }
    if (!chosen) {
      return Error{what + ": no depth mode " + std::to_string(config.width) + "x" +
                   std::to_string(config.height) + "@" + std::to_string(config.fps) +
                   "Hz; it offers " + offered};
    }
    // Only switch when needed: some drivers refuse to set even the mode they are in.
    const openni::VideoMode current = streams->depth.getVideoMode();
    const bool same = current.getResolutionX() == chosen->getResolutionX() &&
                      current.getResolutionY() == chosen->getResolutionY() &&
                      current.getFps() == chosen->getFps() &&
                      current.getPixelFormat() == chosen->getPixelFormat();
    if (!same && streams->depth.setVideoMode(*chosen) != openni::STATUS_OK) {
      return Error{what + ": cannot set depth mode " + ModeText(*chosen) + ": " + LastOpenNiError()};
    }
  }
  std::optional<int> frame_count;
  if (is_file) {
    openni::PlaybackControl* playback = streams->device.getPlaybackControl();
    if (playback == nullptr) return Error{what + ": opened, but not as a file device"};
    playback->setRepeatEnabled(false);
    // Manual speed: a frame is played when it is read, none is skipped, and the player
    // thread is idle when the device closes (at real-time speed Debian's libOniFile now
    // and then crashed in that thread while closing; docs/HARDWARE.md).
    playback->setSpeed(-1.0f);
    frame_count = playback->getNumberOfFrames(streams->depth);
  }
  if (streams->depth.start() != openni::STATUS_OK) {
    return Error{what + ": cannot start the depth stream: " + LastOpenNiError()};
  }
  std::unique_ptr<OpenNiCamera> camera(new OpenNiCamera(config, std::move(streams)));
  camera->uri_ = uri;
  camera->frame_count_ = frame_count;
  return camera;
}

OpenNiCamera::OpenNiCamera(const OpenNiCameraConfig& config, std::unique_ptr<Streams> streams)
    : config_(config), streams_(std::move(streams)) {}

OpenNiCamera::~OpenNiCamera() = default;

Expected<std::optional<DepthFrame>> OpenNiCamera::Grab(std::chrono::milliseconds timeout) {
  if (frame_count_ && frames_read_ >= *frame_count_) {
    return Error{"OpenNI2 recording " + uri_ + ": end of file after " +
                 std::to_string(frames_read_) + " frames"};
  }
  openni::VideoStream* stream = &streams_->depth;
  int ready = -1;
  const openni::Status waited =
      openni::OpenNI::waitForAnyStream(&stream, 1, &ready, static_cast<int>(timeout.count()));
  if (waited == openni::STATUS_TIME_OUT) return std::optional<DepthFrame>{};
  if (waited != openni::STATUS_OK) {
    return Error{"OpenNI2 camera " + uri_ + ": stream lost: " + LastOpenNiError()};
  }
  openni::VideoFrameRef ref;
  if (streams_->depth.readFrame(&ref) != openni::STATUS_OK || !ref.isValid()) {
    return Error{"OpenNI2 camera " + uri_ + ": cannot read a frame: " + LastOpenNiError()};
  }
  const std::int64_t received_ns = MonotonicNanos();
  ++frames_read_;
  DepthFrame frame;
  frame.sensor_id = config_.sensor_id;
  frame.width = ref.getWidth();
  frame.height = ref.getHeight();
  frame.intrinsics = config_.intrinsics.Scaled(frame.width, frame.height);
  frame.depth_mm.resize(static_cast<std::size_t>(frame.width) * static_cast<std::size_t>(frame.height));
  const bool tenths = ref.getVideoMode().getPixelFormat() == openni::PIXEL_FORMAT_DEPTH_100_UM;
  const auto* bytes = static_cast<const std::uint8_t*>(ref.getData());
  for (int v = 0; v < frame.height; ++v) {
    const auto* row = reinterpret_cast<const std::uint16_t*>(bytes + static_cast<std::ptrdiff_t>(v) * ref.getStrideInBytes());
    std::uint16_t* out = frame.depth_mm.data() + static_cast<std::ptrdiff_t>(v) * frame.width;
    for (int u = 0; u < frame.width; ++u) out[u] = tenths ? static_cast<std::uint16_t>(row[u] / 10) : row[u];
  }
  const auto device_ns = static_cast<std::int64_t>(ref.getTimestamp()) * 1000;
  if (is_file()) {
    // A recording keeps its own clock; there is no host arrival to relate it to.
    frame.stamp_ns = device_ns;
    frame.received_ns = device_ns;
    return std::optional<DepthFrame>(std::move(frame));
  }
  const std::int64_t offset = received_ns - device_ns;
  if (!clock_offset_ns_ || offset < *clock_offset_ns_) clock_offset_ns_ = offset;
  frame.stamp_ns = device_ns + *clock_offset_ns_;
  frame.received_ns = received_ns;
  return std::optional<DepthFrame>(std::move(frame));
}

}  // namespace dynamap::robotio::hardware
