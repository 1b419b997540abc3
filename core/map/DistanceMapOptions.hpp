#pragma once
#include <cstddef>
#include <string>

#include "options/FieldVisitor.hpp"

namespace unimap::map {

// Parameters of the occupancy octree and of the distance map kept around the
// sensor. Resolution and max range come from the platform parameters.
struct DistanceMapOptions {
  // Edge of the cells far returns are kept in (voxels; odd, so a cell has a middle voxel).
  static constexpr int kCoarseCell = 3;

  double resolution_m = 0.1;                   // voxel edge of the octree and of the distance grid (m)
  double max_range_m = 15.0;                   // half-size of the box around the sensor that holds distances (m)
  double clamp_distance_m = 1.0;               // distances are exact up to this; farther lookups return it (m)
  double recenter_fraction = 0.25;             // start a new box when the sensor is farther than this
                                               // fraction of max_range_m from the box centre (per axis)
  bool follow_sensor = true;                   // false: the box moves only on DistanceMap::SetCenter
  double growth_margin_m = 0.5;                // slack added when the box grows to cover new obstacles (m)
  std::size_t max_edt_cells = 8000000;         // cell budget of one box; a larger box is shrunk
                                               // around its centre (~25 bytes per cell in the EDT)
  std::size_t max_occupied_voxels = 10000000;  // a loaded .bt map's occupied leaves may cover at most this
                                               // many voxels (each tracked, ~40 bytes: 400 MB); more is an
                                               // error (the simulated scenarios' maps hold a few 100,000)
  double max_insert_range_m = 30.0;            // rays are cut here; a longer return marks no obstacle (m)
  double coarse_beyond_m = 0.0;                // returns farther than this from the sensor are kept in cells of
                                               // kCoarseCell^3 voxels (one surface element per cell, at its
                                               // middle voxel); 0: every return in its own voxel (m)
  bool raycast_free_space = true;              // rays lower the occupancy of the voxels they cross
                                               // (removes vanished obstacles); false: returns only add
  bool clear_occupied_only = true;             // with raycast_free_space: rays only lower voxels that are
                                               // occupied now, creating no free-space nodes (~10x faster,
                                               // unknown and free stay alike); false: standard OctoMap
                                               // insertion (every voxel along every ray)
  bool discretize_rays = true;                 // cast one ray per hit voxel instead of one per point
  double prob_hit = 0.7;                       // occupancy probability of a voxel holding a return
  double prob_miss = 0.4;                      // occupancy probability of a voxel a ray passes through
  double occupancy_threshold = 0.5;            // voxels above this probability are obstacles
  double clamp_min_probability = 0.12;         // lower clamp of a voxel's occupancy probability
  double clamp_max_probability = 0.97;         // upper clamp of a voxel's occupancy probability
  bool compute_distances = true;               // false: only the octree is kept up to date (no distance transform,
                                               // empty fields) until DistanceMap::EnableDistances() (a growing submap)
  bool subvoxel_surfaces = true;               // distances are to the surface inside each occupied voxel
                                               // (mean and plane of its returns, see SurfacePoints; signed
  // behind it with signed_surfaces), instead of to the voxel centre (up to half a
  // voxel off); ~80 bytes per occupied voxel. Voxels without
  // returns (.bt priors) keep the centre
  bool signed_surfaces = true;  // with subvoxel_surfaces: distances are negative directly behind
                                // an oriented surface disk (interpolation crosses zero on it);
                                // false: magnitudes only (see SurfacePoints)
  bool cell_planes = false;     // with subvoxel_surfaces: fields also carry the plane of each
                                // cell's nearest surface element (CellPlanes, 4 bytes per cell),
                                // for GpfOptions::point_to_plane

  // Every field by name, for the platform file's `mapper:` section (SettingsOverrides).
  void VisitFields(options::FieldVisitor& v);
  // True when every field is in range; otherwise false with the reason
  // (naming the field) in *why when why is not null.
  bool IsValid(std::string* why) const;
};

}  // namespace unimap::map
