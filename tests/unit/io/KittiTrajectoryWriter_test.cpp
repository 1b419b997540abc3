#include "io/KittiTrajectoryWriter.hpp"

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "IoTestSupport.hpp"
#include "io/KittiReader.hpp"
#include "io/NumberText.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

using test::ReadText;
using test::SameBits;
using test::ScratchFolder;

StampedPose Pose(double time_s, const Eigen::Vector3d& t, double roll, double pitch, double yaw) {
  StampedPose pose;
  pose.time_s = time_s;
  pose.T_map_body.linear() =
      (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
       Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
          .toRotationMatrix();
  pose.T_map_body.translation() = t;
  return pose;
}

// Deterministic poses with awkward numbers (thirds, large and tiny values).
std::vector<StampedPose> Poses() {
  std::vector<StampedPose> poses;
  for (int k = 0; k < 50; ++k) {
    const double a = 0.1 * k;
    poses.push_back(Pose(0.05 * k, Eigen::Vector3d(1.0 / 3.0 * k, -1e5 + k, 1e-7 * k), 0.3 * std::sin(a),
                         -0.2 * std::cos(a), 3.0 * a - 7.0));
  }
  return poses;
}

// The numbers of every line of text, parsed with the project's exact parser.
std::vector<std::vector<double>> Numbers(const std::string& text) {
  std::vector<std::vector<double>> rows;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream fields(line);
    std::string field;
    std::vector<double> row;
    while (fields >> field) {
      double value = 0.0;
      EXPECT_TRUE(ParseNumber(field, &value)) << field;
      row.push_back(value);
    }
    rows.push_back(row);
  }
  return rows;
}

TEST(KittiTrajectoryWriter, KnownPoseGivesTheRowMajorMatrix) {
  ScratchFolder dir;
  StampedPose pose;  // yaw +90 deg: R = [0 -1 0; 1 0 0; 0 0 1]
  pose.T_map_body.linear() << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  pose.T_map_body.translation() = Eigen::Vector3d(1.5, -2.0, 0.25);
  WriteKittiTrajectory(dir / "poses.txt", {StampedPose{}, pose});
  EXPECT_EQ(ReadText(dir / "poses.txt"), "1 0 0 0 0 1 0 0 0 0 1 0\n0 -1 0 1.5 1 0 0 -2 0 0 1 0.25\n");
  EXPECT_FALSE(std::filesystem::exists(dir / "poses.txt.partial"));
}

TEST(KittiTrajectoryWriter, RoundTripIsBitExactAndKittiReaderAgrees) {
  ScratchFolder dir;
  const std::vector<StampedPose> poses = Poses();
  WriteKittiTrajectory(dir / "poses.txt", poses);
  const std::vector<std::vector<double>> rows = Numbers(ReadText(dir / "poses.txt"));
  ASSERT_EQ(rows.size(), poses.size());
  for (std::size_t k = 0; k < poses.size(); ++k) {
    ASSERT_EQ(rows[k].size(), 12u) << "no time column: 12 numbers per line";
    for (Eigen::Index r = 0; r < 3; ++r) {
      for (Eigen::Index c = 0; c < 4; ++c) {
        ASSERT_TRUE(SameBits(rows[k][static_cast<std::size_t>(4 * r + c)], poses[k].T_map_body.matrix()(r, c)))
            << "pose " << k << " (" << r << ", " << c << ")";
      }
    }
  }
  // The KITTI reader re-orthonormalises, so agreement is to rounding only.
  const std::vector<Eigen::Isometry3d> read = KittiReader::ReadPoses(dir / "poses.txt");
  ASSERT_EQ(read.size(), poses.size());
  for (std::size_t k = 0; k < poses.size(); ++k) {
    EXPECT_TRUE(read[k].matrix().isApprox(poses[k].T_map_body.matrix(), 1e-12)) << "pose " << k;
  }
}

TEST(KittiTrajectoryWriter, EmptyTrajectoryIsAnEmptyFile) {
  ScratchFolder dir;
  WriteKittiTrajectory(dir / "poses.txt", {});
  EXPECT_EQ(ReadText(dir / "poses.txt"), "");
}

TEST(KittiTrajectoryWriter, BadPoseIsRejectedByIndexAndLeavesNoFile) {
  ScratchFolder dir;
  std::vector<StampedPose> poses = Poses();
  poses[4].T_map_body.linear() *= 2.0;  // not a rotation
  const std::filesystem::path file = dir / "poses.txt";
  try {
    WriteKittiTrajectory(file, poses);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(file.string() + ": pose 4: linear part is not a rotation"), std::string::npos) << what;
  }
  poses = Poses();
  poses[9].T_map_body.translation().x() = std::nan("");
  EXPECT_THROW(WriteKittiTrajectory(file, poses), InputError);
  EXPECT_FALSE(std::filesystem::exists(file));
  EXPECT_FALSE(std::filesystem::exists(dir / "poses.txt.partial"));
}

TEST(KittiTrajectoryWriter, UnwritableFolderIsAnInputErrorNamingTheFile) {
  ScratchFolder dir;
  const std::filesystem::path file = dir / "missing" / "poses.txt";
  try {
    WriteKittiTrajectory(file, Poses());
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace unimap::io
