#include "eval/AtomicFile.hpp"

#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <unistd.h>

#include "unimap/Errors.hpp"

namespace unimap::eval {
namespace {

TEST(AtomicFileTest, WritesReplacesAndLeavesNoPartialFile) {
  const std::filesystem::path dir =
      std::filesystem::path(::testing::TempDir()) / ("unimap_atomic_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::filesystem::path file = dir / "x.bin";
  WriteFileAtomically(file, std::string("first\0bytes", 11));
  WriteFileAtomically(file, "second");
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "second");
  EXPECT_FALSE(std::filesystem::exists(dir / "x.bin.partial"));
  std::filesystem::remove_all(dir);
}

TEST(AtomicFileTest, UnwritableFolderThrowsNamingTheFile) {
  try {
    WriteFileAtomically("/nonexistent_unimap_folder/metrics.json", "{}");
    FAIL() << "expected Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent_unimap_folder/metrics.json"), std::string::npos);
  }
}

}  // namespace
}  // namespace unimap::eval
