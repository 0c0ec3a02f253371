#include "dynamap/robotio/Recording.hpp"

namespace dynamap::robotio::recording_files {

namespace {
std::string Suffix(int sensor_id) { return sensor_id == 0 ? "" : std::to_string(sensor_id); }
}  // namespace

std::string DepthDir(int sensor_id) { return "depth" + Suffix(sensor_id); }
std::string DepthIndex(int sensor_id) { return DepthDir(sensor_id) + ".txt"; }
std::string LabelDir(int sensor_id) { return "labels" + Suffix(sensor_id); }
std::string LabelIndex(int sensor_id) { return LabelDir(sensor_id) + ".txt"; }

}  // namespace dynamap::robotio::recording_files
