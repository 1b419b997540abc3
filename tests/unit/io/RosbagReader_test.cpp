#include "io/RosbagReader.hpp"

#include <gtest/gtest.h>

#include "IoTestSupport.hpp"

#include <cstring>
#include <filesystem>
#include <string>

#include "io/DatasetConversion.hpp"
#include "io/DatasetReader.hpp"
#include "unimap/Errors.hpp"

#if UNIMAP_WITH_ROSBAG
#include <rosbag/bag.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/JointState.h>
#include <sensor_msgs/LaserScan.h>
#include <sensor_msgs/PointCloud2.h>
#endif

namespace unimap::io {
namespace {

namespace fs = std::filesystem;

const fs::path kStageBag = fs::path(UNIMAP_SHARED_DATA_DIR) / "rosbag1_stage_laserscan.bag";

#define SKIP_WITHOUT_ROSBAG() \
  if (!RosbagReader::Supported()) GTEST_SKIP() << "built without UNIMAP_WITH_ROSBAG (librosbag-storage-dev absent)"
#define SKIP_WITHOUT_STAGE_BAG() \
  SKIP_WITHOUT_ROSBAG();         \
  if (!fs::exists(kStageBag)) GTEST_SKIP() << "real data absent: " << kStageBag << " (../shared/data not present)"

TEST(RosbagReaderTest, WithoutRosSupportConstructionSaysSo) {
  if (RosbagReader::Supported()) GTEST_SKIP() << "this build reads bags (the error path is for builds without)";
  try {
    RosbagReader reader(kStageBag);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("UNIMAP_WITH_ROSBAG"), std::string::npos) << e.what();
  }
}

TEST(RosbagReaderTest, StageBagCountsAndPerPointTimes) {
  SKIP_WITHOUT_STAGE_BAG();
  RosbagReader reader(kStageBag);
  ASSERT_EQ(reader.topics().size(), 3u);
  EXPECT_EQ(reader.selected().cloud, "/luminar_pointcloud");
  EXPECT_EQ(reader.selected().laser, "/base_scan");
  EXPECT_EQ(reader.selected().odometry, "/base_pose_ground_truth");
  EXPECT_EQ(reader.selected().imu, "");
  EXPECT_EQ(reader.selected().groundtruth, "");

  std::size_t clouds = 0, points = 0, lasers = 0, odometry = 0;
  while (auto message = reader.Next()) {
    if (const auto* scan = std::get_if<RawScan>(&message->data)) {
      ++clouds;
      points += scan->points.size();
      EXPECT_EQ(message->time_convention, PointTimeConvention::kSecondsAndNanoseconds);
      EXPECT_TRUE(scan->has_point_time);
      // The driver stamps a sweep at its last point; a sweep lasts < 0.1 s (10 Hz).
      EXPECT_NEAR(scan->end_time_s, message->stamp_s, 1e-6);
      EXPECT_GT(scan->start_time_s, message->stamp_s - 0.1);
      std::size_t outside = 0, ring1 = 0;
      for (const Point& p : scan->points) {
        if (p.time_s < scan->start_time_s || p.time_s > scan->end_time_s) ++outside;
        if (p.time_s < message->stamp_s - 0.1 || p.time_s > message->stamp_s + 1e-6) ++outside;
        if (p.ring == 1) ++ring1;
        EXPECT_LE(p.ring, 1);
      }
      EXPECT_EQ(outside, 0u);
      EXPECT_GT(ring1, 0u);  // two laser heads (laser_id 0 and 1)
    } else if (const auto* line = std::get_if<LineScan>(&message->data)) {
      ++lasers;
      EXPECT_EQ(line->ranges_m.size(), 90u);
      EXPECT_NEAR(line->angle_min_rad, -2.35619, 1e-5);
      EXPECT_EQ(line->intensities.size(), 90u);
    } else if (std::holds_alternative<OdometrySample>(message->data)) {
      ++odometry;
    }
  }
  EXPECT_EQ(clouds, 5u);
  EXPECT_EQ(points, 180822u);
  EXPECT_EQ(lasers, 5u);
  EXPECT_EQ(odometry, 5u);
  EXPECT_EQ(reader.stats().dropped_points, 0u);
  EXPECT_TRUE(reader.stats().skipped.empty());
}

TEST(RosbagReaderTest, TopicChoicesAndTheirErrors) {
  SKIP_WITHOUT_STAGE_BAG();
  {
    RosbagReaderOptions options;
    options.topics.groundtruth = "/base_pose_ground_truth";  // no longer auto-picked as odometry
    options.topics.cloud = "none";
    RosbagReader reader(kStageBag, options);
    EXPECT_EQ(reader.selected().odometry, "");
    std::size_t poses = 0, clouds = 0;
    while (auto message = reader.Next()) {
      poses += std::holds_alternative<StampedPose>(message->data) ? 1 : 0;
      clouds += std::holds_alternative<RawScan>(message->data) ? 1 : 0;
    }
    EXPECT_EQ(poses, 5u);
    EXPECT_EQ(clouds, 0u);
  }
  RosbagReaderOptions missing;
  missing.topics.imu = "/imu/data";
  try {
    RosbagReader reader(kStageBag, missing);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("no topic /imu/data"), std::string::npos) << what;
    EXPECT_NE(what.find("/luminar_pointcloud (sensor_msgs/PointCloud2, 5)"), std::string::npos) << what;
  }
  RosbagReaderOptions wrong_type;
  wrong_type.topics.cloud = "/base_scan";
  EXPECT_THROW(RosbagReader(kStageBag, wrong_type), InputError);
  EXPECT_THROW(RosbagReader(fs::path(UNIMAP_SOURCE_DIR) / "CMakeLists.txt"), InputError);  // not a bag
}

