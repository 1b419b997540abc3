#pragma once
// Internal to unimap_io: one pose as a TUM row "t x y z qx qy qz qw", shared
// by *.tum files and the dataset's odometry.csv / groundtruth.tum.
#include <string>

#include <Eigen/Geometry>

#include "io/NumberLineStream.hpp"

namespace unimap::io {

// Numbers per TUM row (time, position, quaternion qx qy qz qw).
constexpr std::size_t kTumColumns = 8;
// Largest accepted | |q| - 1 | of a quaternion read from a file.
constexpr double kTumQuaternionTolerance = 1e-3;

// Why a pose cannot be written as a TUM row (non-finite time or translation,
// a linear part that is not a rotation: |R^T R - I| > 1e-6 or det R < 0);
// empty when it can.
std::string TumPoseProblem(double time_s, const Eigen::Isometry3d& T_frame_body);

// Appends "t x y z qx qy qz qw\n" with every number in shortest round-trip
// text; the quaternion is Eigen's conversion of the rotation matrix.
void AppendTumRow(std::string* out, double time_s, const Eigen::Isometry3d& T_frame_body);

// The pose of the row values[1..7] ("x y z qx qy qz qw"), the quaternion
// normalised; calls rows.Fail() for a non-finite value or a quaternion whose
// norm is off by more than kTumQuaternionTolerance.
Eigen::Isometry3d TumRowPose(const double* values, const NumberLineStream& rows);

}  // namespace unimap::io
