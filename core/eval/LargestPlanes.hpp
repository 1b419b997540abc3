#pragma once
// A map's largest planes and how thick each is: the floor and walls of a room
// found by RANSAC, one after another, with the spread of the map's points
// across each (docs/evaluation.md, "Wall thickness"). A wall mapped from two
// poses that disagree is doubled and reads thick; one mapped consistently
// reads as thin as the returns' own noise.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace unimap::eval {

struct LargestPlanesOptions {
  int max_planes = 4;                     // planes found at most, largest first
  double inlier_distance_m = 0.05;        // RANSAC: a point within this distance of a candidate supports it (m)
  double band_m = 0.1;                    // points within this distance of a found plane are its points (m)
  double min_share = 0.05;                // a plane needs at least this share of the map's points
  double min_offset_m = 0.2;              // candidates passing closer than this to the map's origin (where the
                                          // first scan was taken) are not planes: a scan's own fan of rays
  int iterations = 400;                   // RANSAC candidates per plane
  std::size_t max_scored_points = 20000;  // candidates scored on an evenly strided subset of this size
  std::uint64_t seed = 1;                 // the candidates' sampling seed (deterministic)

  bool IsValid(std::string* why) const;
};

struct MapPlane {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit normal, offset_m >= 0 (points at the origin side)
  double offset_m = 0.0;        // n . x = offset_m on the plane: its distance from the map's origin (m)
  std::size_t points = 0;       // map points within band_m of it
  double thickness_m = 0.0;     // 1.4826 x the median |distance| of those points: a robust standard deviation
  double median_range_m = 0.0;  // median distance of those points from the map's origin (m)
};

// The largest planes of points_map, largest first: each the RANSAC candidate
// (passing at least min_offset_m from the origin) with the most points within
// inlier_distance_m, refitted to them (least squares), then removed with
// every point within band_m before the next.
// Stops at max_planes or at a plane with fewer than min_share of the points.
// Deterministic for the same points, order and options. Throws
// std::invalid_argument when the options are invalid.
std::vector<MapPlane> FindLargestPlanes(const std::vector<Eigen::Vector3f>& points_map,
                                        const LargestPlanesOptions& options = {});

}  // namespace unimap::eval
