#include "io/ScanRecord.hpp"

namespace unimap::io {

double ScanEndTime(const ScanRecord& scan) {
  if (const auto* line = std::get_if<LineScan>(&scan)) {
    if (line->ranges_m.empty()) return line->start_time_s;
    // Same expression as LineScanToRawScan's end_time_s: t_0 + (n - 1) * dt.
    return line->start_time_s + line->time_increment_s * static_cast<double>(line->ranges_m.size() - 1);
  }
  return std::get<RawScan>(scan).end_time_s;
}

double ScanStartTime(const ScanRecord& scan) {
  if (const auto* line = std::get_if<LineScan>(&scan)) return line->start_time_s;
  return std::get<RawScan>(scan).start_time_s;
}

}  // namespace unimap::io
