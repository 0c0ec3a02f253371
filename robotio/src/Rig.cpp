#include "dynamap/robotio/Rig.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "dynamap/robotio/AtomicFile.hpp"
#include "dynamap/robotio/ConfigReader.hpp"

namespace dynamap::robotio {

namespace {

constexpr double kDeg = M_PI / 180.0;

Intrinsics ParseIntrinsics(ConfigNode node) {
  Intrinsics k;
  k.width = node.RequireInt("width", 8, 4096);
  k.height = node.RequireInt("height", 8, 4096);
  k.fx = node.RequireDouble("fx", 1.0, 1e5);
  k.fy = node.RequireDouble("fy", 1.0, 1e5);
  k.cx = node.RequireDouble("cx", -1e4, 1e4);
  k.cy = node.RequireDouble("cy", -1e4, 1e4);
  return k;
}

KinectMount ParseMount(ConfigNode& node) {
  KinectMount mount;
  mount.id = node.RequireString("id");
  const Eigen::Vector3d translation = node.RequireVector("translation", 3, -10.0, 10.0);
  const Eigen::Vector3d rpy_deg = node.RequireVector("rpy_deg", 3, -360.0, 360.0);
  mount.T_base_kinect = MountPose(translation, rpy_deg * kDeg);
  if (node.Has("intrinsics")) mount.intrinsics = ParseIntrinsics(node.Child("intrinsics"));
  node.Read("min_range_m", &mount.min_range_m, 0.0, 20.0);
  node.Read("max_range_m", &mount.max_range_m, 0.1, 20.0);
  node.Read("latency_s", &mount.latency_s, -1.0, 1.0);
  node.Read("rate_hz", &mount.rate_hz, 0.1, 120.0);
  if (mount.max_range_m <= mount.min_range_m) {
    node.Fail("max_range_m", "must be greater than min_range_m (" +
                                 std::to_string(mount.min_range_m) + ")");
  }
  return mount;
}

Rig ParseRigNode(ConfigNode& root) {
  Rig rig;
  std::set<std::string> ids;
  for (ConfigNode& node : root.ChildList("kinects")) {
    rig.kinects.push_back(ParseMount(node));
    if (!ids.insert(rig.kinects.back().id).second) {
      node.Fail("id", "'" + rig.kinects.back().id + "' is used by two Kinects");
    }
  }
  if (rig.kinects.empty()) root.Fail("kinects", "must list at least one Kinect");
  return rig;
}

}  // namespace

Eigen::Matrix3d BodyFromOptical() {
  Eigen::Matrix3d R;
  // Columns: optical x (right) → body -y, optical y (down) → body -z, optical z → body x.
  R << 0, 0, 1,  //
      -1, 0, 0,  //
      0, -1, 0;
  return R;
}

Eigen::Isometry3d MountPose(const Eigen::Vector3d& translation_m, const Eigen::Vector3d& rpy_rad) {
  const Eigen::Matrix3d R_base_body =
      (Eigen::AngleAxisd(rpy_rad.z(), Eigen::Vector3d::UnitZ()) *
       Eigen::AngleAxisd(rpy_rad.y(), Eigen::Vector3d::UnitY()) *
       Eigen::AngleAxisd(rpy_rad.x(), Eigen::Vector3d::UnitX()))
          .toRotationMatrix();
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = R_base_body * BodyFromOptical();
  T.translation() = translation_m;
  return T;
}

Eigen::Vector3d MountRollPitchYaw(const Eigen::Isometry3d& T_base_kinect) {
  const Eigen::Matrix3d R = T_base_kinect.linear() * BodyFromOptical().transpose();
  const double pitch = std::asin(std::clamp(-R(2, 0), -1.0, 1.0));
  const double roll = std::atan2(R(2, 1), R(2, 2));
  const double yaw = std::atan2(R(1, 0), R(0, 0));
  return {roll, pitch, yaw};
}

Expected<Rig> LoadRig(const std::string& file) {
  return ParseYamlFile<Rig>(file, ParseRigNode);
}

Expected<Rig> ParseRig(const std::string& yaml_text, const std::string& name) {
  return ParseYamlText<Rig>(yaml_text, name, ParseRigNode);
}

std::string RigToYaml(const Rig& rig) {
  YAML::Emitter out;
  out.SetDoublePrecision(17);
  out << YAML::Comment("dynamap rig: Kinect mounting poses in base (x forward, y left, z up)");
  out << YAML::BeginMap << YAML::Key << "kinects" << YAML::Value << YAML::BeginSeq;
  for (const KinectMount& m : rig.kinects) {
    const Eigen::Vector3d t = m.T_base_kinect.translation();
    const Eigen::Vector3d rpy = MountRollPitchYaw(m.T_base_kinect) / kDeg;
    out << YAML::BeginMap;
    out << YAML::Key << "id" << YAML::Value << m.id;
    out << YAML::Key << "translation" << YAML::Value << YAML::Flow << YAML::BeginSeq << t.x()
        << t.y() << t.z() << YAML::EndSeq;
    out << YAML::Key << "rpy_deg" << YAML::Value << YAML::Flow << YAML::BeginSeq << rpy.x()
        << rpy.y() << rpy.z() << YAML::EndSeq;
    out << YAML::Key << "intrinsics" << YAML::Value << YAML::Flow << YAML::BeginMap;
    out << YAML::Key << "width" << YAML::Value << m.intrinsics.width;
    out << YAML::Key << "height" << YAML::Value << m.intrinsics.height;
    out << YAML::Key << "fx" << YAML::Value << m.intrinsics.fx;
    out << YAML::Key << "fy" << YAML::Value << m.intrinsics.fy;
    out << YAML::Key << "cx" << YAML::Value << m.intrinsics.cx;
    out << YAML::Key << "cy" << YAML::Value << m.intrinsics.cy;
    out << YAML::EndMap;
    out << YAML::Key << "min_range_m" << YAML::Value << m.min_range_m;
    out << YAML::Key << "max_range_m" << YAML::Value << m.max_range_m;
    out << YAML::Key << "latency_s" << YAML::Value << m.latency_s;
    out << YAML::Key << "rate_hz" << YAML::Value << m.rate_hz;
    out << YAML::EndMap;
  }
  out << YAML::EndSeq << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

Status SaveRig(const Rig& rig, const std::string& file) {
  return WriteFileAtomically(file, RigToYaml(rig));
}

}  // namespace dynamap::robotio
