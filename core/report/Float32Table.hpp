#pragma once
// Rows of numbers packed as little-endian float32 and base64-encoded: how
// report.html carries map points, trajectories and plot series (about a
// third of the size of JSON numbers; decoded into a Float32Array).
#include <cstddef>
#include <initializer_list>
#include <string>
#include <vector>

namespace unimap::report {

class Float32Table {
 public:
  explicit Float32Table(std::size_t columns) : columns_(columns) {}

  // Appends one row; its size must equal columns() (std::invalid_argument otherwise).
  void AddRow(std::initializer_list<double> values);
  std::size_t columns() const { return columns_; }
  std::size_t rows() const { return columns_ == 0 ? 0 : values_.size() / columns_; }
  // The values row by row as float32 bytes, base64.
  std::string Base64() const;

  // Indices of about budget evenly spaced items of n: every k-th from 0,
  // k = ceil(n / budget) (all of them when n <= budget).
  static std::vector<std::size_t> Sample(std::size_t n, std::size_t budget);

 private:
  std::size_t columns_;
  std::vector<float> values_;
};

}  // namespace unimap::report
