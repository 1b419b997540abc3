#pragma once
// The loop closures of a mapping run as report.html draws them.
#include <cstddef>
#include <filesystem>

#include <nlohmann/json.hpp>

namespace unimap::report {

// Reads loop_closures.csv (written by `unimap run`: '#' comment lines, then
// one closure a line, "time_s scan_x scan_y scan_z submap_x submap_y
// submap_z": the closing 3D scan's position and the origin of the older
// submap it matched, map frame) and returns {"count", "xyz"}: a
// Float32Table of 6 columns (scan, then submap). Throws InputError naming
// the file and line for a malformed line.
nlohmann::ordered_json LoopClosureLayer(const std::filesystem::path& file, std::size_t* count);

}  // namespace unimap::report
