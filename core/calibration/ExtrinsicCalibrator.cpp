#include "calibration/ExtrinsicCalibrator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "calibration/CrossViewPlane.hpp"
#include "calibration/LidarCorrection.hpp"
#include "calibration/Neighbourhoods.hpp"

namespace unimap::calibration {
namespace {

constexpr double kDegToRad = M_PI / 180.0;
// Rounds end when one moves the extrinsic by less than this many of its
// standard deviations on every axis: choosing the neighbourhoods anew from
// the same map changes the estimate by about one.
constexpr double kRoundSigmas = 3.0;

Eigen::Isometry3d WorldFromLidar(const CalibrationReturn& r) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = r.q_world_lidar.cast<double>().normalized().toRotationMatrix();
  T.translation() = r.t_world_lidar.cast<double>();
  return T;
}

std::vector<CrossViewPlane> Planes(const std::vector<CalibrationReturn>& returns,
                                   const std::vector<Neighbourhood>& neighbourhoods, const Eigen::Isometry3d& X) {
  const auto members = [&](const std::vector<std::uint32_t>& indices) {
    std::vector<CrossViewPlane::Member> m;
    m.reserve(indices.size());
    for (const std::uint32_t k : indices)
      m.push_back({returns[k].p_lidar.cast<double>(), WorldFromLidar(returns[k]) * X});
    return m;
  };
  std::vector<CrossViewPlane> planes;
  planes.reserve(neighbourhoods.size());
  for (const Neighbourhood& n : neighbourhoods) planes.emplace_back(members(n.measured), members(n.plane));
  return planes;
}

// The median of the measured returns' distances from their planes (m).
double MedianAbsoluteDistance(const std::vector<CalibrationReturn>& returns,
                              const std::vector<Neighbourhood>& neighbourhoods, const Eigen::Isometry3d& X,
                              double sigma_m) {
  std::vector<double> distances;
  for (const CrossViewPlane& p : Planes(returns, neighbourhoods, X)) {
    const Eigen::VectorXd r = p.Residuals(Vector6d::Zero(), p.normal(), sigma_m);
    for (Eigen::Index k = 0; k < r.size(); ++k) distances.push_back(sigma_m * std::abs(r(k)));
  }
  std::nth_element(distances.begin(), distances.begin() + static_cast<std::ptrdiff_t>(distances.size() / 2),
                   distances.end());
  return distances[distances.size() / 2];
}

// The data's information, scaled down when the distances are larger than
// sigma_m says (a reduced chi-square above 1).
// Negative eigenvalues (noise subtracted beyond the data's information) are 0.
Matrix6d DataInformation(const Matrix6d& observed, double chi2, std::size_t residuals) {
  const double dof = std::max(1.0, static_cast<double>(residuals) - 6.0);
  const Eigen::SelfAdjointEigenSolver<Matrix6d> eig(observed / std::max(1.0, chi2 / dof));
  return eig.eigenvectors() * eig.eigenvalues().cwiseMax(0.0).asDiagonal() * eig.eigenvectors().transpose();
}

// The correction's covariance: the data's information and the prior's.
Matrix6d Covariance(const Matrix6d& data, const Vector6d& prior_weight) {
  return (data + Matrix6d(prior_weight.asDiagonal())).inverse();
}

// Huber's cost of a whitened residual (r^2 inside, linear beyond k) and its weight (IRLS).
double Huber(double r, double k) { return std::abs(r) <= k ? r * r : 2.0 * k * std::abs(r) - k * k; }
double HuberWeight(double r, double k) { return std::abs(r) <= k ? 1.0 : k / std::abs(r); }

}  // namespace

ExtrinsicCalibrator::ExtrinsicCalibrator(const CalibrationOptions& options) : options_(options) {
  std::string why;
  if (!options_.IsValid(&why)) throw std::invalid_argument("CalibrationOptions: " + why);
}

std::vector<Eigen::Vector3f> ExtrinsicCalibrator::Assemble(const std::vector<CalibrationReturn>& returns,
                                                           const Eigen::Isometry3d& T_lidar_corrected) {
  const Eigen::Isometry3f X = T_lidar_corrected.cast<float>();
  std::vector<Eigen::Vector3f> world;
  world.reserve(returns.size());
  for (const CalibrationReturn& r : returns) world.push_back(r.q_world_lidar * (X * r.p_lidar) + r.t_world_lidar);
  return world;
}

