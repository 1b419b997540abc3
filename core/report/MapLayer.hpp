#pragma once
// The map as report.html draws it: a budget of its points, their heights,
// intensities and errors against the true surfaces.
#include <cstddef>
#include <filesystem>
#include <optional>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "report/ReportOptions.hpp"

namespace unimap::report {

// What MapLayer drew.
struct MapLayerCounts {
  std::size_t total = 0;   // points in the file
  std::size_t shown = 0;   // points drawn (at most the budget)
  bool intensity = false;  // the file has intensities that vary
  bool error = false;      // points coloured by their error
};

// Reads a .ply or .pcd map, keeps every k-th point to fit budget (non-finite
// points dropped first) and returns {"file", "total", "shown", "xyz"
// (Float32Table, 3 columns), "intensity" (1 column, or null), "error" (1
// column in m, or null), "error_note"}. Errors are surface_distance of each
// point moved by T_world_map (both given). Throws InputError naming the file
// when it cannot be read.
nlohmann::ordered_json MapLayer(const std::filesystem::path& file, std::size_t budget,
                                const std::optional<Eigen::Isometry3d>& T_world_map,
                                const SurfaceDistance& surface_distance, MapLayerCounts* counts);

}  // namespace unimap::report
