#include "io/RawInput.hpp"

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "IoTestSupport.hpp"
#include "io/DatasetReader.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

namespace fs = std::filesystem;

TEST(RawInputTest, RecognisesEachFormatConvertReads) {
  test::ScratchFolder folder;
  test::WriteText(folder / "run.bag", "not even a bag");
  test::WriteText(folder / "renamed", "#ROSBAG V2.0\nrest");
  test::WriteText(folder / "intel.clf", "FLASER 0\n");
  test::WriteText(folder / "intel.clf.bz2", "BZh");
  fs::create_directories(folder / "seq" / "velodyne");
  test::WriteText(folder / "seq" / "velodyne" / "000000.bin", "");
  fs::create_directories(folder / "flat");
  test::WriteText(folder / "flat" / "000003.pcd", "");
  fs::create_directories(folder / "bag2");
  test::WriteText(folder / "bag2" / "metadata.yaml", "rosbag2_bagfile_information:\n  version: 5\n");
  EXPECT_EQ(DetectRawInput(folder / "run.bag")->format, "rosbag");
  EXPECT_EQ(DetectRawInput(folder / "renamed")->format, "rosbag");
  EXPECT_EQ(DetectRawInput(folder / "intel.clf")->format, "carmen");
  EXPECT_EQ(DetectRawInput(folder / "intel.clf.bz2")->format, "carmen");
  EXPECT_EQ(DetectRawInput(folder / "seq")->format, "kitti");
  EXPECT_EQ(DetectRawInput(folder / "flat")->format, "kitti");
  EXPECT_EQ(DetectRawInput(folder / "bag2")->format, "ros2");
  // Not recordings: an empty folder, a text file, nothing at all.
  fs::create_directories(folder / "empty");
  test::WriteText(folder / "notes.txt", "hello");
  EXPECT_FALSE(DetectRawInput(folder / "empty").has_value());
  EXPECT_FALSE(DetectRawInput(folder / "notes.txt").has_value());
  EXPECT_FALSE(DetectRawInput(folder / "missing").has_value());
}

TEST(RawInputTest, TheDatasetReaderNamesTheConvertCommand) {
  test::ScratchFolder folder;
  fs::create_directories(folder / "seq");
  test::WriteText(folder / "seq" / "000000.bin", "");
  try {
    DatasetReader reader(folder / "seq");
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("is a KITTI sequence, not a dataset"), std::string::npos) << what;
    EXPECT_NE(what.find("unimap convert --format kitti --input " + (folder / "seq").string() + " --out DATASET"),
              std::string::npos)
        << what;
  }
  test::WriteText(folder / "notes.txt", "hello");
  try {
    DatasetReader reader(folder / "notes.txt");
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("a file, not a dataset folder"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace unimap::io
