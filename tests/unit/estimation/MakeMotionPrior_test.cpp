#include "estimation/MakeMotionPrior.hpp"

#include <gtest/gtest.h>

#include "estimation/ConstantVelocityPrior.hpp"
#include "estimation/WheelOdometryPrior.hpp"

namespace unimap::estimation {
namespace {

TEST(MakeMotionPrior, OnePriorPerSourceAndNoneForTheImu) {
  MotionPriorOptions options;
  EXPECT_EQ(MakeMotionPrior(options), nullptr);
  options.source = MotionSource::kWheelOdometry;
  const auto odometry = MakeMotionPrior(options);
  EXPECT_NE(dynamic_cast<WheelOdometryPrior*>(odometry.get()), nullptr);
  options.source = MotionSource::kConstantVelocity;
  const auto constant = MakeMotionPrior(options);
  EXPECT_NE(dynamic_cast<ConstantVelocityPrior*>(constant.get()), nullptr);
}

}  // namespace
}  // namespace unimap::estimation
