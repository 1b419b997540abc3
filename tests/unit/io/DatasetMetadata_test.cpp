#include "io/DatasetMetadata.hpp"

#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "IoTestSupport.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

DatasetMetadata FullMetadata() {
  DatasetMetadata m;
  m.source = "unimap simulate";
  m.payload = "rotating_2d";
  m.scenario = "tunnel: \"quoted\", with # and \n newline";
  m.seed = std::numeric_limits<std::uint64_t>::max();
  m.duration_s = 900.0;  // a whole number: must stay a double
  m.imu_rate_hz = 200.0;
  m.encoder_rate_hz = 1.0 / 3.0;
  m.scan_rate_hz = 40.0;
  m.gravity_m_s2 = 9.80665;
  m.sigma_accel_m_s2 = std::numeric_limits<double>::denorm_min();
  m.sigma_gyro_rad_s = -0.0;
  m.accel_bias_walk_m_s2_sqrt_s = 1e-300;
  m.gyro_bias_walk_rad_s_sqrt_s = std::numeric_limits<double>::max();
  m.range_noise_m = 0.01;
  m.encoder_resolution_rad = std::numeric_limits<double>::infinity();
  ParameterMap& p = m.payload_parameters;
  p.Set("n", std::int64_t{40});
  p.Set("big", std::int64_t{-9223372036854775807LL - 1});
  p.Set("enabled", true);
  p.Set("mirrored", false);
  p.Set("rate_hz", 2.0);
  p.Set("tiny", 4.9406564584124654e-324);
  p.Set("name", std::string("hokuyo"));
  p.Set("looks_like_bool", std::string("true"));
  p.Set("looks_like_int", std::string("42"));
  p.Set("empty_text", std::string());
  p.Set("extrinsic.body_motor.rpy_deg", std::vector<double>{0.0, -0.0, 90.0});
  p.Set("extrinsic.body_motor.xyz_m", std::vector<double>{0.1, 1e-310, -2.5e8});
  p.Set("extrinsic.motor_lidar.xyz_m", std::vector<double>{});
  p.Set("extrinsic-other", 1.5);  // sorts between "extrinsic" and "extrinsic.*"
  p.Set("motor.axis.direction", std::int64_t{-1});
  return m;
}

void ExpectSame(const DatasetMetadata& a, const DatasetMetadata& b) {
  EXPECT_EQ(a.format_version, b.format_version);
  EXPECT_EQ(a.source, b.source);
  EXPECT_EQ(a.payload, b.payload);
  EXPECT_EQ(a.scenario, b.scenario);
  EXPECT_EQ(a.seed, b.seed);
  for (auto field : {&DatasetMetadata::duration_s, &DatasetMetadata::imu_rate_hz, &DatasetMetadata::encoder_rate_hz,
                     &DatasetMetadata::scan_rate_hz, &DatasetMetadata::gravity_m_s2, &DatasetMetadata::sigma_accel_m_s2,
                     &DatasetMetadata::sigma_gyro_rad_s, &DatasetMetadata::accel_bias_walk_m_s2_sqrt_s,
                     &DatasetMetadata::gyro_bias_walk_rad_s_sqrt_s, &DatasetMetadata::range_noise_m,
                     &DatasetMetadata::encoder_resolution_rad}) {
    EXPECT_TRUE(test::SameBits(a.*field, b.*field)) << a.*field << " vs " << b.*field;
  }
  EXPECT_EQ(a.payload_parameters, b.payload_parameters);
  for (const auto& [key, value] : a.payload_parameters.values()) {
    ASSERT_TRUE(b.payload_parameters.Contains(key)) << key;
    EXPECT_EQ(TypeName(value), TypeName(b.payload_parameters.At(key))) << key;
    if (const auto* list = std::get_if<std::vector<double>>(&value)) {
      const auto& other = std::get<std::vector<double>>(b.payload_parameters.At(key));
      for (std::size_t i = 0; i < list->size(); ++i) {
        EXPECT_TRUE(test::SameBits((*list)[i], other[i])) << key << "[" << i << "]";
      }
    }
  }
}

