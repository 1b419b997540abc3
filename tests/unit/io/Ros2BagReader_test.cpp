#include "io/Ros2BagReader.hpp"

#include <gtest/gtest.h>

#include "IoTestSupport.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "io/DatasetConversion.hpp"
#include "io/DatasetReader.hpp"
#include "io/RosbagReader.hpp"
#include "unimap/Errors.hpp"

#if UNIMAP_WITH_ROS2BAG
#include "Ros2BagTestWriter.hpp"
#endif

namespace unimap::io {
namespace {

namespace fs = std::filesystem;

// The nodding RPLIDAR recording: a rosbag2 folder (one .db3, metadata version 5).
const fs::path kNoddingBag = fs::path(UNIMAP_SHARED_DATA_DIR) / "nodding_rplidar";

#define SKIP_WITHOUT_ROS2BAG()                                          \
  if (!Ros2BagReader::Supported())                                      \
  GTEST_SKIP() << "built without UNIMAP_WITH_ROS2BAG (libsqlite3-dev, " \
                  "libfastcdr-dev)"
#define SKIP_WITHOUT_NODDING_BAG() \
  SKIP_WITHOUT_ROS2BAG();          \
  if (!fs::exists(kNoddingBag)) GTEST_SKIP() << "real data absent: " << kNoddingBag << " (../shared/data not present)"

// The what() of the InputError `statement` throws ("" if it throws none).
#define INPUT_ERROR_OF(statement)   \
  [&]() -> std::string {            \
    try {                           \
      statement;                    \
    } catch (const InputError& e) { \
      return e.what();              \
    }                               \
    return "";                      \
  }()

bool Contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

constexpr double kDeg = M_PI / 180.0;

TEST(Ros2BagReaderTest, WithoutSupportConstructionSaysSo) {
  if (Ros2BagReader::Supported()) GTEST_SKIP() << "this build reads ROS 2 bags (the error path is for builds without)";
  const std::string what = INPUT_ERROR_OF(Ros2BagReader reader(kNoddingBag));
  EXPECT_TRUE(Contains(what, "UNIMAP_WITH_ROS2BAG")) << what;
}

TEST(Ros2BagReaderTest, NoddingRplidarCountsBeamsAndAngles) {
  SKIP_WITHOUT_NODDING_BAG();
  RosbagReaderOptions options;
  options.angle_unit = AngleUnit::kDegrees;
  Ros2BagReader reader(kNoddingBag, options);
  ASSERT_EQ(reader.topics().size(), 2u);
  EXPECT_EQ(reader.selected().laser, "/scan");
  EXPECT_EQ(reader.selected().angle, "/lidar_servo_angle");
  EXPECT_EQ(reader.selected().cloud, "");
  for (const RosbagTopicInfo& t : reader.topics()) {
    if (t.topic == "/scan") {
      EXPECT_EQ(t.datatype, "sensor_msgs/msg/LaserScan");
      EXPECT_EQ(t.messages, 298u);
    } else {
      EXPECT_EQ(t.topic, "/lidar_servo_angle");
      EXPECT_EQ(t.datatype, "std_msgs/msg/Int32");
      EXPECT_EQ(t.messages, 1372u);
    }
  }
  std::size_t scans = 0, angles = 0, min_beams = 100000, max_beams = 0;
  double min_angle = 1e9, max_angle = -1e9, last_angle_time = 0.0;
  LineScan first_scan, last_scan;
  EncoderSample first_angle, last_angle;
  while (auto message = reader.Next()) {
    if (const auto* line = std::get_if<LineScan>(&message->data)) {
      if (scans == 0) first_scan = *line;
      last_scan = *line;
      ++scans;
      min_beams = std::min(min_beams, line->ranges_m.size());
      max_beams = std::max(max_beams, line->ranges_m.size());
      EXPECT_EQ(line->intensities.size(), line->ranges_m.size());
      EXPECT_EQ(line->angle_min_rad, 0.0);
      EXPECT_FLOAT_EQ(static_cast<float>(line->range_min_m), 0.05f);
      EXPECT_EQ(line->range_max_m, 10.0);
      EXPECT_EQ(line->time_increment_s, 0.0);
    } else {
      const auto& sample = std::get<EncoderSample>(message->data);
      if (angles == 0) first_angle = sample;
      last_angle = sample;
      ++angles;
      EXPECT_GE(sample.time_s, last_angle_time);  // receive times: in bag order
      last_angle_time = sample.time_s;
      min_angle = std::min(min_angle, sample.angle_rad);
      max_angle = std::max(max_angle, sample.angle_rad);
    }
  }
  EXPECT_EQ(scans, 295u);  // 298 LaserScans, 3 of them empty
  EXPECT_EQ(reader.stats().skipped.at("/scan: LaserScan without beams"), 3u);
  EXPECT_EQ(reader.stats().delivered.at("/scan"), 295u);
  EXPECT_EQ(angles, 1372u);
  EXPECT_EQ(min_beams, 504u);
  EXPECT_EQ(max_beams, 587u);
  // Scan headers: the scanner's uptime clock; angles: the bag's receive time.
  EXPECT_NEAR(first_scan.start_time_s, 634.027, 1e-9);
  EXPECT_EQ(first_scan.ranges_m.size(), 508u);
  EXPECT_NEAR(last_scan.start_time_s, 699.72, 1e-9);
  EXPECT_EQ(last_scan.ranges_m.size(), 512u);
  EXPECT_DOUBLE_EQ(first_angle.angle_rad, 89 * kDeg);
  EXPECT_NEAR(first_angle.time_s, 1748602824.940924080, 1e-6);
  EXPECT_DOUBLE_EQ(last_angle.angle_rad, 74 * kDeg);
  EXPECT_NEAR(last_angle.time_s, 1748602894.082947327, 1e-6);
  EXPECT_DOUBLE_EQ(min_angle, 60 * kDeg);
  EXPECT_DOUBLE_EQ(max_angle, 119 * kDeg);
}

TEST(Ros2BagReaderTest, NoddingRplidarAsALoneDb3AndItsErrors) {
  SKIP_WITHOUT_NODDING_BAG();
  RosbagReaderOptions options;
  options.angle_unit = AngleUnit::kRadians;
  options.topics.laser = "none";
  Ros2BagReader db3(kNoddingBag / "lidarServo_0.db3", options);  // no metadata: topics counted in the file
  ASSERT_EQ(db3.topics().size(), 2u);
  EXPECT_EQ(db3.topics()[0].messages + db3.topics()[1].messages, 298u + 1372u);
  auto first = db3.Next();
  ASSERT_TRUE(first.has_value());
  EXPECT_DOUBLE_EQ(std::get<EncoderSample>(first->data).angle_rad, 89.0);  // "rad": the number as it is

  const std::string no_unit = INPUT_ERROR_OF(Ros2BagReader reader(kNoddingBag));
  EXPECT_TRUE(Contains(no_unit, "--angle-unit deg|rad")) << no_unit;
  EXPECT_TRUE(Contains(no_unit, "/lidar_servo_angle")) << no_unit;
  RosbagReaderOptions absent;
  absent.topics.imu = "/imu";
  const std::string missing = INPUT_ERROR_OF(Ros2BagReader reader(kNoddingBag, absent));
  EXPECT_TRUE(Contains(missing, "no topic /imu")) << missing;
  EXPECT_TRUE(Contains(missing, "/scan (sensor_msgs/msg/LaserScan, 298)")) << missing;
  // The ROS 1 reader points at the ROS 2 one.
  const std::string ros1 = INPUT_ERROR_OF(RosbagReader reader(kNoddingBag));
  EXPECT_TRUE(Contains(ros1, "--format ros2")) << ros1;
}

TEST(Ros2BagReaderTest, NoddingRplidarConversion) {
  SKIP_WITHOUT_NODDING_BAG();
  test::ScratchFolder dir;
  ConversionOptions options;
  options.input = kNoddingBag;
  options.output = dir.path() / "nodding";
  options.rosbag.angle_unit = AngleUnit::kDegrees;
  const ConversionReport report = ConvertRos2Bag(options);
  EXPECT_EQ(report.payload, "rotating_2d");
  EXPECT_EQ(report.scans, 295u);
  EXPECT_EQ(report.encoder, 1372u);
  bool receive_time_noted = false;
  for (const std::string& note : report.notes) receive_time_noted |= Contains(note, "receive times");
  EXPECT_TRUE(receive_time_noted);
  DatasetReader dataset(options.output);
  EXPECT_EQ(dataset.metadata().source, "ros2bag");
  std::size_t encoder = 0;
  while (dataset.NextEncoder()) ++encoder;
  EXPECT_EQ(encoder, 1372u);
}

#if UNIMAP_WITH_ROS2BAG
using test::CdrBytes;
using test::Db3Writer;

std::vector<std::uint8_t> LaserScanCdr(std::int32_t sec, std::uint32_t nanosec, const std::vector<float>& ranges,
                                       const std::vector<float>& intensities) {
  return CdrBytes([&](test::Cdr& cdr) {
    test::WriteHeader(cdr, sec, nanosec);
    cdr << -1.5f << 1.5f << 0.25f << 0.001f << 0.1f << 0.05f << 30.0f << ranges << intensities;
  });
}

std::vector<std::uint8_t> ScalarCdr(const std::string& type, double value) {
  return CdrBytes([&](test::Cdr& cdr) {
    if (type == "std_msgs/msg/Int32") {
      cdr << static_cast<std::int32_t>(value);
    } else if (type == "std_msgs/msg/Float32") {
      cdr << static_cast<float>(value);
    } else {
      cdr << value;
    }
  });
}

// Every header-stamped type once or more, in one file.
void WriteAllTypesBag(const fs::path& file) {
  Db3Writer bag(file);
  const auto cloud = bag.AddTopic("/points", "sensor_msgs/msg/PointCloud2");
  const auto scan = bag.AddTopic("/scan", "sensor_msgs/msg/LaserScan");
  const auto imu = bag.AddTopic("/imu", "sensor_msgs/msg/Imu");
  const auto joints = bag.AddTopic("/joint_states", "sensor_msgs/msg/JointState");
  const auto odom = bag.AddTopic("/odom", "nav_msgs/msg/Odometry");
  const auto pose = bag.AddTopic("/pose", "geometry_msgs/msg/PoseStamped");
  bag.Write(cloud, 10'000'000'000, CdrBytes([](test::Cdr& cdr) {
              test::WriteHeader(cdr, 10, 500'000'000);
              cdr << std::uint32_t{1} << std::uint32_t{3} << std::uint32_t{4};  // height, width, 4 fields
              const char* names[] = {"x", "y", "z", "intensity"};
              for (std::uint32_t k = 0; k < 4; ++k) {
                cdr << std::string(names[k]) << 4 * k << std::uint8_t{7} << std::uint32_t{1};  // FLOAT32
              }
              std::vector<std::uint8_t> data(48);
              for (int i = 0; i < 3; ++i) {
                const float f = static_cast<float>(i);
                const float point[4] = {1.0f + f, -2.0f * f, 0.5f, 10.0f * f};
                std::memcpy(&data[static_cast<std::size_t>(16 * i)], point, 16);
              }
              cdr << false << std::uint32_t{16} << std::uint32_t{48} << data << true;
            }));
  bag.Write(scan, 11'000'000'000, LaserScanCdr(11, 0, {1.0f, 2.5f, NAN}, {7.0f, 8.0f, 9.0f}));
  bag.Write(scan, 11'100'000'000, LaserScanCdr(11, 100'000'000, {}, {}));  // no beams: skipped
  bag.Write(imu, 12'000'000'000, CdrBytes([](test::Cdr& cdr) {
              test::WriteHeader(cdr, 0, 0);  // zero stamp: the receive time
              cdr << 0.0 << 0.0 << 0.0 << 1.0 << std::array<double, 9>{};
              cdr << 0.125 << -0.25 << 0.5 << std::array<double, 9>{};
              cdr << 1.0 << 2.0 << 9.81 << std::array<double, 9>{};
            }));
  for (const auto& [name, stamp] : {std::pair{"motor", 13}, {"other", 14}}) {
    bag.Write(joints, stamp * 1'000'000'000LL, CdrBytes([&, name = name, stamp = stamp](test::Cdr& cdr) {
                test::WriteHeader(cdr, stamp, 0);
                cdr << std::vector<std::string>{"tilt", name} << std::vector<double>{0.3, 1.25} << std::vector<double>{}
                    << std::vector<double>{};
              }));
  }
  // Odometry in big-endian CDR: the encapsulation header tells the reader.
  bag.Write(odom, 15'000'000'000,
            CdrBytes(
                [](test::Cdr& cdr) {
                  test::WriteHeader(cdr, 15, 0);
                  cdr << std::string("base_link");
                  test::WritePose(cdr, {1.0, 2.0, 3.0}, {0.0, 0.0, 1.0, 0.0});
                  cdr << std::array<double, 36>{} << 0.1 << 0.0 << 0.0 << 0.0 << 0.0 << 0.2 << std::array<double, 36>{};
                },
                test::Cdr::BIG_ENDIANNESS));
  bag.Write(pose, 16'000'000'000, CdrBytes([](test::Cdr& cdr) {
              test::WriteHeader(cdr, 16, 0);
              test::WritePose(cdr, {-4.0, 5.0, 0.0}, {0.0, 0.0, 0.0, 2.0});  // any norm: normalized
            }));
}

