#pragma once
#include <memory>

#include "estimation/MotionPrior.hpp"
#include "estimation/MotionPriorOptions.hpp"

namespace unimap::estimation {

// The motion prior of options.source; nullptr for the IMU (the ESKF
// integrates it itself).
std::unique_ptr<MotionPrior> MakeMotionPrior(const MotionPriorOptions& options);

}  // namespace unimap::estimation
