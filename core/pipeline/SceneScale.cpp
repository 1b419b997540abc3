#include "pipeline/SceneScale.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <variant>

#include "unimap/Errors.hpp"

namespace unimap::pipeline {

SceneScale MeasureSceneScale(const std::vector<io::ScanRecord>& scans) {
  std::vector<float> ranges;
  for (const io::ScanRecord& record : scans) {
    if (const auto* line = std::get_if<LineScan>(&record)) {
      for (const float r : line->ranges_m) {
        if (std::isfinite(r) && r > 0.0f && r >= line->range_min_m && r <= line->range_max_m) ranges.push_back(r);
      }
    } else {
      for (const Point& p : std::get<RawScan>(record).points) {
        const auto r = static_cast<float>(p.position_m.norm());
        if (std::isfinite(r) && r > 0.0f) ranges.push_back(r);
      }
    }
  }
  SceneScale scale;
  scale.returns = ranges.size();
  scale.scans = scans.size();
  if (ranges.empty()) return scale;
  const auto middle = ranges.begin() + static_cast<std::ptrdiff_t>(ranges.size() / 2);
  std::nth_element(ranges.begin(), middle, ranges.end());
  scale.median_range_m = *middle;
  return scale;
}

SceneScale ReadSceneScale(io::DatasetReader& reader, int scans) {
  std::vector<io::ScanRecord> first;
  try {
    while (static_cast<int>(first.size()) < scans) {
      std::optional<io::ScanRecord> scan = reader.NextScan();
      if (!scan) break;
      first.push_back(std::move(*scan));
    }
  } catch (const Error&) {
    // Measured from the scans before the bad record; the run reports it.
  }
  return MeasureSceneScale(first);
}

double SceneVoxel(double platform_voxel_m, double median_range_m, double max_voxels_across, double max_voxel_m) {
  if (!(median_range_m > 0.0) || !(platform_voxel_m > 0.0) || !(max_voxels_across > 0.0)) return platform_voxel_m;
  const double k_max = std::floor(max_voxel_m / platform_voxel_m + 1e-9);
  const double k = std::min(std::ceil(median_range_m / (max_voxels_across * platform_voxel_m) - 1e-9), k_max);
  if (!(k > 1.0)) return platform_voxel_m;
  // Rounded to a nanometre so that 3 x 0.1 m is the 0.3 m a platform file would write.
  return std::round(platform_voxel_m * k * 1e9) / 1e9;
}

}  // namespace unimap::pipeline
