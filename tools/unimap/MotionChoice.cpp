#include "MotionChoice.hpp"

#include "unimap/Errors.hpp"

namespace unimap::cli {
namespace {

const char* Name(estimation::MotionSource source) {
  switch (source) {
    case estimation::MotionSource::kImu:
      return "imu";
    case estimation::MotionSource::kWheelOdometry:
      return "odometry";
    case estimation::MotionSource::kConstantVelocity:
      return "constant-velocity";
    case estimation::MotionSource::kStatic:
      return "static";
  }
  return "?";
}

}  // namespace

MotionChoice ChooseMotion(const std::string& requested, io::DatasetReader& reader, bool static_body) {
  const bool imu = reader.has_imu();
  const bool odometry = reader.has_odometry();
  MotionChoice choice;
  if (requested == "auto") {
    if (static_body) {
      choice.source = estimation::MotionSource::kStatic;
      choice.reason = "the platform's body does not move (mapper: motion: static_body): scans are placed, not matched";
    } else if (imu) {
      choice.source = estimation::MotionSource::kImu;
      choice.reason = "the dataset has IMU data (imu.csv)";
    } else if (odometry) {
      choice.source = estimation::MotionSource::kWheelOdometry;
      choice.reason = "the dataset has no IMU data but wheel odometry (odometry.csv)";
    } else {
      choice.source = estimation::MotionSource::kConstantVelocity;
      choice.reason = "the dataset has neither IMU data (imu.csv) nor wheel odometry (odometry.csv)";
    }
  } else {
    if (!estimation::ParseMotionSource(requested, &choice.source)) {
      throw InputError("--motion: unknown source '" + requested + "' (auto, imu, odometry, constant-velocity, static)");
    }
    if (choice.source == estimation::MotionSource::kImu && !imu) {
      throw InputError("--motion imu: the dataset has no IMU data (imu.csv absent or empty); use --motion " +
                       std::string(odometry ? "odometry" : "constant-velocity") + " or leave --motion out");
    }
    if (choice.source == estimation::MotionSource::kWheelOdometry && !odometry) {
      throw InputError(
          "--motion odometry: the dataset has no wheel odometry (odometry.csv absent or empty); use "
          "--motion " +
          std::string(imu ? "imu" : "constant-velocity") + " or leave --motion out");
    }
    choice.reason = "--motion " + requested;
  }
  choice.name = Name(choice.source);
  return choice;
}

}  // namespace unimap::cli
