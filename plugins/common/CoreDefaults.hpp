#pragma once
#include <string>

#include "unimap/CoreParameters.hpp"
#include "unimap/ParameterSet.hpp"

namespace unimap::payload {

// A payload's defaults for the paper's seven per-platform parameters (Table 1),
// each with the reason it suits the payload. AddTo appends the reason to the
// SDK's description of the key, so `unimap describe`-style listings explain
// why the platform uses that value.
struct CoreDefaults {
  CoreParameters values;       // N, M, I, sigma_a, sigma_g, resolution, max range
  std::string why_n;           // reason for scans_per_3d_scan
  std::string why_m;           // reason for scans_3d_per_submap
  std::string why_i;           // reason for scans_3d_per_optimization
  std::string why_sigma_a;     // reason for sigma_accel_m_s2
  std::string why_sigma_g;     // reason for sigma_gyro_rad_s
  std::string why_resolution;  // reason for distance_map_resolution_m
  std::string why_max_range;   // reason for distance_map_max_range_m

  // Adds the seven keys (CoreParameters::AddTo) with `values` as defaults and
  // "<SDK description>; <reason>" as descriptions.
  void AddTo(ParameterSet* set) const;
};

}  // namespace unimap::payload