// The ConfigError a metadata text raises.
ConfigError LoadError(const test::ScratchFolder& folder, const std::string& text) {
  test::WriteText(folder / "metadata.yaml", text);
  try {
    LoadDatasetMetadata(folder / "metadata.yaml");
  } catch (const ConfigError& e) {
    return e;
  }
  ADD_FAILURE() << "no ConfigError for:\n" << text;
  return ConfigError("", 0, "", "none");
}

TEST(DatasetMetadata, EveryFieldAndParameterTypeRoundTripsBitExactly) {
  test::ScratchFolder folder;
  const DatasetMetadata written = FullMetadata();
  SaveDatasetMetadata(written, folder / "metadata.yaml");
  const DatasetMetadata read = LoadDatasetMetadata(folder / "metadata.yaml");
  ExpectSame(written, read);
  EXPECT_FALSE(std::filesystem::exists(folder / "metadata.yaml.partial"));
}

TEST(DatasetMetadata, KittiCameraFromLidarRoundTripsAndIsChecked) {
  test::ScratchFolder folder;
  DatasetMetadata m;
  m.payload = "fixed_3d";
  for (int k = 0; k < 12; ++k) m.camera_from_lidar.push_back(0.1 * k - 1.0 / 3.0);
  SaveDatasetMetadata(m, folder / "metadata.yaml");
  const DatasetMetadata read = LoadDatasetMetadata(folder / "metadata.yaml");
  ASSERT_EQ(read.camera_from_lidar.size(), 12u);
  for (std::size_t k = 0; k < 12; ++k) EXPECT_TRUE(test::SameBits(read.camera_from_lidar[k], m.camera_from_lidar[k]));
  // Without it the key is not written and reads back empty.
  DatasetMetadata plain;
  plain.payload = "fixed_3d";
  SaveDatasetMetadata(plain, folder / "metadata.yaml");
  EXPECT_EQ(test::ReadText(folder / "metadata.yaml").find("camera_from_lidar"), std::string::npos);
  EXPECT_TRUE(LoadDatasetMetadata(folder / "metadata.yaml").camera_from_lidar.empty());
  const ConfigError e = LoadError(folder, "format_version: 1\npayload: fixed_3d\ncamera_from_lidar: [1, 2, 3]\n");
  EXPECT_EQ(e.line(), 3);
  EXPECT_EQ(e.key(), "camera_from_lidar");
  m.camera_from_lidar.pop_back();
  EXPECT_THROW(SaveDatasetMetadata(m, folder / "metadata.yaml"), ConfigError);
}

TEST(DatasetMetadata, PayloadParametersAreNestedMaps) {
  test::ScratchFolder folder;
  DatasetMetadata m;
  m.payload = "rotating_2d";
  m.payload_parameters.Set("extrinsic.body_motor.xyz_m", std::vector<double>{1.0, 2.0, 3.0});
  m.payload_parameters.Set("extrinsic.body_motor.enabled", true);
  SaveDatasetMetadata(m, folder / "metadata.yaml");
  const std::string text = test::ReadText(folder / "metadata.yaml");
  EXPECT_NE(text.find("payload_parameters:\n  extrinsic:\n    body_motor:\n"), std::string::npos) << text;
  EXPECT_NE(text.find("xyz_m: [1.0, 2.0, 3.0]"), std::string::npos) << text;
}

TEST(DatasetMetadata, AValueThatIsAlsoAGroupCannotBeSaved) {
  test::ScratchFolder folder;
  DatasetMetadata m;
  m.payload_parameters.Set("motor", 1.0);
  m.payload_parameters.Set("motor.rate_hz", 2.0);
  EXPECT_THROW(SaveDatasetMetadata(m, folder / "metadata.yaml"), ConfigError);
  EXPECT_FALSE(std::filesystem::exists(folder / "metadata.yaml"));
}

TEST(DatasetMetadata, UnknownKeyNamesFileLineAndKey) {
  test::ScratchFolder folder;
  const ConfigError e = LoadError(folder, "format_version: 1\npayload: \"fixed_3d\"\nimu_rate: 200\n");
  EXPECT_EQ(e.line(), 3);
  EXPECT_EQ(e.key(), "imu_rate");
  EXPECT_NE(e.file().find("metadata.yaml"), std::string::npos);
}

