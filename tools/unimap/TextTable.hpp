#pragma once
#include <algorithm>
#include <ostream>
#include <string>
#include <vector>

namespace unimap::cli {

// Left-aligned text columns for terminal output.
class TextTable {
 public:
  explicit TextTable(std::vector<std::string> header) : rows_{std::move(header)} {}
  // Appends a row (as many cells as the header).
  void AddRow(std::vector<std::string> row) { rows_.push_back(std::move(row)); }
  // Writes every row, each line starting with indent.
  void Print(std::ostream& out, const std::string& indent = "") const {
    std::vector<std::size_t> widths(rows_.front().size(), 0);
    for (const auto& row : rows_) {
      for (std::size_t c = 0; c < row.size() && c < widths.size(); ++c) {
        widths[c] = std::max(widths[c], row[c].size());
      }
    }
    for (const auto& row : rows_) {
      std::string line = indent;
      for (std::size_t c = 0; c < row.size(); ++c) {
        line += row[c];
        if (c + 1 < row.size()) line += std::string(widths[c] - row[c].size() + 2, ' ');
      }
      out << line << '\n';
    }
  }

 private:
  std::vector<std::vector<std::string>> rows_;
};

}  // namespace unimap::cli
