#pragma once
// Shared by the tests of the dataset format (tests/unit/io): a scratch
// folder, deterministic random data with extreme values, bit comparisons.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "io/ScanRecord.hpp"

namespace unimap::io::test {

// A fresh folder under the system temp folder, removed with its contents.
class ScratchFolder {
 public:
  ScratchFolder() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() / ("unimap_io_" + std::string(info->test_suite_name()) + "_" +
                                                      info->name() + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchFolder() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

inline void WriteText(const std::filesystem::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary);
  out << text;
}

inline std::string ReadText(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Same IEEE-754 bit pattern (distinguishes -0 from 0, compares NaN payloads).
inline bool SameBits(double a, double b) { return std::memcmp(&a, &b, sizeof(a)) == 0; }
inline bool SameBits(float a, float b) { return std::memcmp(&a, &b, sizeof(a)) == 0; }

// Deterministic values, including the awkward ones a text format gets wrong.
class ValueSource {
 public:
  explicit ValueSource(std::uint32_t seed) : rng_(seed) {}

  // Finite doubles: specials (+-0, subnormals, extremes, 1/3) and random
  // mantissas across the whole exponent range.
  double Finite() {
    static const double kSpecial[] = {0.0,
                                      -0.0,
                                      std::numeric_limits<double>::denorm_min(),
                                      -std::numeric_limits<double>::denorm_min(),
                                      2.2250738585072009e-308,  // largest subnormal
                                      std::numeric_limits<double>::min(),
                                      std::numeric_limits<double>::max(),
                                      std::numeric_limits<double>::lowest(),
                                      std::numeric_limits<double>::epsilon(),
                                      1.0 / 3.0,
                                      -9.80665,
                                      1.7e9 + 0.123456789};
    std::uniform_int_distribution<int> pick(0, 2 * static_cast<int>(std::size(kSpecial)) - 1);
    const int k = pick(rng_);
    if (k < static_cast<int>(std::size(kSpecial))) return kSpecial[k];
    std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
    std::uniform_int_distribution<int> exponent(-1070, 1020);
    return std::ldexp(mantissa(rng_), exponent(rng_));
  }
  // Any double: finite ones plus +-infinity and NaN of both signs.
  double Any() {
    std::uniform_int_distribution<int> pick(0, 9);
    switch (pick(rng_)) {
      case 0:
        return std::numeric_limits<double>::infinity();
      case 1:
        return -std::numeric_limits<double>::infinity();
      default:
        return Finite();
    }
  }
  // A random float bit pattern (subnormals, -0, large values, NaN with a
  // payload); NaNs are made quiet so no hardware path may alter them.
  float AnyFloat() {
    std::uniform_int_distribution<std::uint32_t> bits;
    std::uint32_t b = bits(rng_);
    if ((b & 0x7f800000u) == 0x7f800000u) b |= 0x00400000u;
    float f = 0.0f;
    std::memcpy(&f, &b, sizeof(f));
    return f;
  }
  // Uniform in [lo, hi).
  double Uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  int Int(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  std::mt19937& rng() { return rng_; }

 private:
  std::mt19937 rng_;
};

}  // namespace unimap::io::test