TEST(DatasetMetadata, NewerFormatVersionIsRefusedBeforeItsUnknownKeys) {
  test::ScratchFolder folder;
  const ConfigError e = LoadError(folder, "new_key: 3\nformat_version: 2\npayload: x\n");
  EXPECT_EQ(e.key(), "format_version");
  EXPECT_EQ(e.line(), 2);
  EXPECT_NE(e.reason().find("newer"), std::string::npos) << e.what();
}

TEST(DatasetMetadata, BadValuesNameTheirKeyAndLine) {
  test::ScratchFolder folder;
  EXPECT_EQ(LoadError(folder, "format_version: 1\npayload: x\nimu_rate_hz: fast\n").key(), "imu_rate_hz");
  EXPECT_EQ(LoadError(folder, "format_version: 1\npayload: x\nseed: -1\n").key(), "seed");
  EXPECT_EQ(LoadError(folder, "format_version: 1\npayload: x\nduration_s: \"5\"\n").line(), 3);
  EXPECT_EQ(LoadError(folder, "format_version: 1\npayload: x\nseed: 1\nseed: 2\n").line(), 4);
  EXPECT_EQ(LoadError(folder, "format_version: 1\n").key(), "payload");
  EXPECT_EQ(LoadError(folder, "payload: x\n").key(), "format_version");
  EXPECT_EQ(LoadError(folder, "format_version: one\npayload: x\n").key(), "format_version");
  const ConfigError list =
      LoadError(folder, "format_version: 1\npayload: x\npayload_parameters:\n  a:\n    b: [1, x]\n");
  EXPECT_EQ(list.key(), "a.b");
  EXPECT_EQ(list.line(), 5);
  EXPECT_EQ(LoadError(folder, "format_version: 1\npayload: x\npayload_parameters:\n  a:\n").key(), "a");
  EXPECT_GT(LoadError(folder, "format_version: 1\npayload: [x\n").line(), 0);
}

TEST(DatasetMetadata, YamlAliasCyclesAreErrorsNotEndlessRecursion) {
  test::ScratchFolder folder;
  const ConfigError direct = LoadError(folder, "format_version: 1\npayload: x\npayload_parameters: &a\n  g: *a\n");
  EXPECT_EQ(direct.key(), "g");
  EXPECT_EQ(direct.line(), 4);
  EXPECT_NE(direct.reason().find("a cycle"), std::string::npos) << direct.what();
  // The whole file as its own payload_parameters.
  const ConfigError root = LoadError(folder, "&r\nformat_version: 1\npayload: x\npayload_parameters: *r\n");
  EXPECT_NE(root.reason().find("a cycle"), std::string::npos) << root.what();
  // A list holding itself.
  const ConfigError list = LoadError(folder, "format_version: 1\npayload: x\npayload_parameters:\n  x: &a [*a]\n");
  EXPECT_NE(list.reason().find("element 1 is a list"), std::string::npos) << list.what();
}

TEST(DatasetMetadata, MissingFileIsAConfigError) {
  test::ScratchFolder folder;
  EXPECT_THROW(LoadDatasetMetadata(folder / "metadata.yaml"), ConfigError);
}

TEST(DatasetMetadata, HandWrittenFileUsesDefaultsForOmittedKeys) {
  test::ScratchFolder folder;
  test::WriteText(folder / "metadata.yaml",
                  "format_version: 1\npayload: fixed_3d\nimu_rate_hz: 200\n"
                  "payload_parameters:\n  n: 1\n  lidar: {range_max_m: 100.5}\n");
  const DatasetMetadata m = LoadDatasetMetadata(folder / "metadata.yaml");
  EXPECT_EQ(m.payload, "fixed_3d");
  EXPECT_EQ(m.imu_rate_hz, 200.0);
  EXPECT_EQ(m.gravity_m_s2, 9.80665);
  EXPECT_EQ(m.payload_parameters.GetInt("n"), 1);
  EXPECT_EQ(m.payload_parameters.GetDouble("lidar.range_max_m"), 100.5);
}

}  // namespace
}  // namespace unimap::io
