#include "io/PcdHeader.hpp"

#include <charconv>
#include <fstream>
#include <limits>
#include <sstream>

#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

constexpr std::size_t kMaxHeaderBytes = std::size_t{64} << 10;  // real headers take ~250 bytes
constexpr std::size_t kMaxFields = 4096;                        // far above any real cloud's
constexpr std::uint64_t kMaxCount = std::uint64_t{1} << 20;     // values per field per point
// LZF's best case: a 3-byte back reference expands to 264 bytes.
constexpr std::uint64_t kLzfMaxExpansion = 88;

struct HeaderParser {
  const std::string label;  // file name for messages
  std::int64_t line = 0;    // current header line

  [[noreturn]] void Fail(const std::string& reason) const {
    throw InputError(label + ":" + std::to_string(line) + ": " + reason);
  }

  std::uint64_t Whole(const std::string& word, const char* what) const {
    std::uint64_t value = 0;
    const char* end = word.data() + word.size();
    const std::from_chars_result r = std::from_chars(word.data(), end, value);
    if (word.empty() || r.ec != std::errc() || r.ptr != end) {
      Fail(std::string(what) + " '" + word.substr(0, 40) + "' is not a whole number");
    }
    return value;
  }

  // The words after the keyword; exactly `expected` of them unless 0.
  std::vector<std::string> Words(std::istringstream& in, std::size_t expected, const char* keyword) const {
    std::vector<std::string> words;
    for (std::string word; in >> word;) {
      if (words.size() == kMaxFields)
        Fail(std::string(keyword) + " has more than " + std::to_string(kMaxFields) + " entries");
      words.push_back(word);
    }
    if (expected != 0 && words.size() != expected) {
      Fail(std::string(keyword) + " has " + std::to_string(words.size()) + " entries for " + std::to_string(expected) +
           " fields");
    }
    if (words.empty()) Fail(std::string(keyword) + " has no value");
    return words;
  }
};

}  // namespace

const PcdField* PcdHeader::Find(const std::string& name) const {
  for (const PcdField& field : fields) {
    if (field.name == name) return &field;
  }
  return nullptr;
}

std::size_t PcdHeader::ValuesPerPoint() const {
  std::size_t values = 0;
  for (const PcdField& field : fields) values += field.count;
  return values;
}

PcdHeader ReadPcdHeader(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  HeaderParser parser{file.string()};
  if (!in) parser.Fail("cannot open");
  PcdHeader header;
  bool has_size = false, has_type = false, has_width = false, has_height = false, has_points = false;
  std::string text;
  while (header.data.empty()) {
    text.clear();
    for (int c = in.get(); c != '\n'; c = in.get()) {
      if (c == std::char_traits<char>::eof()) {
        ++parser.line;
        parser.Fail("the header ends without a DATA line");
      }
      if (header.data_offset + text.size() >= kMaxHeaderBytes) {
        parser.Fail("no DATA line within the first " + std::to_string(kMaxHeaderBytes) + " bytes (not a PCD file?)");
      }
      text.push_back(static_cast<char>(c));
    }
    ++parser.line;
    header.data_offset += text.size() + 1;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    std::istringstream words(text);
    std::string keyword;
    if (!(words >> keyword) || keyword[0] == '#') continue;
    const std::size_t n = header.fields.size();
    if (keyword == "VERSION" || keyword == "VIEWPOINT") {
      continue;
    } else if (keyword == "FIELDS") {
      if (n != 0) parser.Fail("FIELDS given twice");
      for (const std::string& name : parser.Words(words, 0, "FIELDS")) header.fields.push_back(PcdField{name});
    } else if (keyword == "SIZE" || keyword == "TYPE" || keyword == "COUNT") {
      if (n == 0) parser.Fail(keyword + " before FIELDS");
      const std::vector<std::string> values = parser.Words(words, n, keyword.c_str());
      for (std::size_t i = 0; i < n; ++i) {
        PcdField& field = header.fields[i];
        if (keyword == "SIZE") {
          field.size = parser.Whole(values[i], "SIZE");
          if (field.size != 1 && field.size != 2 && field.size != 4 && field.size != 8) {
            parser.Fail("SIZE of field " + field.name + " is " + values[i] + " (expected 1, 2, 4 or 8)");
          }
        } else if (keyword == "TYPE") {
          if (values[i] != "F" && values[i] != "I" && values[i] != "U") {
            parser.Fail("TYPE of field " + field.name + " is '" + values[i].substr(0, 40) + "' (expected F, I or U)");
          }
          field.type = values[i][0];
        } else {
          const std::uint64_t count = parser.Whole(values[i], "COUNT");
          if (count < 1 || count > kMaxCount) parser.Fail("COUNT of field " + field.name + " is " + values[i]);
          field.count = static_cast<std::size_t>(count);
        }
      }
      if (keyword == "SIZE") has_size = true;
      if (keyword == "TYPE") has_type = true;
    } else if (keyword == "WIDTH" || keyword == "HEIGHT" || keyword == "POINTS") {
      const std::uint64_t value = parser.Whole(parser.Words(words, 1, keyword.c_str())[0], keyword.c_str());
      (keyword == "WIDTH" ? header.width : keyword == "HEIGHT" ? header.height : header.points) = value;
      (keyword == "WIDTH" ? has_width : keyword == "HEIGHT" ? has_height : has_points) = true;
    } else if (keyword == "DATA") {
      const std::string kind = parser.Words(words, 1, "DATA")[0];
      if (kind != "ascii" && kind != "binary" && kind != "binary_compressed") {
        parser.Fail("DATA '" + kind.substr(0, 40) + "' (expected ascii, binary or binary_compressed)");
      }
      header.data = kind;
    } else {
      parser.Fail("unknown header line '" + text.substr(0, 40) + "'");
    }
  }
  header.data_line = parser.line;
  if (header.fields.empty()) parser.Fail("the header has no FIELDS line");
  if (!has_size || !has_type) parser.Fail("the header lacks a SIZE or TYPE line");
  if (!has_width) parser.Fail("the header has no WIDTH line");
  if (!has_height) header.height = 1;
  if (header.width != 0 && header.height > std::numeric_limits<std::uint64_t>::max() / header.width) {
    parser.Fail("WIDTH x HEIGHT overflows");
  }
  if (!has_points) header.points = header.width * header.height;
  if (header.points != header.width * header.height) {
    parser.Fail("POINTS " + std::to_string(header.points) +
                " is not WIDTH x HEIGHT = " + std::to_string(header.width * header.height));
  }
  for (PcdField& field : header.fields) {
    if (field.type == 'F' && field.size != 4 && field.size != 8) {
      parser.Fail("field " + field.name + " is a float of " + std::to_string(field.size) + " bytes (expected 4 or 8)");
    }
    field.offset = header.point_bytes;
    header.point_bytes += field.size * field.count;
  }
  return header;
}

