#include "dynamap/app/runtime/MissionConfig.hpp"

namespace dynamap::app::runtime {

const char* ToString(PoseSource source) {
  switch (source) {
    case PoseSource::kSlam: return "slam";
    case PoseSource::kOdometry: return "odometry";
    case PoseSource::kGroundTruth: return "groundtruth";
  }
  return "unknown";
}

}  // namespace dynamap::app::runtime
