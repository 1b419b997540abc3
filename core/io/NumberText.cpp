#include "io/NumberText.hpp"

#include <charconv>
#include <system_error>

namespace unimap::io {

void AppendNumber(std::string* out, double value) {
  char buffer[32];  // the longest shortest-round-trip double is 24 characters
  const std::to_chars_result result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  out->append(buffer, result.ptr);
}

bool ParseNumber(std::string_view field, double* value) {
  const char* begin = field.data();
  const char* end = field.data() + field.size();
  if (begin != end && *begin == '+') {
    ++begin;  // from_chars refuses an explicit '+'; "+-1" and "++1" stay invalid
    if (begin == end || *begin == '+' || *begin == '-') return false;
  }
  const std::from_chars_result result = std::from_chars(begin, end, *value);
  return result.ec == std::errc() && result.ptr == end;
}

std::string NumberString(double value) {
  std::string out;
  AppendNumber(&out, value);
  return out;
}

}  // namespace unimap::io
