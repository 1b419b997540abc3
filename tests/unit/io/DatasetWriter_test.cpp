#include "io/DatasetWriter.hpp"

#include <set>
#include <string>

#include <gtest/gtest.h>

#include "DatasetTestData.hpp"
#include "io/DatasetReader.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

DatasetMetadata Meta() {
  DatasetMetadata m;
  m.source = "test";
  m.payload = "rotating_2d";
  return m;
}

std::set<std::string> FilesIn(const std::filesystem::path& folder) {
  std::set<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    names.insert(entry.path().filename().string());
  }
  return names;
}

ImuSample Imu(double t) {
  ImuSample s;
  s.time_s = t;
  return s;
}

RawScan Raw(double start, double end) {
  RawScan raw;
  raw.start_time_s = start;
  raw.end_time_s = end;
  return raw;
}

// The message of the InputError `write` throws.
template <typename Write>
std::string ErrorOf(Write write) {
  try {
    write();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return {};
}

TEST(DatasetWriter, EachStreamGoingBackwardsIsRejectedNamingTheStream) {
  test::ScratchFolder folder;
  DatasetWriter writer(folder.path(), Meta());
  writer.WriteImu(Imu(2.0));
  writer.WriteImu(Imu(2.0));  // equal times are fine
  EXPECT_NE(ErrorOf([&] { writer.WriteImu(Imu(1.0)); }).find("imu.csv: time goes backwards"), std::string::npos);
  writer.WriteEncoder({5.0, 0.0});
  EXPECT_NE(ErrorOf([&] { writer.WriteEncoder({4.0, 0.0}); }).find("encoder.csv"), std::string::npos);
  OdometrySample odometry;
  odometry.time_s = 3.0;
  writer.WriteOdometry(odometry);
  odometry.time_s = 2.5;
  EXPECT_NE(ErrorOf([&] { writer.WriteOdometry(odometry); }).find("odometry.csv"), std::string::npos);
  writer.WriteScan(Raw(0.5, 1.0));
  // Scans are ordered by their end time: this one starts later but ends earlier.
  EXPECT_NE(ErrorOf([&] { writer.WriteScan(Raw(0.8, 0.9)); }).find("scans.bin"), std::string::npos);
  StampedPose truth;
  truth.time_s = 1.0;
  writer.WriteGroundTruth(truth);
  truth.time_s = 0.0;
  EXPECT_NE(ErrorOf([&] { writer.WriteGroundTruth(truth); }).find("groundtruth.tum"), std::string::npos);
  EXPECT_NE(ErrorOf([&] { writer.WriteImu(Imu(std::nan(""))); }).find("not finite"), std::string::npos);
  writer.WriteImu(Imu(3.0));  // the writer is still usable; rejected items were not written
  writer.Finish();

  DatasetReader reader(folder.path());
  int imu = 0;
  while (reader.NextImu()) ++imu;
  EXPECT_EQ(imu, 3);
  EXPECT_EQ(reader.metadata().duration_s, 5.0 - 0.5);  // span of every stream
}

TEST(DatasetWriter, MalformedItemsAreRejected) {
  test::ScratchFolder folder;
  DatasetWriter writer(folder.path(), Meta());
  LineScan line;
  line.ranges_m = {1.0f, 2.0f};
  line.intensities = {1.0f};
  EXPECT_THROW(writer.WriteScan(line), InputError);           // intensities: none or one per beam
  EXPECT_THROW(writer.WriteScan(Raw(2.0, 1.0)), InputError);  // ends before it starts
  EXPECT_THROW(writer.WriteScan(Raw(std::nan(""), 1.0)), InputError);
  OdometrySample odometry;
  odometry.T_odom_body.linear() *= 2.0;  // not a rotation
  EXPECT_THROW(writer.WriteOdometry(odometry), InputError);
  StampedPose truth;
  truth.T_map_body.translation().x() = std::numeric_limits<double>::infinity();
  EXPECT_THROW(writer.WriteGroundTruth(truth), InputError);
}

TEST(DatasetWriter, UnfinishedWriterLeavesNothing) {
  test::ScratchFolder folder;
  {
    DatasetWriter writer(folder.path(), Meta());
    writer.WriteImu(Imu(0.0));
    writer.WriteEncoder({0.0, 1.0});
    writer.WriteOdometry(OdometrySample{});
    writer.WriteScan(Raw(0.0, 0.1));
    writer.WriteGroundTruth(StampedPose{});
    EXPECT_EQ(FilesIn(folder.path()),
              (std::set<std::string>{"imu.csv.partial", "encoder.csv.partial", "odometry.csv.partial",
                                     "scans.bin.partial", "groundtruth.tum.partial"}));
  }  // destroyed without Finish() (an error, a full disk): the .partial files go too
  EXPECT_EQ(FilesIn(folder.path()), std::set<std::string>{});
  try {
    DatasetReader reader(folder.path());
    FAIL() << "an unfinished dataset was opened";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("metadata.yaml"), std::string::npos) << e.what();
  }
}

TEST(DatasetWriter, FinishWritesTheStreamsGivenThenMetadataAndRefusesMore) {
  test::ScratchFolder folder;
  DatasetWriter writer(folder.path(), Meta());
  writer.WriteImu(Imu(1.0));
  writer.WriteScan(Raw(0.9, 1.0));
  writer.Finish();
  EXPECT_EQ(FilesIn(folder.path()), (std::set<std::string>{"imu.csv", "scans.bin", "metadata.yaml"}));
  EXPECT_THROW(writer.WriteImu(Imu(2.0)), InputError);
  EXPECT_THROW(writer.Finish(), InputError);
  const std::string imu = test::ReadText(folder / "imu.csv");
  EXPECT_EQ(imu, "# time_s ax_m_s2 ay_m_s2 az_m_s2 gx_rad_s gy_rad_s gz_rad_s\n1 0 0 0 0 0 0\n");
  const std::string scans = test::ReadText(folder / "scans.bin");
  ASSERT_GE(scans.size(), 17u);
  EXPECT_EQ(scans.substr(0, 12), std::string("UNIMAPSC\x01\x00\x00\x00", 12));
  EXPECT_EQ(scans[12], '\x02');             // RawScan
  EXPECT_EQ(scans.size(), 12u + 5u + 21u);  // header, record header, empty RawScan payload
}

TEST(DatasetWriter, RewritingAFolderRemovesTheOldDatasetsFiles) {
  test::ScratchFolder folder;
  {
    DatasetWriter writer(folder.path(), Meta());
    writer.WriteImu(Imu(0.0));
    writer.WriteGroundTruth(StampedPose{});
    writer.Finish();
  }
  {
    DatasetWriter writer(folder.path(), Meta());
    EXPECT_FALSE(std::filesystem::exists(folder / "metadata.yaml"));  // incomplete until Finish
    writer.WriteEncoder({0.0, 0.0});
    writer.Finish();
  }
  EXPECT_EQ(FilesIn(folder.path()), (std::set<std::string>{"encoder.csv", "metadata.yaml"}));
  DatasetReader reader(folder.path());
  EXPECT_FALSE(reader.has_groundtruth());
  EXPECT_FALSE(reader.NextImu().has_value());
  EXPECT_TRUE(reader.NextEncoder().has_value());
}

TEST(DatasetWriter, UnwritableFolderIsAnInputError) {
  test::ScratchFolder folder;
  test::WriteText(folder / "file", "x");
  EXPECT_THROW(DatasetWriter(folder / "file", Meta()), InputError);
}

}  // namespace
}  // namespace unimap::io
