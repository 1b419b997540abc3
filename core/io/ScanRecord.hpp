#pragma once
#include <variant>

#include "unimap/LineScan.hpp"
#include "unimap/RawScan.hpp"

namespace unimap::io {

// One scan as stored in a dataset: a 2D line (compact: ranges) or a 3D sweep (points).
using ScanRecord = std::variant<LineScan, RawScan>;

// Time the scan ends (last beam / latest point): scans are ordered by it.
// LineScan: start_time_s + (n - 1) * time_increment_s (start_time_s for no
// beams); RawScan: end_time_s.
double ScanEndTime(const ScanRecord& scan);
// Time the scan starts (beam 0 / first firing): start_time_s of either kind.
double ScanStartTime(const ScanRecord& scan);

}  // namespace unimap::io