TEST(RosbagReaderTest, StageBagRoundTripThroughTheDatasetFormat) {
  SKIP_WITHOUT_STAGE_BAG();
  test::ScratchFolder dir;
  ConversionOptions options;
  options.input = kStageBag;
  options.output = dir.path() / "stage";
  const ConversionReport report = ConvertRosbag(options);
  EXPECT_EQ(report.payload, "fixed_3d");
  EXPECT_EQ(report.scans, 5u);
  EXPECT_EQ(report.odometry, 5u);
  EXPECT_EQ(report.skipped.at("/base_scan: second scan topic (not converted)"), 5u);

  DatasetReader reader(options.output);
  EXPECT_EQ(reader.metadata().source, "rosbag");
  std::size_t scans = 0, points = 0, odometry = 0;
  while (auto record = reader.NextScan()) {
    ++scans;
    points += std::get<RawScan>(*record).points.size();
  }
  while (reader.NextOdometry()) ++odometry;
  EXPECT_EQ(scans, 5u);
  EXPECT_EQ(points, 180822u);
  EXPECT_EQ(odometry, 5u);
}

#if UNIMAP_WITH_ROSBAG
// A bag written here with bz2 chunks: a cloud with a Velodyne-style float
// "time" (s after the stamp) and "ring", IMU samples and a two-joint
// JointState whose "motor" joint is the encoder.
void WriteBz2Bag(const fs::path& file) {
  rosbag::Bag bag(file.string(), rosbag::bagmode::Write);
  bag.setCompression(rosbag::compression::BZ2);
  bag.setChunkThreshold(256);  // several chunks
  for (int k = 0; k < 3; ++k) {
    const ros::Time stamp(100.0 + 0.1 * k);
    sensor_msgs::PointCloud2 cloud;
    cloud.header.stamp = stamp;
    cloud.height = 1;
    cloud.width = 4;
    cloud.point_step = 20;
    cloud.row_step = 80;
    for (auto [name, offset, type] :
         {std::tuple{"x", 0u, 7}, {"y", 4u, 7}, {"z", 8u, 7}, {"time", 12u, 7}, {"ring", 16u, 4}}) {
      sensor_msgs::PointField field;
      field.name = name;
      field.offset = offset;
      field.datatype = static_cast<std::uint8_t>(type);
      field.count = 1;
      cloud.fields.push_back(field);
    }
    cloud.data.resize(80);
    for (int i = 0; i < 4; ++i) {
      const float xyz_time[4] = {static_cast<float>(i), 1.0f, -1.0f, 0.025f * static_cast<float>(i)};
      const std::uint16_t ring = static_cast<std::uint16_t>(i);
      std::memcpy(&cloud.data[static_cast<std::size_t>(20 * i)], xyz_time, 16);
      std::memcpy(&cloud.data[static_cast<std::size_t>(20 * i + 16)], &ring, 2);
    }
    bag.write("/velodyne_points", stamp, cloud);
    for (int j = 0; j < 10; ++j) {
      sensor_msgs::Imu imu;
      imu.header.stamp = ros::Time(100.0 + 0.1 * k + 0.01 * j);
      imu.linear_acceleration.z = 9.81;
      imu.angular_velocity.x = 0.5 * j;
      bag.write("/imu", imu.header.stamp, imu);
    }
    sensor_msgs::JointState joints;
    joints.header.stamp = stamp;
    joints.name = {"tilt", "motor"};
    joints.position = {0.3, 1.0 + k};
    bag.write("/joint_states", stamp, joints);
  }
  bag.close();
}