CalibrationResult ExtrinsicCalibrator::Calibrate(const std::vector<CalibrationReturn>& returns) const {
  const CalibrationOptions& o = options_;
  CalibrationResult result;
  Vector6d prior_sigma;
  prior_sigma << Eigen::Vector3d::Constant(o.prior_sigma_translation_m),
      Eigen::Vector3d::Constant(o.prior_sigma_rotation_deg * kDegToRad);
  const Vector6d prior_weight = prior_sigma.cwiseInverse().cwiseAbs2();  // per axis, on the correction
  const auto whiten = [&](const Matrix6d& m) -> Matrix6d {
    return prior_sigma.asDiagonal() * m * prior_sigma.asDiagonal();
  };
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  Matrix6d information = Matrix6d::Zero();  // of the data at the last linearisation (J' W J)
  Matrix6d observed = Matrix6d::Zero();     // ... less what the planes' noise alone gives
  double chi2 = 0.0;                        // sum of w r^2 there
  double raw_chi2 = 0.0;                    // sum of r^2 there
  // Returns measured against a plane: all in the first round, then those
  // within 3 robust standard deviations of the last round's distances (at
  // least 3 sigma_m): a return beside the plane's patch (past an edge, on
  // another surface) is not a measurement of it.
  double gate_m = std::numeric_limits<double>::infinity();
  for (int round = 0; round < o.max_rounds; ++round) {
    const std::vector<Neighbourhood> neighbourhoods = ChooseNeighbourhoods(returns, X, o, gate_m);
    if (neighbourhoods.empty()) {
      result.failure = "no plane of " + std::to_string(o.min_neighbours) + " returns within " +
                       std::to_string(o.neighbourhood_radius_m) + " m is seen from two views (" +
                       std::to_string(returns.size()) + " returns): the scans do not see common surfaces";
      return result;
    }
    result.rounds = round + 1;
    result.neighbourhoods = neighbourhoods.size();
    const Eigen::Isometry3d round_start = X;
    bool steps_converged = false;
    for (int iteration = 0; iteration < o.max_iterations; ++iteration) {
      const std::vector<CrossViewPlane> planes = Planes(returns, neighbourhoods, X);
      Vector6d gradient = Vector6d::Zero();  // of sum Huber(r) / 2: J' W r
      information.setZero();
      Matrix6d noise = Matrix6d::Zero();
      chi2 = raw_chi2 = 0.0;
      result.residuals = 0;
      for (const CrossViewPlane& p : planes) {
        const Eigen::VectorXd r = p.Residuals(Vector6d::Zero(), p.normal(), o.sigma_m);
        const Eigen::Matrix<double, Eigen::Dynamic, 6> J = p.Jacobian(o.sigma_m);
        for (Eigen::Index k = 0; k < r.size(); ++k) {
          const double w = HuberWeight(r(k), o.huber_sigmas);
          gradient += w * r(k) * J.row(k).transpose();
          information += w * J.row(k).transpose() * J.row(k);
          chi2 += w * r(k) * r(k);
          raw_chi2 += r(k) * r(k);
        }
        noise += p.NormalNoiseInformation(o.sigma_m);
        result.residuals += static_cast<std::size_t>(r.size());
      }
      observed = information - noise;
      const double rms = o.sigma_m * std::sqrt(raw_chi2 / static_cast<double>(result.residuals));
      if (round == 0 && iteration == 0) result.rms_start_m = rms;
      result.rms_end_m = rms;
      // The objective: Huber of the distances plus the prior on the
      // accumulated correction (composition taken as addition, which holds
      // for the small corrections a platform file leaves); the normals held
      // (the Gauss-Newton model) or fitted again at D.
      const Vector6d offset = CorrectionLog(X);
      const auto objective = [&](const Vector6d& D, bool refit) {
        double sum = (offset + D).cwiseAbs2().dot(prior_weight);
        for (const CrossViewPlane& p : planes) {
          const Eigen::VectorXd r = p.Residuals(D, refit ? p.NormalAt(D) : p.normal(), o.sigma_m);
          for (Eigen::Index k = 0; k < r.size(); ++k) sum += Huber(r(k), o.huber_sigmas);
        }
        return sum;
      };
      const Vector6d g_total = gradient + prior_weight.cwiseProduct(offset);
      const Matrix6d h_total = information + Matrix6d(prior_weight.asDiagonal());
      // Steps only along the observed directions (data information at least
      // min_information_ratio times the prior's, in prior-sigma units).
      const Eigen::SelfAdjointEigenSolver<Matrix6d> eig(whiten(observed));
      std::vector<int> free;
      for (int k = 0; k < 6; ++k) {
        if (eig.eigenvalues()(k) >= o.min_information_ratio) free.push_back(k);
      }
      if (free.empty()) {
        steps_converged = true;  // nothing observable: the platform's extrinsic stays
        break;
      }
      Eigen::MatrixXd basis(6, static_cast<Eigen::Index>(free.size()));
      for (std::size_t c = 0; c < free.size(); ++c) {
        basis.col(static_cast<Eigen::Index>(c)) = prior_sigma.asDiagonal() * eig.eigenvectors().col(free[c]);
      }
      const Eigen::MatrixXd h_sub = basis.transpose() * h_total * basis;
      const Eigen::VectorXd g_sub = basis.transpose() * g_total;
      // Levenberg-Marquardt: damp until the step lowers the objective.
      const double f0 = objective(Vector6d::Zero(), true);
      double damping = 0.0;
      Vector6d step = Vector6d::Zero();
      for (int attempt = 0; attempt < 12; ++attempt) {
        Eigen::MatrixXd damped = h_sub;
        damped.diagonal() += damping * h_sub.diagonal();
        const Vector6d candidate = basis * damped.ldlt().solve(-g_sub);
        double f = candidate.allFinite() ? objective(candidate, true) : f0;
        if (f < f0) {
          step = candidate;
          // The model holds the normals, which turn with the step: it
          // overrates the curvature along directions that turn them (the
          // steps then shrink slowly), so the step is lengthened while the
          // objective keeps falling.
          for (double scale = 2.0; scale <= 64.0; scale *= 2.0) {
            const double longer = objective(scale * candidate, true);
            if (!(longer < f)) break;
            f = longer;
            step = scale * candidate;
          }
          break;
        }
        damping = damping == 0.0 ? 1e-3 : damping * 10.0;
      }
      X = X * CorrectionExp(step);
      result.iterations += 1;
      const Vector6d total = CorrectionLog(X);
      if (((total.array() / prior_sigma.array()).abs() > o.max_correction_sigmas).any()) {
        std::ostringstream why;
        why << "the views agree best " << (total.head<3>() * 1000.0).transpose() << " mm and "
            << (total.tail<3>() / kDegToRad).transpose() << " deg (rotation vector) from the platform's extrinsic, "
            << "beyond " << o.max_correction_sigmas << " times the prior's " << o.prior_sigma_translation_m << " m / "
            << o.prior_sigma_rotation_deg << " deg on some axis: the data do not determine the "
            << "extrinsic near the platform's (a map folded onto one plane agrees with itself everywhere)";
        result.failure = why.str();
        return result;
      }
      if (step.head<3>().norm() <= o.tolerance_translation_m &&
          step.tail<3>().norm() <= o.tolerance_rotation_deg * kDegToRad) {
        steps_converged = true;
        break;
      }
    }
    gate_m = std::max(3.0 * o.sigma_m, 3.0 * 1.4826 * MedianAbsoluteDistance(returns, neighbourhoods, X, o.sigma_m));
    const Vector6d moved = CorrectionLog(round_start.inverse() * X);
    const Vector6d sigma =
        Covariance(DataInformation(observed, chi2, result.residuals), prior_weight).diagonal().cwiseSqrt();
    if (steps_converged && (moved.array().abs() <= kRoundSigmas * sigma.array()).all()) {
      result.converged = true;
      break;
    }
  }
  result.ok = true;
  result.T_lidar_corrected = X;
  const Matrix6d data = DataInformation(observed, chi2, result.residuals);
  result.covariance = Covariance(data, prior_weight);
  const Eigen::SelfAdjointEigenSolver<Matrix6d> eig(whiten(data));
  result.information_ratio = eig.eigenvalues().cwiseMax(0.0);
  result.directions = eig.eigenvectors();
  for (int k = 0; k < 6; ++k) result.observable += result.information_ratio(k) >= o.min_information_ratio ? 1 : 0;
  return result;
}

}  // namespace unimap::calibration
