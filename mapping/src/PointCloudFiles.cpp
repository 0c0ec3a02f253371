#include "dynamap/mapping/PointCloudFiles.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "dynamap/robotio/AtomicFile.hpp"

namespace dynamap::mapping {
namespace {

std::string FormatPoints(const robotio::PointList& points) {
  std::string text;
  text.reserve(points.size() * 32);
  char line[96];
  for (const Eigen::Vector3f& p : points) {
    const int n = std::snprintf(line, sizeof(line), "%.6f %.6f %.6f\n", p.x(), p.y(), p.z());
    text.append(line, static_cast<std::size_t>(n));
  }
  return text;
}

// Reads `count` lines of "x y z" after the header.
robotio::Expected<robotio::PointList> ReadXyzLines(std::istream& in, std::size_t count,
                                                   const std::string& file) {
  robotio::PointList points;
  points.reserve(count);
  std::string line;
  while (points.size() < count && std::getline(in, line)) {
    std::istringstream fields(line);
    float x = 0, y = 0, z = 0;
    if (!(fields >> x >> y >> z)) {
      return robotio::Error{file + ": malformed point line '" + line + "'"};
    }
    points.emplace_back(x, y, z);
  }
  if (points.size() != count) {
    return robotio::Error{file + ": truncated: header announces " + std::to_string(count) +
                          " points, found " + std::to_string(points.size())};
  }
  return points;
}

}  // namespace

robotio::Status WritePly(const robotio::PointList& points, const std::string& file) {
  std::ostringstream header;
  header << "ply\nformat ascii 1.0\ncomment dynamap occupied voxel centres, map frame, m\n"
         << "element vertex " << points.size()
         << "\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
  return robotio::WriteFileAtomically(file, header.str() + FormatPoints(points));
}

robotio::Status WritePcd(const robotio::PointList& points, const std::string& file) {
  std::ostringstream header;
  header << "# .PCD v0.7 - dynamap occupied voxel centres, map frame, m\n"
         << "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
         << "WIDTH " << points.size() << "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\n"
         << "POINTS " << points.size() << "\nDATA ascii\n";
  return robotio::WriteFileAtomically(file, header.str() + FormatPoints(points));
}

robotio::Expected<robotio::PointList> ReadPly(const std::string& file) {
  std::ifstream in(file);
  if (!in) return robotio::Error{file + ": cannot open"};
  std::string line;
  if (!std::getline(in, line) || line != "ply") return robotio::Error{file + ": not a PLY file"};
  std::size_t count = 0;
  bool ascii = false;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string key;
    fields >> key;
    if (key == "format") {
      std::string format;
      fields >> format;
      ascii = format == "ascii";
    } else if (key == "element") {
      std::string name;
      fields >> name >> count;
    } else if (key == "end_header") {
      if (!ascii) return robotio::Error{file + ": only ASCII PLY files are read"};
      return ReadXyzLines(in, count, file);
    }
  }
  return robotio::Error{file + ": truncated PLY header (no end_header)"};
}

robotio::Expected<robotio::PointList> ReadPcd(const std::string& file) {
  std::ifstream in(file);
  if (!in) return robotio::Error{file + ": cannot open"};
  std::string line;
  std::size_t count = 0;
  bool have_version = false;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string key;
    fields >> key;
    if (key == "VERSION") have_version = true;
    if (key == "POINTS") fields >> count;
    if (key == "DATA") {
      std::string kind;
      fields >> kind;
      if (!have_version) return robotio::Error{file + ": not a PCD file"};
      if (kind != "ascii") return robotio::Error{file + ": only ASCII PCD files are read"};
      return ReadXyzLines(in, count, file);
    }
  }
  return robotio::Error{file + ": not a PCD file or truncated header (no DATA line)"};
}

}  // namespace dynamap::mapping
