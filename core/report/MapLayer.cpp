#include "report/MapLayer.hpp"

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

#include "io/PcdPointLoader.hpp"
#include "io/PlyReader.hpp"
#include "report/Float32Table.hpp"
#include "unimap/Errors.hpp"

namespace unimap::report {
namespace {

// x y z and intensity (0 for PLY files) of every finite point.
std::vector<Eigen::Vector4f> LoadPoints(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  std::vector<Eigen::Vector4f> xyzi;
  if (ext == ".pcd") {
    io::LoadPcdXyzi(file, &xyzi);
  } else if (ext == ".ply") {
    for (const Eigen::Vector3f& p : io::ReadPlyVertices(file)) xyzi.emplace_back(p.x(), p.y(), p.z(), 0.0f);
  } else {
    throw InputError("map " + file.string() + ": unknown extension '" + ext + "' (expected .ply or .pcd)");
  }
  xyzi.erase(std::remove_if(xyzi.begin(), xyzi.end(), [](const Eigen::Vector4f& p) { return !p.allFinite(); }),
             xyzi.end());
  return xyzi;
}

}  // namespace

nlohmann::ordered_json MapLayer(const std::filesystem::path& file, std::size_t budget,
                                const std::optional<Eigen::Isometry3d>& T_world_map,
                                const SurfaceDistance& surface_distance, MapLayerCounts* counts) {
  const std::vector<Eigen::Vector4f> points = LoadPoints(file);
  const std::vector<std::size_t> kept = Float32Table::Sample(points.size(), budget);
  Float32Table xyz(3), intensity(1), error(1);
  float lo = 0.0f, hi = 0.0f;
  for (std::size_t n = 0; n < kept.size(); ++n) {
    const Eigen::Vector4f& p = points[kept[n]];
    xyz.AddRow({p.x(), p.y(), p.z()});
    intensity.AddRow({p.w()});
    lo = n == 0 ? p.w() : std::min(lo, p.w());
    hi = n == 0 ? p.w() : std::max(hi, p.w());
  }
  MapLayerCounts c;
  c.total = points.size();
  c.shown = kept.size();
  c.intensity = hi > lo;
  std::string error_note;
  if (!surface_distance) {
    error_note = "no true world (simulated data only)";
  } else if (!T_world_map) {
    error_note = "no ground truth to align the map with";
  } else {
    for (const std::size_t i : kept) {
      const Eigen::Vector3d p_world = *T_world_map * points[i].head<3>().cast<double>();
      error.AddRow({surface_distance(p_world)});
    }
    c.error = true;
  }
  if (counts != nullptr) *counts = c;
  return {{"file", file.string()},
          {"total", c.total},
          {"shown", c.shown},
          {"xyz", xyz.Base64()},
          {"intensity", c.intensity ? nlohmann::ordered_json(intensity.Base64()) : nlohmann::ordered_json()},
          {"error", c.error ? nlohmann::ordered_json(error.Base64()) : nlohmann::ordered_json()},
          {"error_note", error_note}};
}

}  // namespace unimap::report
