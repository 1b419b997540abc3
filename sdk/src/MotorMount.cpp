#include "unimap/MotorMount.hpp"

#include <cmath>

#include "unimap/Errors.hpp"

namespace unimap {
namespace {
constexpr double kDegToRad = M_PI / 180.0;
}  // namespace

double MotorMount::MotorAngle(double encoder_angle_rad) const {
  return static_cast<double>(encoder_direction) * encoder_angle_rad + encoder_offset_deg * kDegToRad;
}

Eigen::Isometry3d MotorMount::BodyFromLidar(double motor_angle_rad) const {
  // T_body_lidar(theta) = T_body_motor * Rot(axis, theta) * T_motor_lidar
  Eigen::Isometry3d R_motor = Eigen::Isometry3d::Identity();
  R_motor.linear() = Eigen::AngleAxisd(motor_angle_rad, axis_motor.normalized()).toRotationMatrix();
  return body_motor.ToIsometry() * R_motor * motor_lidar.ToIsometry();
}

void MotorMount::AddTo(ParameterSet* set) const {
  body_motor.AddTo(set, "extrinsic.body_motor", "motor frame in the body frame (T_body_motor)");
  motor_lidar.AddTo(set, "extrinsic.motor_lidar", "LiDAR frame in the motor frame at angle 0 (T_motor_lidar)");
  set->Add({"motor.axis",
            "",
            "motor rotation axis in the motor frame (unit vector, normalised)",
            std::vector<double>{axis_motor.x(), axis_motor.y(), axis_motor.z()},
            -1.0,
            1.0,
            {}});
  set->Add({"motor.encoder_offset_deg",
            "",
            "motor angle when the encoder reads 0 (deg)",
            encoder_offset_deg,
            -360.0,
            360.0,
            {}});
  set->Add({"motor.encoder_direction",
            "",
            "+1: encoder counts about +axis, -1: about -axis",
            std::int64_t{encoder_direction},
            -1,
            1,
            {}});
}

MotorMount MotorMount::FromMap(const ParameterMap& map) {
  MotorMount m;
  m.body_motor = Extrinsic::FromMap(map, "extrinsic.body_motor");
  m.motor_lidar = Extrinsic::FromMap(map, "extrinsic.motor_lidar");
  m.axis_motor = map.GetVector3("motor.axis");
  if (m.axis_motor.norm() < 1e-6) throw ConfigError("", 0, "motor.axis", "axis must not be zero");
  m.encoder_offset_deg = map.GetDouble("motor.encoder_offset_deg");
  const std::int64_t direction = map.GetInt("motor.encoder_direction");
  if (direction != 1 && direction != -1) {
    throw ConfigError("", 0, "motor.encoder_direction", "must be +1 or -1");
  }
  m.encoder_direction = static_cast<int>(direction);
  return m;
}

}  // namespace unimap
