// Reading and writing 16-bit depth images (PNG, TIFF) with OpenCV imgcodecs.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "dynamap/robotio/Expected.hpp"

namespace dynamap::robotio {

struct DepthImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint16_t> values;  // Row-major raw values (units depend on the file).
};

// Reads a single-channel 16-bit image; any other kind is an error naming the file.
[[nodiscard]] Expected<DepthImage> ReadDepthImage(const std::string& file);
// Writes a 16-bit PNG atomically.
[[nodiscard]] Status WriteDepthPng(const DepthImage& image, const std::string& file);

// TUM scale: PNG value = metres * 5000. Kinect millimetres ↔ TUM values.
constexpr double kTumDepthScale = 5000.0;
[[nodiscard]] std::vector<std::uint16_t> TumToMillimetres(const std::vector<std::uint16_t>& tum);
[[nodiscard]] std::vector<std::uint16_t> MillimetresToTum(const std::vector<std::uint16_t>& mm);

}  // namespace dynamap::robotio
