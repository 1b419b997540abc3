#pragma once
#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

#include "calibration/CalibrationOptions.hpp"
#include "calibration/ExtrinsicCalibrator.hpp"

namespace unimap::calibration {

// A neighbourhood: returns of its centre's view measured against the plane of
// returns seen from other views (indices into the returns).
struct Neighbourhood {
  std::vector<std::uint32_t> measured;
  std::vector<std::uint32_t> plane;
};

// The neighbourhoods with the correction X, around an even subset of at most
// options.max_neighbourhoods returns: another view is one whose LiDAR was
// turned by min_view_angle_deg or moved by min_view_distance_m from the
// centre's; its returns (at least min_neighbours, at most max_neighbours)
// must lie on a plane (eigenvalue ratios, and an RMS distance from it of at
// most max_plane_sigmas sigma_m), and the centre's view's returns measured
// against it (at most max_measured) lie within gate_m of it.
std::vector<Neighbourhood> ChooseNeighbourhoods(const std::vector<CalibrationReturn>& returns,
                                                const Eigen::Isometry3d& X, const CalibrationOptions& options,
                                                double gate_m);

}  // namespace unimap::calibration
