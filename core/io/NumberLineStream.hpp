#pragma once
// Internal to unimap_io: the text streams of a dataset and TUM files.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include "io/LineReader.hpp"

namespace unimap::io {

// Rows of a fixed number of space-separated numbers, the first being a time
// in seconds. Blank lines and lines starting with '#' are skipped. Every
// error is an InputError reading "<file>:<line>: <reason>".
class NumberLineStream {
 public:
  // Opens the file; `columns` numbers per row (time included).
  NumberLineStream(const std::filesystem::path& file, std::size_t columns);

  // Reads the next row into values[0 .. columns); false at the end of the
  // file. Throws on a wrong number of fields, a field that is not a number, a
  // non-finite time, a time before the previous row's, or (SetTimeLimits) a
  // time beyond +-max_abs_time_s or more than max_step_s after the previous row's.
  bool Next(double* values);
  // Limits for the times of later rows (none by default).
  void SetTimeLimits(double max_abs_time_s, double max_step_s);
  // Throws InputError "<file>:<line of the last row>: <reason>".
  [[noreturn]] void Fail(const std::string& reason) const;
  // The file as named in errors.
  const std::string& label() const { return lines_.label(); }

 private:
  LineReader lines_;                  // the file, line by line
  std::size_t columns_;               // numbers per row
  double max_abs_time_s_ = HUGE_VAL;  // |time| of a row at most
  double max_step_s_ = HUGE_VAL;      // time after the previous row's at most
  double last_time_s_ = 0.0;          // time of the previous row
  bool has_last_ = false;             // a row was read already
};

}  // namespace unimap::io