void CheckPcdDataSize(const std::filesystem::path& file, const PcdHeader& header, std::uint64_t file_bytes) {
  const std::string name = file.string();
  const std::uint64_t left = file_bytes > header.data_offset ? file_bytes - header.data_offset : 0;
  const std::uint64_t points = header.points;
  const std::string announced = "the header announces " + std::to_string(points) + " points";
  if (header.data == "ascii") {
    if (points > left / 2) {  // every point takes at least a digit and a line end
      throw InputError(name + ": " + announced + ", the " + std::to_string(left) +
                       " bytes of ascii data after it cannot hold them");
    }
    return;
  }
  const std::uint64_t step = header.point_bytes;
  if (step != 0 && points > std::numeric_limits<std::uint64_t>::max() / step) {
    throw InputError(name + ": " + announced + " of " + std::to_string(step) + " bytes: the size overflows");
  }
  const std::uint64_t needed = points * step;
  if (header.data == "binary") {
    if (needed > left) {
      throw InputError(name + ": " + announced + " of " + std::to_string(step) + " bytes (" + std::to_string(needed) +
                       " bytes), only " + std::to_string(left) + " bytes follow the header");
    }
    return;
  }
  unsigned char sizes[8];
  std::ifstream in(file, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(header.data_offset));
  if (left < 8 || !in.read(reinterpret_cast<char*>(sizes), 8)) {
    throw InputError(name + ": binary_compressed data lacks its 8-byte size header");
  }
  const auto u32 = [&sizes](int at) {
    std::uint64_t v = 0;
    for (int b = 0; b < 4; ++b) v |= std::uint64_t{sizes[at + b]} << (8 * b);
    return v;
  };
  const std::uint64_t compressed = u32(0), uncompressed = u32(4);
  if (compressed > left - 8) {
    throw InputError(name + ": compressed block of " + std::to_string(compressed) + " bytes, only " +
                     std::to_string(left - 8) + " bytes follow");
  }
  if (uncompressed != needed) {
    throw InputError(name + ": " + announced + " of " + std::to_string(step) + " bytes (" + std::to_string(needed) +
                     " bytes), the compressed block expands to " + std::to_string(uncompressed));
  }
  if (needed > compressed * kLzfMaxExpansion) {
    throw InputError(name + ": " + announced + " (" + std::to_string(needed) + " bytes), more than a " +
                     std::to_string(compressed) + "-byte LZF block can expand to");
  }
}

}  // namespace unimap::io
