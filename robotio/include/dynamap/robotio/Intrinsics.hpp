// Pinhole intrinsics of a depth camera (Kinect v1 defaults: 640x480, f = 525 px).
#pragma once

namespace dynamap::robotio {

struct Intrinsics {
  int width = 640;     // px.
  int height = 480;    // px.
  double fx = 525.0;   // px.
  double fy = 525.0;   // px.
  double cx = 319.5;   // px, principal point column.
  double cy = 239.5;   // px, principal point row.

  // The same camera at another resolution (focal length and centre scale with it).
  [[nodiscard]] Intrinsics Scaled(int new_width, int new_height) const;
  bool operator==(const Intrinsics& other) const;
};

}  // namespace dynamap::robotio