TEST(RosbagReaderTest, Bz2BagWithRelativePointTimesImuAndEncoder) {
  test::ScratchFolder dir;
  const fs::path file = dir.path() / "rig.bag";
  WriteBz2Bag(file);
  RosbagReaderOptions options;
  options.joint_name = "motor";
  RosbagReader reader(file, options);
  EXPECT_EQ(reader.selected().cloud, "/velodyne_points");
  EXPECT_EQ(reader.selected().imu, "/imu");
  EXPECT_EQ(reader.selected().joint, "/joint_states");
  std::size_t clouds = 0, imu = 0, encoder = 0;
  while (auto message = reader.Next()) {
    if (const auto* scan = std::get_if<RawScan>(&message->data)) {
      const double stamp = 100.0 + 0.1 * static_cast<double>(clouds);
      EXPECT_EQ(message->time_convention, PointTimeConvention::kRelativeSeconds);
      ASSERT_EQ(scan->points.size(), 4u);
      EXPECT_NEAR(scan->start_time_s, stamp, 1e-9);
      EXPECT_NEAR(scan->points[3].time_s, stamp + 0.075, 1e-6);
      EXPECT_NEAR(scan->end_time_s, stamp + 0.075, 1e-6);
      EXPECT_EQ(scan->points[2].ring, 2);
      EXPECT_EQ(scan->points[3].position_m, Eigen::Vector3d(3.0, 1.0, -1.0));
      ++clouds;
    } else if (const auto* sample = std::get_if<ImuSample>(&message->data)) {
      EXPECT_DOUBLE_EQ(sample->accel_m_s2.z(), 9.81);
      EXPECT_DOUBLE_EQ(sample->gyro_rad_s.x(), 0.5 * static_cast<double>(imu % 10));
      ++imu;
    } else if (const auto* angle = std::get_if<EncoderSample>(&message->data)) {
      EXPECT_DOUBLE_EQ(angle->angle_rad, 1.0 + static_cast<double>(encoder));  // "motor", not the first joint
      EXPECT_NEAR(angle->time_s, 100.0 + 0.1 * static_cast<double>(encoder), 1e-9);
      ++encoder;
    }
  }
  EXPECT_EQ(clouds, 3u);
  EXPECT_EQ(imu, 30u);
  EXPECT_EQ(encoder, 3u);

  // Converted: a cloud with a motor encoder is the rotating 3D payload.
  ConversionOptions convert;
  convert.input = file;
  convert.output = dir.path() / "rig";
  convert.rosbag = options;
  const ConversionReport report = ConvertRosbag(convert);
  EXPECT_EQ(report.payload, "rotating_3d");
  EXPECT_EQ(report.scans, 3u);
  EXPECT_EQ(report.imu, 30u);
  EXPECT_EQ(report.encoder, 3u);
  DatasetReader dataset(convert.output);
  std::size_t written_imu = 0, written_encoder = 0;
  while (dataset.NextImu()) ++written_imu;
  while (dataset.NextEncoder()) ++written_encoder;
  EXPECT_EQ(written_imu, 30u);
  EXPECT_EQ(written_encoder, 3u);
}

// Adds delta to the 8-byte value of the first header field `name=` in the
// bag's bytes (index_pos in the bag header, chunk_pos in a chunk info).
void ShiftPosition(const fs::path& file, const std::string& name, std::uint64_t delta) {
  std::string bytes = test::ReadText(file);  // (binary-safe)
  const std::size_t at = bytes.find(name + "=");
  ASSERT_NE(at, std::string::npos) << name;
  std::uint64_t value = 0;
  std::memcpy(&value, &bytes[at + name.size() + 1], 8);  // little-endian, as the bag stores it
  value += delta;
  std::memcpy(&bytes[at + name.size() + 1], &value, 8);
  test::WriteText(file, bytes);
}

