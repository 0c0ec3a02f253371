// The Kinect rig: each depth camera's full 6-DoF mounting pose on the base, intrinsics,
// depth range and latency (the file calibration writes and mapping reads).
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "dynamap/robotio/Expected.hpp"
#include "dynamap/robotio/Intrinsics.hpp"

namespace dynamap::robotio {

struct KinectMount {
  std::string id = "kinect0";                            // Unique name, e.g. device serial.
  Eigen::Isometry3d T_base_kinect = Eigen::Isometry3d::Identity();  // kinect optical → base.
  Intrinsics intrinsics;                                 // At the configured resolution.
  double min_range_m = 0.5;                              // m, nearer returns are invalid.
  double max_range_m = 4.5;                              // m, farther returns are invalid.
  double latency_s = 0.1;                                // s, capture → delivery delay.
  double rate_hz = 30.0;                                 // Hz, frame rate.
};

struct Rig {
  std::vector<KinectMount> kinects;
};

// Mounting angles in files: roll/pitch/yaw (degrees) of the camera *body* frame
// (x forward, y left, z up) in base, applied as Rz(yaw)·Ry(pitch)·Rx(roll); the optical
// frame (z forward, x right, y down) is fixed relative to the body. A level, forward
// looking Kinect is rpy_deg [0, 0, 0]; one mounted upside down has roll 180.
[[nodiscard]] Eigen::Isometry3d MountPose(const Eigen::Vector3d& translation_m,
                                          const Eigen::Vector3d& rpy_rad);
// Inverse of MountPose's rotation: (roll, pitch, yaw) in rad.
[[nodiscard]] Eigen::Vector3d MountRollPitchYaw(const Eigen::Isometry3d& T_base_kinect);
// Rotation that maps optical-frame vectors into the body frame.
[[nodiscard]] Eigen::Matrix3d BodyFromOptical();

[[nodiscard]] Expected<Rig> LoadRig(const std::string& file);
[[nodiscard]] Expected<Rig> ParseRig(const std::string& yaml_text, const std::string& name);
[[nodiscard]] std::string RigToYaml(const Rig& rig);
// Written atomically (temp file + rename).
[[nodiscard]] Status SaveRig(const Rig& rig, const std::string& file);

}  // namespace dynamap::robotio
