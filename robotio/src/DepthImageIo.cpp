#include "dynamap/robotio/DepthImageIo.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "dynamap/robotio/AtomicFile.hpp"

namespace dynamap::robotio {

Expected<DepthImage> ReadDepthImage(const std::string& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) return Error{file + ": file not found"};
  cv::Mat image;
  try {
    image = cv::imread(file, cv::IMREAD_ANYDEPTH | cv::IMREAD_ANYCOLOR);
  } catch (const cv::Exception& e) {
    return Error{file + ": not a readable image (" + e.what() + ")"};
  }
  if (image.empty()) return Error{file + ": not a readable image (truncated or wrong format)"};
  if (image.type() != CV_16UC1) {
    return Error{file + ": expected a single-channel 16-bit depth image, found " +
                 std::to_string(image.channels()) + " channel(s) of " +
                 (image.depth() == CV_8U ? "8-bit" : "non-16-bit") + " data"};
  }
  DepthImage out;
  out.width = image.cols;
  out.height = image.rows;
  out.values.resize(static_cast<std::size_t>(image.cols) * image.rows);
  for (int r = 0; r < image.rows; ++r) {
    const auto* row = image.ptr<std::uint16_t>(r);
    std::copy(row, row + image.cols, out.values.begin() + static_cast<std::ptrdiff_t>(r) * image.cols);
  }
  return out;
}

Status WriteDepthPng(const DepthImage& image, const std::string& file) {
  // cv::Mat over the caller's buffer: no copy; imwrite only reads it.
  const cv::Mat mat(image.height, image.width, CV_16UC1,
                    const_cast<std::uint16_t*>(image.values.data()));
  return WriteFileAtomically(file, [&mat](const std::string& path) {
    try {
      return cv::imwrite(path, mat, {cv::IMWRITE_PNG_COMPRESSION, 1});
    } catch (const cv::Exception&) {
      return false;
    }
  });
}

std::vector<std::uint16_t> TumToMillimetres(const std::vector<std::uint16_t>& tum) {
  std::vector<std::uint16_t> mm(tum.size());
  for (std::size_t i = 0; i < tum.size(); ++i) {
    mm[i] = static_cast<std::uint16_t>(std::lround(tum[i] * (1000.0 / kTumDepthScale)));
  }
  return mm;
}

std::vector<std::uint16_t> MillimetresToTum(const std::vector<std::uint16_t>& mm) {
  std::vector<std::uint16_t> tum(mm.size());
  for (std::size_t i = 0; i < mm.size(); ++i) {
    // 5 TUM units per mm; depths above 13.1 m saturate (beyond any Kinect range).
    tum[i] = static_cast<std::uint16_t>(std::min<std::uint32_t>(mm[i] * 5u, 65535u));
  }
  return tum;
}

}  // namespace dynamap::robotio
