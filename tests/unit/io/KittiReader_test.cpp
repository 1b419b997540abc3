#include "io/KittiReader.hpp"

#include <gtest/gtest.h>

#include "IoTestSupport.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/DatasetConversion.hpp"
#include "io/DatasetReader.hpp"
#include "io/PcdPointLoader.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

using test::WriteText;

namespace fs = std::filesystem;

const fs::path kKitti = fs::path(UNIMAP_SHARED_DATA_DIR) / "kitti00";

#define SKIP_WITHOUT_KITTI()                                                           \
  if (!fs::exists(kKitti / "000000.pcd"))                                              \
    GTEST_SKIP() << "real data absent: " << kKitti << " (../shared/data not present)"; \
  if (!PcdSupported()) GTEST_SKIP() << "built without PCL: .pcd scans unsupported"

void WriteBin(const fs::path& file, const std::vector<float>& xyzi) {
  std::ofstream out(file, std::ios::binary);
  out.write(reinterpret_cast<const char*>(xyzi.data()), static_cast<std::streamsize>(xyzi.size() * sizeof(float)));
}

// A two-frame .bin sequence in the KITTI layout (velodyne/, times.txt,
// calib.txt, poses.txt). Tr turns LiDAR axes into camera axes exactly:
// x_cam = -y_lidar, y_cam = -z_lidar, z_cam = x_lidar (the KITTI convention
// without the small mounting offsets).
void WriteBinSequence(const fs::path& root) {
  fs::create_directories(root / "velodyne");
  WriteBin(root / "velodyne" / "000000.bin", {1.0f, 2.0f, 3.0f, 0.5f, -4.0f, 5.5f, -6.0f, 0.25f});
  WriteBin(root / "velodyne" / "000001.bin", {7.0f, 8.0f, 9.0f, 1.0f});
  WriteText(root / "times.txt", "0.000000e+00\n1.000000e-01\n");
  WriteText(root / "calib.txt",
            "P0: 1 0 0 0 0 1 0 0 0 0 1 0\n"
            "Tr: 0 -1 0 0 0 0 -1 0 1 0 0 0\n");
  // Frame 1: the camera moved 2 m along its z (forward) and yawed (about
  // camera -y = LiDAR +z) by 90 deg: R_cam = Ry(-90 deg).
  WriteText(root / "poses.txt",
            "1 0 0 0 0 1 0 0 0 0 1 0\n"
            "0 0 -1 0 0 1 0 0 1 0 0 2\n");
}

TEST(KittiReaderTest, BinSequenceReadsPointsTimesAndLidarPosesExactly) {
  test::ScratchFolder dir;
  WriteBinSequence(dir.path());
  KittiReader reader(dir.path());
  ASSERT_EQ(reader.size(), 2u);
  EXPECT_EQ(reader.calibration_source(), (dir.path() / "calib.txt").string());
  const KittiFrame frame0 = reader.Read(0);
  EXPECT_EQ(frame0.index, 0u);
  ASSERT_EQ(frame0.scan.points.size(), 2u);
  EXPECT_EQ(frame0.scan.points[1].position_m, Eigen::Vector3d(-4.0, 5.5, -6.0));
  EXPECT_FLOAT_EQ(frame0.scan.points[1].intensity, 0.25f);
  EXPECT_FALSE(frame0.scan.has_point_time);
  EXPECT_DOUBLE_EQ(frame0.scan.start_time_s, 0.0);
  EXPECT_DOUBLE_EQ(frame0.scan.end_time_s, 0.1);
  const KittiFrame frame1 = reader.Read(1);
  EXPECT_DOUBLE_EQ(frame1.scan.start_time_s, 0.1);

  ASSERT_TRUE(reader.has_poses());
  const std::vector<StampedPose>& poses = reader.lidar_poses();
  ASSERT_EQ(poses.size(), 2u);
  EXPECT_TRUE(poses[0].T_map_body.isApprox(Eigen::Isometry3d::Identity(), 1e-12));
  // T_lidar0_lidar1 = Tr^-1 T_cam0_cam1 Tr: 2 m along LiDAR x, yaw +90 deg about LiDAR z.
  EXPECT_TRUE(poses[1].T_map_body.translation().isApprox(Eigen::Vector3d(2.0, 0.0, 0.0), 1e-12))
      << poses[1].T_map_body.translation().transpose();
  const Eigen::Matrix3d yaw90 = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  EXPECT_TRUE(poses[1].T_map_body.linear().isApprox(yaw90, 1e-12)) << poses[1].T_map_body.linear();
  EXPECT_DOUBLE_EQ(poses[1].time_s, 0.1);

  // Next() walks the same frames in order.
  EXPECT_EQ(reader.Next()->scan.points.size(), 2u);
  EXPECT_EQ(reader.Next()->scan.points.size(), 1u);
  EXPECT_FALSE(reader.Next().has_value());
}

