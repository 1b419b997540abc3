#include "report/Float32Table.hpp"

#include <cstring>
#include <stdexcept>

#include "eval/Base64.hpp"

namespace unimap::report {

void Float32Table::AddRow(std::initializer_list<double> values) {
  if (values.size() != columns_) throw std::invalid_argument("Float32Table::AddRow: wrong number of values");
  for (const double v : values) values_.push_back(static_cast<float>(v));
}

std::string Float32Table::Base64() const {
  static_assert(sizeof(float) == 4, "float32 expected");
  static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "report.html reads little-endian float32");
  std::string bytes(values_.size() * sizeof(float), '\0');
  if (!values_.empty()) std::memcpy(bytes.data(), values_.data(), bytes.size());
  return eval::EncodeBase64(bytes);
}

std::vector<std::size_t> Float32Table::Sample(std::size_t n, std::size_t budget) {
  std::vector<std::size_t> indices;
  if (n == 0 || budget == 0) return indices;
  const std::size_t stride = (n + budget - 1) / budget;
  indices.reserve(n / stride + 1);
  for (std::size_t i = 0; i < n; i += stride) indices.push_back(i);
  return indices;
}

}  // namespace unimap::report
