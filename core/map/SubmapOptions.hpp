#pragma once
#include <string>

#include "map/DistanceMapOptions.hpp"

namespace unimap::map {

// The paper's two-stage submap scheme (docs/design.md 1.4).
struct SubmapOptions {
  int scans_3d_per_submap = 20;  // M: 3D scans a submap receives before it is retired; a new
                                 // growing submap starts when the newest one holds M / 2
  DistanceMapOptions map;        // surface, occupancy and distance map of each live submap

  // True when every field is in range; otherwise false with the reason in *why.
  bool IsValid(std::string* why) const;
};

}  // namespace unimap::map
