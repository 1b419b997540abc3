#pragma once
#include <variant>

#include "unimap/LineScan.hpp"
#include "unimap/RawScan.hpp"

namespace unimap::io {

// One scan as stored in a dataset: a 2D line (compact: ranges) or a 3D sweep (points).
using ScanRecord = std::variant<LineScan, RawScan>;

// Time the scan ends (last beam / latest point): scans are ordered by it.
double ScanEndTime(const ScanRecord& scan);

}  // namespace unimap::io
