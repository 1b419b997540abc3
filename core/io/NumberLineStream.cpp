#include "io/NumberLineStream.hpp"

#include <cmath>
#include <string_view>

#include "io/NumberText.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

bool IsSpace(char c) { return c == ' ' || c == '\t'; }

// Text of a number for messages.
std::string Text(double value) {
  std::string out;
  AppendNumber(&out, value);
  return out;
}

}  // namespace

NumberLineStream::NumberLineStream(const std::filesystem::path& file, std::size_t columns)
    : lines_(file), columns_(columns) {}

void NumberLineStream::Fail(const std::string& reason) const {
  throw InputError(lines_.label() + ":" + std::to_string(lines_.line_number()) + ": " + reason);
}

void NumberLineStream::SetTimeLimits(double max_abs_time_s, double max_step_s) {
  max_abs_time_s_ = max_abs_time_s;
  max_step_s_ = max_step_s;
}

bool NumberLineStream::Next(double* values) {
  std::string_view line;
  for (;;) {
    if (!lines_.Next(&line)) return false;
    std::size_t first = 0;
    while (first < line.size() && IsSpace(line[first])) ++first;
    if (first < line.size() && line[first] != '#') break;  // a data row
  }
  std::size_t count = 0;
  std::size_t pos = 0;
  while (pos < line.size()) {
    while (pos < line.size() && IsSpace(line[pos])) ++pos;
    if (pos == line.size()) break;
    std::size_t end = pos;
    while (end < line.size() && !IsSpace(line[end])) ++end;
    const std::string_view field = line.substr(pos, end - pos);
    if (count == columns_) {
      Fail("expected " + std::to_string(columns_) + " numbers, found more");
    }
    if (!ParseNumber(field, &values[count])) {
      Fail("field " + std::to_string(count + 1) + " '" + std::string(field.substr(0, 40)) + "' is not a number");
    }
    ++count;
    pos = end;
  }
  if (count != columns_) {
    Fail("expected " + std::to_string(columns_) + " numbers, found " + std::to_string(count));
  }
  const double time_s = values[0];
  if (!std::isfinite(time_s)) Fail("time " + Text(time_s) + " is not finite");
  if (!(std::abs(time_s) <= max_abs_time_s_)) {
    Fail("time " + Text(time_s) + " s is beyond +-" + Text(max_abs_time_s_) + " s (not a plausible clock)");
  }
  if (has_last_ && time_s < last_time_s_) {
    Fail("time goes backwards: " + Text(time_s) + " s after " + Text(last_time_s_) + " s");
  }
  if (has_last_ && time_s - last_time_s_ > max_step_s_) {
    Fail("time jumps " + Text(time_s - last_time_s_) + " s ahead (" + Text(time_s) + " s after " + Text(last_time_s_) +
         " s), more than the " + Text(max_step_s_) +
         " s a sample may follow the previous one: a clock jump or lost data");
  }
  last_time_s_ = time_s;
  has_last_ = true;
  return true;
}

}  // namespace unimap::io
