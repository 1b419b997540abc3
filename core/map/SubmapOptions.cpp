#include "map/SubmapOptions.hpp"

namespace unimap::map {

bool SubmapOptions::IsValid(std::string* why) const {
  std::string reason;
  if (scans_3d_per_submap < 2) {
    reason = "scans_3d_per_submap must be >= 2 (got " + std::to_string(scans_3d_per_submap) + ")";
  } else if (!map.IsValid(&reason)) {
    reason = "map: " + reason;
  }
  if (why != nullptr) *why = reason;
  return reason.empty();
}

}  // namespace unimap::map
