#include "dynamap/robotio/Intrinsics.hpp"

namespace dynamap::robotio {

Intrinsics Intrinsics::Scaled(int new_width, int new_height) const {
  const double sx = static_cast<double>(new_width) / width;
  const double sy = static_cast<double>(new_height) / height;
  Intrinsics out;
  out.width = new_width;
  out.height = new_height;
  out.fx = fx * sx;
  out.fy = fy * sy;
  // Pixel centres: continuous coordinate of pixel i is i + 0.5 before and after scaling.
  out.cx = (cx + 0.5) * sx - 0.5;
  out.cy = (cy + 0.5) * sy - 0.5;
  return out;
}

bool Intrinsics::operator==(const Intrinsics& o) const {
  return width == o.width && height == o.height && fx == o.fx && fy == o.fy && cx == o.cx &&
         cy == o.cy;
}

}  // namespace dynamap::robotio