TEST(Ros2BagReaderTest, EveryMessageTypeConvertsExactly) {
  test::ScratchFolder dir;
  const fs::path file = dir / "all.db3";
  WriteAllTypesBag(file);
  RosbagReaderOptions options;
  options.topics.groundtruth = "/pose";
  options.joint_name = "motor";
  Ros2BagReader reader(file, options);
  EXPECT_EQ(reader.selected().cloud, "/points");
  EXPECT_EQ(reader.selected().odometry, "/odom");
  std::vector<RosbagMessage> messages;
  while (auto message = reader.Next()) messages.push_back(std::move(*message));
  ASSERT_EQ(messages.size(), 6u);

  const auto& cloud = std::get<RawScan>(messages[0].data);
  EXPECT_DOUBLE_EQ(messages[0].stamp_s, 10.5);
  ASSERT_EQ(cloud.points.size(), 3u);
  EXPECT_EQ(cloud.points[2].position_m, Eigen::Vector3d(3.0, -4.0, 0.5));
  EXPECT_FLOAT_EQ(cloud.points[2].intensity, 20.0f);
  EXPECT_FALSE(cloud.has_point_time);

  const auto& line = std::get<LineScan>(messages[1].data);
  EXPECT_EQ(line.start_time_s, 11.0);
  EXPECT_EQ(line.angle_min_rad, -1.5);
  EXPECT_EQ(line.angle_increment_rad, 0.25);
  EXPECT_EQ(line.time_increment_s, 0.001f);
  EXPECT_EQ(line.range_min_m, 0.05f);
  EXPECT_EQ(line.range_max_m, 30.0);
  ASSERT_EQ(line.ranges_m.size(), 3u);
  EXPECT_EQ(line.ranges_m[1], 2.5f);
  EXPECT_TRUE(std::isnan(line.ranges_m[2]));
  EXPECT_EQ(line.intensities, (std::vector<float>{7.0f, 8.0f, 9.0f}));
  EXPECT_EQ(reader.stats().skipped.at("/scan: LaserScan without beams"), 1u);

  const auto& imu = std::get<ImuSample>(messages[2].data);
  EXPECT_EQ(imu.time_s, 12.0);  // zero header stamp: the receive time
  EXPECT_EQ(imu.gyro_rad_s, Eigen::Vector3d(0.125, -0.25, 0.5));
  EXPECT_EQ(imu.accel_m_s2, Eigen::Vector3d(1.0, 2.0, 9.81));

  const auto& motor = std::get<EncoderSample>(messages[3].data);
  EXPECT_EQ(motor.time_s, 13.0);
  EXPECT_EQ(motor.angle_rad, 1.25);  // "motor", the second joint
  EXPECT_EQ(reader.stats().skipped.at("/joint_states: JointState without joint motor"), 1u);

  const auto& odometry = std::get<OdometrySample>(messages[4].data);
  EXPECT_EQ(odometry.time_s, 15.0);
  EXPECT_EQ(odometry.T_odom_body.translation(), Eigen::Vector3d(1.0, 2.0, 3.0));
  EXPECT_TRUE(
      odometry.T_odom_body.linear().isApprox(Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitZ()).toRotationMatrix()));

  const auto& truth = std::get<StampedPose>(messages[5].data);
  EXPECT_EQ(truth.time_s, 16.0);
  EXPECT_EQ(truth.T_map_body.translation(), Eigen::Vector3d(-4.0, 5.0, 0.0));
  EXPECT_TRUE(truth.T_map_body.linear().isIdentity());
}

