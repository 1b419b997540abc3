#pragma once
// Readable names and units for the keys of run.json and metrics.json.
#include <string>

namespace unimap::report {

// How one key is shown.
struct MetricLabel {
  std::string label;  // e.g. "ATE RMSE (SE(3)-aligned)"
  std::string unit;   // e.g. "m"; empty for counts, names and ratios
};

// A known key's label and unit; any other key is named after itself with
// its unit suffix turned into the unit ("map_entropy_mean_m" -> "Map
// entropy mean", "m"; suffixes _m, _s, _deg, _rad, _percent, _mb, _mib,
// _m_s, _m_s2, _rad_s, _deg_per_m, _hz, _rpm), so keys added later read well
// without code changes. A dotted key ("mapping.submaps") is named by its
// last part when that part is known, else after all of it.
MetricLabel LabelFor(const std::string& key);

}  // namespace unimap::report
