#pragma once
// What frame each output file of a run is in (run.json "frames").
#include <filesystem>

#include "Json.hpp"

namespace unimap::cli {

// For every trajectory and map file present in out_dir, the transform or
// frame it holds, e.g. "trajectory.tum": "T_map_body ...". prior_map: the
// run localised in a given map (`unimap localize`), whose frame the map
// frame then is; otherwise the map frame is the body's at the first pose.
Json OutputFramesJson(const std::filesystem::path& out_dir, bool prior_map);

}  // namespace unimap::cli
