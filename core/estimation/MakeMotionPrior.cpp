#include "estimation/MakeMotionPrior.hpp"

#include "estimation/ConstantVelocityPrior.hpp"
#include "estimation/StaticBodyPrior.hpp"
#include "estimation/WheelOdometryPrior.hpp"

namespace unimap::estimation {

std::unique_ptr<MotionPrior> MakeMotionPrior(const MotionPriorOptions& options) {
  switch (options.source) {
    case MotionSource::kWheelOdometry:
      return std::make_unique<WheelOdometryPrior>(options);
    case MotionSource::kConstantVelocity:
      return std::make_unique<ConstantVelocityPrior>(options);
    case MotionSource::kStatic:
      return std::make_unique<StaticBodyPrior>();
    case MotionSource::kImu:
      break;
  }
  return nullptr;
}

}  // namespace unimap::estimation
