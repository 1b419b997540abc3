#include "io/LiveStreamCheck.hpp"

#include <cmath>

#include "io/NumberText.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {

void LiveStreamCheck::Check(const std::filesystem::path& input, const DatasetLimits& limits, double time_s,
                            const std::string& problem) {
  ++count_;
  std::string why = problem;
  if (why.empty() && !(std::abs(time_s) <= limits.max_abs_time_s)) {
    why = "time " + NumberString(time_s) + " s is beyond +-" + NumberString(limits.max_abs_time_s) + " s";
  } else if (why.empty() && has_last_ && time_s - last_s_ > max_step_s_) {
    why = "time jumps by " + NumberString(time_s - last_s_) + " s after the previous item (more than " +
          NumberString(max_step_s_) + " s: a clock jump or lost data)";
  }
  if (!why.empty()) {
    throw InputError(input.string() + ": " + stream_ + " item " + std::to_string(count_) + " (time " +
                     NumberString(time_s) + " s): " + why);
  }
  last_s_ = time_s;
  has_last_ = true;
}

}  // namespace unimap::io