TEST(Ros2BagReaderTest, ScalarAnglesInDegreesAndRadiansAtReceiveTime) {
  test::ScratchFolder dir;
  const fs::path file = dir / "angles.db3";
  const char* types[] = {"std_msgs/msg/Float32", "std_msgs/msg/Float64", "std_msgs/msg/Int32"};
  {
    Db3Writer bag(file);
    for (const char* type : types) {
      const auto id = bag.AddTopic(std::string("/") + (type + 13), type);  // "/Float32", ...
      bag.Write(id, 1'500'000'000 + id, ScalarCdr(type, 90.0));
      bag.Write(id, 2'500'000'000 + id, ScalarCdr(type, -45.0));
    }
  }
  for (const char* type : types) {
    for (const AngleUnit unit : {AngleUnit::kDegrees, AngleUnit::kRadians}) {
      RosbagReaderOptions options;
      options.topics.angle = std::string("/") + (type + 13);
      options.angle_unit = unit;
      Ros2BagReader reader(file, options);
      const double scale = unit == AngleUnit::kDegrees ? kDeg : 1.0;
      std::vector<EncoderSample> samples;
      while (auto message = reader.Next()) samples.push_back(std::get<EncoderSample>(message->data));
      ASSERT_EQ(samples.size(), 2u) << type;
      EXPECT_EQ(samples[0].angle_rad, 90.0 * scale) << type;
      EXPECT_EQ(samples[1].angle_rad, -45.0 * scale) << type;
      EXPECT_NEAR(samples[0].time_s, 1.5, 1e-8) << type;  // the receive time (+ the topic id in ns)
      EXPECT_NEAR(samples[1].time_s, 2.5, 1e-8) << type;
    }
  }
  // Several scalar topics: one must be chosen.
  RosbagReaderOptions unchosen;
  unchosen.angle_unit = AngleUnit::kDegrees;
  const std::string several = INPUT_ERROR_OF(Ros2BagReader reader(file, unchosen));
  EXPECT_TRUE(Contains(several, "--angle-topic")) << several;
}

TEST(Ros2BagReaderTest, SplitBagIsReadInTimestampOrder) {
  test::ScratchFolder dir;
  {
    // Interleaved times across the files; the topic has another id in each.
    Db3Writer first(dir / "split_0.db3");
    Db3Writer second(dir / "split_1.db3");
    const auto a = first.AddTopic("/angle", "std_msgs/msg/Float64");
    second.AddTopic("/other", "std_msgs/msg/Int32");
    const auto b = second.AddTopic("/angle", "std_msgs/msg/Float64");
    for (int k = 0; k < 6; ++k) {
      Db3Writer& file = k % 2 == 0 ? second : first;
      file.Write(k % 2 == 0 ? b : a, (k + 1) * 1'000'000'000LL, ScalarCdr("std_msgs/msg/Float64", k));
    }
  }
  test::WriteRos2Metadata(dir.path(), {"split_0.db3", "split_1.db3"},
                          {{"/angle", "std_msgs/msg/Float64", 6}, {"/other", "std_msgs/msg/Int32", 0}});
  RosbagReaderOptions options;
  options.topics.angle = "/angle";
  options.angle_unit = AngleUnit::kRadians;
  Ros2BagReader reader(dir.path(), options);
  std::vector<double> angles, times;
  while (auto message = reader.Next()) {
    angles.push_back(std::get<EncoderSample>(message->data).angle_rad);
    times.push_back(message->stamp_s);
  }
  EXPECT_EQ(angles, (std::vector<double>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(times, (std::vector<double>{1, 2, 3, 4, 5, 6}));
}

TEST(Ros2BagReaderTest, UnsupportedStorageAndDamagedFilesAreInputErrors) {
  test::ScratchFolder dir;
  const fs::path mcap = dir / "mcap";
  fs::create_directories(mcap);
  test::WriteRos2Metadata(mcap, {"bag_0.mcap"}, {}, "mcap");
  const std::string mcap_error = INPUT_ERROR_OF(Ros2BagReader reader(mcap));
  EXPECT_TRUE(Contains(mcap_error, (mcap / "metadata.yaml").string())) << mcap_error;
  EXPECT_TRUE(Contains(mcap_error, "storage_identifier mcap")) << mcap_error;
  EXPECT_TRUE(Contains(mcap_error, "sqlite3")) << mcap_error;
  EXPECT_TRUE(Contains(mcap_error, "ros2 bag convert")) << mcap_error;

  const fs::path zstd = dir / "zstd";
  fs::create_directories(zstd);
  { Db3Writer bag(zstd / "bag_0.db3"); }
  test::WriteRos2Metadata(zstd, {"bag_0.db3"}, {}, "sqlite3", "zstd", "file");
  const std::string zstd_error = INPUT_ERROR_OF(Ros2BagReader reader(zstd));
  EXPECT_TRUE(Contains(zstd_error, "compression_format zstd")) << zstd_error;
  EXPECT_TRUE(Contains(zstd_error, "uncompressed")) << zstd_error;
  EXPECT_TRUE(Contains(zstd_error, "ros2 bag convert")) << zstd_error;

  const fs::path missing = dir / "missing";
  fs::create_directories(missing);
  { Db3Writer bag(missing / "bag_0.db3"); }
  test::WriteRos2Metadata(missing, {"bag_0.db3", "bag_1.db3"}, {});
  const std::string missing_error = INPUT_ERROR_OF(Ros2BagReader reader(missing));
  EXPECT_TRUE(Contains(missing_error, (missing / "bag_1.db3").string())) << missing_error;
  EXPECT_TRUE(Contains(missing_error, "missing")) << missing_error;

  const fs::path garbage = dir / "garbage.db3";
  test::WriteText(garbage, std::string(4096, 'x'));
  const std::string garbage_error = INPUT_ERROR_OF(Ros2BagReader reader(garbage));
  EXPECT_TRUE(Contains(garbage_error, garbage.string())) << garbage_error;

  const fs::path json = dir / "json.db3";
  {
    Db3Writer bag(json);
    bag.AddTopic("/scan", "sensor_msgs/msg/LaserScan", "json");
  }
  const std::string json_error = INPUT_ERROR_OF(Ros2BagReader reader(json));
  EXPECT_TRUE(Contains(json_error, json.string() + ": topic /scan is serialized as 'json'; only cdr")) << json_error;
}

TEST(Ros2BagReaderTest, TruncatedMessagesNameFileTopicAndTime) {
  test::ScratchFolder dir;
  const fs::path file = dir / "cut.db3";
  {
    Db3Writer bag(file);
    const auto scan = bag.AddTopic("/scan", "sensor_msgs/msg/LaserScan");
    const auto angle = bag.AddTopic("/angle", "std_msgs/msg/Int32");
    bag.Write(scan, 1'000'000'000, LaserScanCdr(1, 0, {1.0f, 2.0f}, {}));
    std::vector<std::uint8_t> cut = LaserScanCdr(2, 0, {1.0f, 2.0f, 3.0f}, {});
    cut.resize(cut.size() - 6);  // the last range cut
    bag.Write(scan, 2'000'000'000, cut);
    bag.Write(angle, 3'000'000'000, {0, 1, 0, 0, 7});  // a 1-byte Int32
  }
  RosbagReaderOptions options;
  options.angle_unit = AngleUnit::kDegrees;
  options.topics.angle = "none";
  Ros2BagReader reader(file, options);
  ASSERT_TRUE(reader.Next().has_value());
  const std::string scan_error = INPUT_ERROR_OF(reader.Next());
  EXPECT_TRUE(Contains(scan_error, file.string() + ": /scan at t=2: truncated CDR message")) << scan_error;

  options.topics.laser = "none";
  options.topics.angle = "/angle";
  Ros2BagReader angles(file, options);
  const std::string angle_error = INPUT_ERROR_OF(angles.Next());
  EXPECT_TRUE(Contains(angle_error, file.string() + ": /angle at t=3: truncated CDR message")) << angle_error;
}

TEST(Ros2BagReaderTest, JointAndAngleTopicsTogetherAreAnError) {
  test::ScratchFolder dir;
  const fs::path file = dir / "both.db3";
  {
    Db3Writer bag(file);
    bag.AddTopic("/joint_states", "sensor_msgs/msg/JointState");
    bag.AddTopic("/angle", "std_msgs/msg/Float32");
  }
  RosbagReaderOptions options;
  options.angle_unit = AngleUnit::kRadians;
  const std::string both = INPUT_ERROR_OF(Ros2BagReader reader(file, options));
  EXPECT_TRUE(Contains(both, "--joint-topic none or --angle-topic none")) << both;
  options.topics.joint = "none";
  Ros2BagReader reader(file, options);
  EXPECT_EQ(reader.selected().angle, "/angle");
  EXPECT_FALSE(reader.Next().has_value());  // no messages
}
#endif

}  // namespace
}  // namespace unimap::io
