#pragma once
// Internal to unimap_io: the one place that turns doubles into text and back
// for the dataset's text streams (imu.csv, encoder.csv, odometry.csv, *.tum).
#include <string>
#include <string_view>

namespace unimap::io {

// Appends the shortest decimal text that reads back as exactly `value`
// (std::to_chars; locale-independent; "nan", "inf", "-inf" for non-finite).
void AppendNumber(std::string* out, double value);
// The same text as a string (for messages).
std::string NumberString(double value);

// Reads one whole field as a double (std::from_chars, locale-independent; a
// leading '+' is accepted, subnormals are kept, "nan"/"inf" are accepted).
// Returns false, leaving *value unspecified, when the field is not entirely a
// number or overflows a double.
bool ParseNumber(std::string_view field, double* value);

}  // namespace unimap::io
