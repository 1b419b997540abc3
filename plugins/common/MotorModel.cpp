#include "MotorModel.hpp"

#include "unimap/Errors.hpp"

namespace unimap::payload {
namespace {
constexpr const char* kRate = "motor.rate_rpm";
}  // namespace

void MotorModel::AddTo(ParameterSet* set) const {
  mount.AddTo(set);
  set->Add({kRate,
            "",
            "nominal motor speed; informative (the simulator spins the motor at this rate, "
            "the mapper follows the encoder) (rev/min)",
            rate_rpm,
            0.1,
            600.0,
            {}});
}

MotorModel MotorModel::FromMap(const ParameterMap& map) {
  MotorModel model;
  model.mount = MotorMount::FromMap(map);
  model.rate_rpm = map.GetDouble(kRate);
  if (!(model.rate_rpm > 0.0)) throw ConfigError("", 0, kRate, "must be positive");
  return model;
}

double MotorModel::MotorAngleAt(const EncoderTrack& encoder, double time_s) const {
  return mount.MotorAngle(encoder.AngleAt(time_s));
}

Eigen::Isometry3d MotorModel::BodyFromLidarAt(const EncoderTrack& encoder, double time_s) const {
  return mount.BodyFromLidar(MotorAngleAt(encoder, time_s));
}

}  // namespace unimap::payload
