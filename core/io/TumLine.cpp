#include "io/TumLine.hpp"

#include <cmath>

#include "io/NumberText.hpp"

namespace unimap::io {

std::string TumPoseProblem(double time_s, const Eigen::Isometry3d& T_frame_body) {
  if (!std::isfinite(time_s)) return "time is not finite";
  if (!T_frame_body.translation().allFinite()) return "translation is not finite";
  const Eigen::Matrix3d R = T_frame_body.linear();
  if (!R.allFinite()) return "rotation is not finite";
  const double orthogonality_error = (R.transpose() * R - Eigen::Matrix3d::Identity()).norm();
  if (orthogonality_error > 1e-6 || R.determinant() < 0.0) {
    return "linear part is not a rotation (|R^T R - I| = " + std::to_string(orthogonality_error) +
           ", det = " + std::to_string(R.determinant()) + ")";
  }
  return {};
}

void AppendTumRow(std::string* out, double time_s, const Eigen::Isometry3d& T_frame_body) {
  const Eigen::Quaterniond q(T_frame_body.linear());
  const Eigen::Vector3d& p = T_frame_body.translation();
  const double row[kTumColumns] = {time_s, p.x(), p.y(), p.z(), q.x(), q.y(), q.z(), q.w()};
  for (std::size_t i = 0; i < kTumColumns; ++i) {
    if (i > 0) out->push_back(' ');
    AppendNumber(out, row[i]);
  }
  out->push_back('\n');
}

Eigen::Isometry3d TumRowPose(const double* values, const NumberLineStream& rows) {
  for (std::size_t i = 1; i < kTumColumns; ++i) {
    if (!std::isfinite(values[i])) rows.Fail("field " + std::to_string(i + 1) + " is not finite");
  }
  // Eigen's Quaterniond constructor takes (w, x, y, z); the row is x y z w.
  Eigen::Quaterniond q(values[7], values[4], values[5], values[6]);
  const double norm = q.norm();
  if (std::abs(norm - 1.0) > kTumQuaternionTolerance) {
    std::string text;
    AppendNumber(&text, norm);
    rows.Fail("quaternion (qx qy qz qw) is not unit: |q| = " + text);
  }
  q.normalize();
  Eigen::Isometry3d T_frame_body = Eigen::Isometry3d::Identity();
  T_frame_body.linear() = q.toRotationMatrix();
  T_frame_body.translation() = Eigen::Vector3d(values[1], values[2], values[3]);
  return T_frame_body;
}

}  // namespace unimap::io
