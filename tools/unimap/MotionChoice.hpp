#pragma once
// Which prediction a run uses between scans: what the user asked for, or
// what the platform and the dataset hold (a static body, else an IMU, else
// wheel odometry, else constant velocity).
#include <string>

#include "estimation/MotionPriorOptions.hpp"
#include "io/DatasetReader.hpp"

namespace unimap::cli {

struct MotionChoice {
  estimation::MotionSource source = estimation::MotionSource::kImu;
  std::string name;    // "imu", "odometry", "constant-velocity" or "static"
  std::string reason;  // why, e.g. "the dataset has no imu.csv and no odometry.csv"
};

// requested: "auto" (the default) or a name ParseMotionSource accepts;
// static_body: the platform says its body does not move
// (MotionPriorOptions::static_body), which "auto" follows. Throws InputError
// for an unknown name, or for a source the dataset lacks (the message names
// the file and what to use instead).
MotionChoice ChooseMotion(const std::string& requested, io::DatasetReader& reader, bool static_body = false);

}  // namespace unimap::cli