// The InputError that opening and reading `file` ends with ("" and a test
// failure when it reads without one).
std::string ReadError(const fs::path& file) {
  try {
    RosbagReader reader(file);
    while (reader.Next()) {
    }
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << file << ": no error";
  return "";
}

// Found by fuzzing (regressions/rosbag/oom-index-pos-inside-a-record.bag):
// librosbag reads a record wherever index_pos or a chunk_pos points and
// allocates the header length it finds there.
TEST(RosbagReaderTest, PositionsThatAreNoRecordStartAreErrors) {
  test::ScratchFolder dir;
  for (const std::string field : {"index_pos", "chunk_pos"}) {
    const fs::path file = dir.path() / (field + ".bag");
    WriteBz2Bag(file);
    ShiftPosition(file, field, 90);
    const std::string what = ReadError(file);
    EXPECT_NE(what.find(file.string()), std::string::npos) << what;
    EXPECT_NE(what.find("its " + field + " "), std::string::npos) << what;
    EXPECT_NE(what.find(field == "index_pos" ? "is not the start of a record" : "is not the start of a chunk"),
              std::string::npos)
        << what;
  }
}

// Found by fuzzing (regressions/rosbag/oom-index-count-past-its-data.bag):
// librosbag reads an index data's and a chunk info's `count` entries from
// the file, so a count larger than the record's data made it read the next
// "record" from inside an entry and allocate the 2.3 GB length it found.
// The first `count` field of the bag is an index data's (after the first
// chunk), the last one a chunk info's (at the end).
TEST(RosbagReaderTest, EntryCountsMustFillTheirRecord) {
  test::ScratchFolder dir;
  for (const bool last : {false, true}) {
    const fs::path file = dir.path() / (last ? "chunk-info.bag" : "index-data.bag");
    WriteBz2Bag(file);
    std::string bytes = test::ReadText(file);  // (binary-safe)
    // The field with its length (10: "count=" and a u32), not the bag
    // header's conn_count or chunk_count.
    const std::string field(
        "\x0a\x00\x00\x00"
        "count=",
        10);
    const std::size_t at = last ? bytes.rfind(field) : bytes.find(field);
    ASSERT_NE(at, std::string::npos);
    std::uint32_t count = 0;
    std::memcpy(&count, &bytes[at + field.size()], 4);
    const std::uint32_t more = count + 1;
    std::memcpy(&bytes[at + field.size()], &more, 4);
    test::WriteText(file, bytes);
    const std::string what = ReadError(file);
    EXPECT_NE(what.find(file.string()), std::string::npos) << what;
    const std::string expected = std::string(last ? "a chunk info" : "index data") + " announcing " +
                                 std::to_string(more) + " entries of " + (last ? "8" : "12") + " bytes in " +
                                 std::to_string(count * (last ? 8 : 12)) + " bytes of data";
    EXPECT_NE(what.find(expected), std::string::npos) << what;
  }
}

// Found by fuzzing: librosbag parses the records inside a chunk, and the
// header that is a connection record's data, with lengths unchecked (heap
// overflows in ros::Header::parse); they are walked like the file's
// records before it opens the bag.
TEST(RosbagReaderTest, RecordsInsideChunksAndConnectionHeadersAreChecked) {
  const fs::path regressions = fs::path(UNIMAP_SOURCE_DIR) / "tests/fuzz/regressions/rosbag";
  for (const auto& [file, expected] :
       {std::pair{"overflow-message-header-inside-a-chunk.bag",
                  "record at byte 9376: the chunk's record at offset 0: its connection: a header field runs past its "
                  "header"},
        std::pair{"overflow-connection-header-data.bag",
                  "record at byte 19351: its connection: a header field runs past its header"}}) {
    const std::string what = ReadError(regressions / file);
    EXPECT_NE(what.find(expected), std::string::npos) << what;
  }
}

// Found by fuzzing (regressions/rosbag/oom-laserscan-range-count.bag): ROS
// 1's generated deserializer resizes an array to the count it reads before
// it knows whether the bytes are there, so a LaserScan claiming 2^30 ranges
// allocated 4 GiB. The count is patched into a bag written by librosbag.
TEST(RosbagReaderTest, AnArrayCountPastTheMessageIsAnError) {
  test::ScratchFolder dir;
  const fs::path file = dir.path() / "scan.bag";
  {
    rosbag::Bag bag(file.string(), rosbag::bagmode::Write);
    sensor_msgs::LaserScan scan;
    scan.header.stamp = ros::Time(100.0);
    scan.angle_min = -1.0f;
    scan.angle_increment = 0.5f;
    scan.range_max = 30.0f;
    scan.ranges = {1.25f, 2.5f, 3.75f};
    bag.write("/scan", scan.header.stamp, scan);
  }
  RosbagReader intact(file);
  ASSERT_TRUE(intact.Next().has_value());

  std::string bytes = test::ReadText(file);  // (binary-safe)
  const std::uint32_t count = 3;
  const float ranges[3] = {1.25f, 2.5f, 3.75f};
  std::string pattern(4 + sizeof(ranges), '\0');
  std::memcpy(&pattern[0], &count, 4);
  std::memcpy(&pattern[4], ranges, sizeof(ranges));
  const std::size_t at = bytes.find(pattern);
  ASSERT_NE(at, std::string::npos);
  const std::uint32_t huge = 1u << 30;
  std::memcpy(&bytes[at], &huge, 4);
  test::WriteText(file, bytes);
  const std::string what = ReadError(file);
  EXPECT_NE(what.find(file.string()), std::string::npos) << what;
  EXPECT_NE(what.find("/scan message received at 100.000000 s: sensor_msgs/LaserScan message of "), std::string::npos)
      << what;
  EXPECT_NE(what.find("bytes is shorter than its definition"), std::string::npos) << what;
}
#endif

}  // namespace
}  // namespace unimap::io
