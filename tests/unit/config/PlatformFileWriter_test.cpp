#include "config/PlatformFileWriter.hpp"

#include <gtest/gtest.h>

#include "config/PlatformFile.hpp"

namespace unimap {
namespace {

TEST(PlatformFileWriter, WritesWhatTheReaderReadsBack) {
  const std::vector<ParameterOverride> parameters = {
      {"scans_per_3d_scan", std::int64_t{40}, 0},
      {"sigma_accel_m_s2", 0.1 + 0.2, 0},  // not exactly 0.3: needs all its digits
      {"extrinsic.motor_lidar.translation_m", std::vector<double>{0.0123456789012345, -1e-9, 2.5}, 0},
      {"lidar.timing", std::string("azimuth"), 0},
      {"motor.encoder_direction", std::int64_t{-1}, 0},
      {"flag", true, 0}};
  const std::vector<ParameterOverride> mapper = {{"localizer.gpf.num_particles", std::int64_t{200}, 0}};
  const std::string text = WritePlatformYaml("rotating_2d", parameters, mapper, "made by a test\nsecond line");
  EXPECT_EQ(text.rfind("# made by a test\n# second line\n", 0), 0u) << text;
  const PlatformFile file = PlatformFile::Parse(text, "written.yaml");
  EXPECT_EQ(file.plugin(), "rotating_2d");
  ASSERT_EQ(file.overrides().size(), parameters.size());
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    EXPECT_EQ(file.overrides()[i].key, parameters[i].key);
    EXPECT_EQ(file.overrides()[i].value, parameters[i].value) << parameters[i].key << " in\n" << text;
  }
  ASSERT_EQ(file.mapper_settings().size(), 1u);
  EXPECT_EQ(file.mapper_settings()[0].key, "localizer.gpf.num_particles");
  // Without mapper settings there is no mapper section.
  EXPECT_EQ(WritePlatformYaml("fixed_3d", parameters, {}, "").find("mapper"), std::string::npos);
}

}  // namespace
}  // namespace unimap