TEST(KittiReaderTest, DamagedSideFilesAndScansAreErrorsNamingTheFile) {
  test::ScratchFolder dir;
  WriteBinSequence(dir.path());
  WriteText(dir.path() / "poses.txt", "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 0 0 1 0 0 0 0 1\n");
  try {
    KittiReader reader(dir.path());
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("poses.txt:2:"), std::string::npos) << e.what();
  }
  // Fewer poses than frames.
  WriteText(dir.path() / "poses.txt", "1 0 0 0 0 1 0 0 0 0 1 0\n");
  EXPECT_THROW(KittiReader{dir.path()}, InputError);
  fs::remove(dir.path() / "poses.txt");

  // A .bin whose size is not whole points.
  WriteText(dir.path() / "velodyne" / "000001.bin", std::string(18, '\0'));
  KittiReader reader(dir.path());
  EXPECT_FALSE(reader.has_poses());
  EXPECT_THROW(reader.Read(1), InputError);
  EXPECT_THROW(KittiReader(dir.path() / "missing"), InputError);
}

TEST(KittiReaderTest, Sequence00PcdFramesAndPosesInTheLidarFrame) {
  SKIP_WITHOUT_KITTI();
  KittiReader reader(kKitti);
  ASSERT_EQ(reader.size(), 16u);  // frames 0-15
  EXPECT_EQ(reader.calibration_source(), "sequence 00 default Tr");
  const KittiFrame frame0 = reader.Read(0);
  EXPECT_EQ(frame0.scan.points.size(), 124668u);  // POINTS in 000000.pcd's header
  EXPECT_EQ(frame0.dropped_points, 0u);
  EXPECT_FALSE(frame0.scan.has_point_time);
  EXPECT_DOUBLE_EQ(frame0.scan.start_time_s, 0.0);
  const KittiFrame frame15 = reader.Read(15);
  EXPECT_EQ(frame15.index, 15u);
  EXPECT_DOUBLE_EQ(frame15.scan.start_time_s, 1.555212);  // times.txt line 16
  EXPECT_GT(frame15.scan.points.size(), 100000u);

  ASSERT_TRUE(reader.has_poses());
  const std::vector<StampedPose>& poses = reader.lidar_poses();
  ASSERT_EQ(poses.size(), 16u);
  // Frame 0's camera pose is the identity, so its LiDAR pose is too.
  EXPECT_TRUE(poses[0].T_map_body.isApprox(Eigen::Isometry3d::Identity(), 1e-6)) << poses[0].T_map_body.matrix();
  // The car drives ahead along LiDAR +x (camera +z), about 0.86 m per frame:
  // 15 frames put it ~12.9 m ahead, within 5 deg of +x (it drifts 0.7 m left).
  const Eigen::Vector3d t15 = poses[15].T_map_body.translation();
  EXPECT_GT(t15.x(), 0.86 * 15 * 0.9) << t15.transpose();
  EXPECT_LT(t15.x(), 0.86 * 15 * 1.1) << t15.transpose();
  const double tan5deg = std::tan(5.0 * M_PI / 180.0);
  EXPECT_LT(std::abs(t15.y()), tan5deg * t15.x()) << t15.transpose();
  EXPECT_LT(std::abs(t15.z()), tan5deg * t15.x()) << t15.transpose();
  // Camera +z maps to LiDAR +x: the heading stays within 5 deg of +x too.
  const Eigen::Vector3d forward = poses[15].T_map_body.linear() * Eigen::Vector3d::UnitX();
  EXPECT_GT(forward.x(), std::cos(5.0 * M_PI / 180.0)) << forward.transpose();
}

TEST(KittiReaderTest, Sequence00RoundTripThroughTheDatasetFormat) {
  SKIP_WITHOUT_KITTI();
  test::ScratchFolder dir;
  ConversionOptions options;
  options.input = kKitti;
  options.output = dir.path() / "kitti00";
  const ConversionReport report = ConvertKitti(options);
  EXPECT_EQ(report.scans, 16u);
  EXPECT_EQ(report.groundtruth, 16u);
  EXPECT_EQ(report.payload, "fixed_3d");

  KittiReader kitti(kKitti);
  DatasetReader reader(options.output);
  EXPECT_EQ(reader.metadata().source, "kitti");
  EXPECT_EQ(reader.metadata().payload, "fixed_3d");
  std::size_t scans = 0;
  while (auto record = reader.NextScan()) {
    const auto& scan = std::get<RawScan>(*record);
    EXPECT_FALSE(scan.has_point_time);
    if (scans == 0) {
      EXPECT_EQ(scan.points.size(), 124668u);
    }
    ++scans;
  }
  EXPECT_EQ(scans, 16u);
  ASSERT_TRUE(reader.has_groundtruth());
  std::size_t poses = 0;
  while (auto pose = reader.NextGroundTruth()) {
    EXPECT_TRUE(pose->T_map_body.isApprox(kitti.lidar_poses()[poses].T_map_body, 1e-9));
    ++poses;
  }
  EXPECT_EQ(poses, 16u);
}

}  // namespace
}  // namespace unimap::io
