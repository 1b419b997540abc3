#include "io/TumTrajectory.hpp"

#include <string>

#include <gtest/gtest.h>

#include "DatasetTestData.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

std::vector<StampedPose> RandomTrajectory(std::uint32_t seed, int count) {
  test::ValueSource v(seed);
  std::vector<StampedPose> poses;
  double t = 1.3e9;
  for (int i = 0; i < count; ++i) {
    t += v.Uniform(0.0, 0.1);
    poses.push_back({t, test::RandomPose(v)});
  }
  return poses;
}

std::string ReadError(const test::ScratchFolder& folder, const std::string& text) {
  test::WriteText(folder / "t.tum", text);
  try {
    ReadTumTrajectory(folder / "t.tum");
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError for:\n" << text;
  return {};
}

TEST(TumTrajectory, RoundTripKeepsTimesAndPositionsBitExact) {
  test::ScratchFolder folder;
  const auto poses = RandomTrajectory(11, 500);
  WriteTumTrajectory(folder / "t.tum", poses);
  EXPECT_FALSE(std::filesystem::exists(folder / "t.tum.partial"));
  const auto read = ReadTumTrajectory(folder / "t.tum");
  ASSERT_EQ(read.size(), poses.size());
  for (std::size_t i = 0; i < poses.size(); ++i) {
    test::ExpectSamePose(poses[i].time_s, poses[i].T_map_body, read[i].time_s, read[i].T_map_body);
  }
}

TEST(TumTrajectory, ReadsCommentsBlankLinesAndQuaternionOrderXyzw) {
  test::ScratchFolder folder;
  // A 90 degree turn about z: q = (x, y, z, w) = (0, 0, sin 45, cos 45).
  test::WriteText(folder / "t.tum",
                  "# timestamp tx ty tz qx qy qz qw\n\n  1.5\t1 2 3 0 0 0.70710678118654752 "
                  "0.70710678118654752\r\n# end\n2.0 0 0 0 0 0 0 1.0005\n");
  const auto poses = ReadTumTrajectory(folder / "t.tum");
  ASSERT_EQ(poses.size(), 2u);
  EXPECT_EQ(poses[0].time_s, 1.5);
  EXPECT_EQ(poses[0].T_map_body.translation(), Eigen::Vector3d(1, 2, 3));
  const Eigen::Vector3d x_in_map = poses[0].T_map_body.linear() * Eigen::Vector3d::UnitX();
  EXPECT_NEAR((x_in_map - Eigen::Vector3d::UnitY()).norm(), 0.0, 1e-15);
  // |q| = 1.0005 is within the 1e-3 tolerance and normalised on reading.
  EXPECT_NEAR((poses[1].T_map_body.linear() - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-15);
}

TEST(TumTrajectory, BadLinesNameFileAndLine) {
  test::ScratchFolder folder;
  auto has = [](const std::string& error, const std::string& part) { return error.find(part) != std::string::npos; };
  EXPECT_TRUE(has(ReadError(folder, "# h\n1 0 0 0 0 0 0 1\n2 0 0 0 0 0 1\n"), "t.tum:3: expected 8 numbers, found 7"));
  EXPECT_TRUE(has(ReadError(folder, "1 0 0 0 0 0 0 1 9\n"), "t.tum:1: expected 8 numbers, found more"));
  EXPECT_TRUE(has(ReadError(folder, "1 0 0 zero 0 0 0 1\n"), "t.tum:1: field 4 'zero'"));
  EXPECT_TRUE(has(ReadError(folder, "1 0 0 0 0 0 0 1.01\n"), "t.tum:1: quaternion"));
  EXPECT_TRUE(has(ReadError(folder, "1 0 0 0 0 0 0 1\n0.5 0 0 0 0 0 0 1\n"), "t.tum:2: time goes backwards"));
  EXPECT_TRUE(has(ReadError(folder, "1 inf 0 0 0 0 0 1\n"), "t.tum:1: field 2 is not finite"));
  EXPECT_TRUE(has(ReadError(folder, "1 0 0 0 nan 0 0 1\n"), "t.tum:1: field 5 is not finite"));
  EXPECT_THROW(ReadTumTrajectory(folder / "missing.tum"), InputError);
}

TEST(TumTrajectory, WriterAppendsAndRenamesOnClose) {
  test::ScratchFolder folder;
  const auto poses = RandomTrajectory(12, 20);
  TumTrajectoryWriter writer(folder / "run.tum");
  for (const auto& pose : poses) writer.Write(pose);
  EXPECT_FALSE(std::filesystem::exists(folder / "run.tum"));
  EXPECT_TRUE(std::filesystem::exists(folder / "run.tum.partial"));
  StampedPose earlier = poses.back();
  earlier.time_s -= 1.0;
  EXPECT_THROW(writer.Write(earlier), InputError);
  StampedPose scaled = poses.back();
  scaled.T_map_body.linear() *= 1.1;
  EXPECT_THROW(writer.Write(scaled), InputError);
  writer.Close();
  EXPECT_THROW(writer.Write(poses.back()), InputError);
  EXPECT_THROW(writer.Close(), InputError);
  EXPECT_FALSE(std::filesystem::exists(folder / "run.tum.partial"));
  EXPECT_EQ(ReadTumTrajectory(folder / "run.tum").size(), poses.size());
}

TEST(TumTrajectory, WriterDestroyedOpenKeepsWhatItWrote) {
  test::ScratchFolder folder;
  {
    TumTrajectoryWriter writer(folder / "run.tum");
    writer.Write(StampedPose{});
  }
  EXPECT_EQ(ReadTumTrajectory(folder / "run.tum").size(), 1u);
}

TEST(TumTrajectory, RejectedTrajectoryLeavesNoFile) {
  test::ScratchFolder folder;
  auto poses = RandomTrajectory(13, 5);
  poses[3].time_s = poses[1].time_s - 1.0;
  EXPECT_THROW(WriteTumTrajectory(folder / "t.tum", poses), InputError);
  EXPECT_TRUE(std::filesystem::is_empty(folder.path()));
}

}  // namespace
}  // namespace unimap::io
