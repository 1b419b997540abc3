#include "WorldLoader.hpp"

#include <cmath>
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "BoxPrimitive.hpp"
#include "CylinderPrimitive.hpp"
#include "HeightfieldPrimitive.hpp"
#include "PlanePrimitive.hpp"
#include "SpherePrimitive.hpp"
#include "unimap/Errors.hpp"

namespace unimap::sim {
namespace {

constexpr char kFile[] = "scenarios/tunnel.yaml";

// Loads the `world:` list of a YAML document.
World Load(const std::string& text) { return LoadWorld(YAML::Load(text)["world"], kFile); }

// The ConfigError that loading text throws (a failure if it throws none).
ConfigError ErrorOf(const std::string& text) {
  try {
    Load(text);
  } catch (const ConfigError& e) {
    return e;
  }
  ADD_FAILURE() << "no ConfigError for:\n" << text;
  return ConfigError("", 0, "", "");
}

TEST(WorldLoader, ParsesEveryPrimitiveTypeAndRepeats) {
  const World world = Load(R"(world:
  - {type: box, center: [54, 0, 3.5], size: [108, 5.8, 7], rpy_deg: [0, 0, 0]}
  - {type: plane, center: [0, 0, 0], size: [40, 40], rpy_deg: [0, 0, 0]}
  - {type: cylinder, base: [3, 4, 0], axis: [0, 0, 2], radius: 0.3, height: 3}
  - {type: sphere, center: [3, 4, 4], radius: 1.5}
  - {type: heightfield, center: [0, 0, 0], size: [40, 40], z0: 0.5, waves: [[0.1, 0.3, 0.2, 0.0, 0.0]]}
  - {type: box, center: [10, 0, 1], size: [12, 3, 3], repeat: {count: 8, step: [12.5, 0, 0]}}
)");
  ASSERT_TRUE(world.built());
  ASSERT_EQ(world.size(), 13u);
  const std::vector<std::string> kinds = {"box", "plane", "cylinder", "sphere", "heightfield"};
  for (std::size_t i = 0; i < kinds.size(); ++i) EXPECT_EQ(world.primitive(i).Kind(), kinds[i]);
  const auto& room = dynamic_cast<const BoxPrimitive&>(world.primitive(0));
  EXPECT_TRUE(room.center().isApprox(Eigen::Vector3d(54, 0, 3.5)));
  EXPECT_TRUE(room.size().isApprox(Eigen::Vector3d(108, 5.8, 7)));
  const auto& plane = dynamic_cast<const PlanePrimitive&>(world.primitive(1));
  EXPECT_TRUE(plane.size().isApprox(Eigen::Vector2d(40, 40)));
  const auto& post = dynamic_cast<const CylinderPrimitive&>(world.primitive(2));
  EXPECT_TRUE(post.axis().isApprox(Eigen::Vector3d(0, 0, 1)));  // normalised
  EXPECT_DOUBLE_EQ(post.radius(), 0.3);
  EXPECT_DOUBLE_EQ(post.height(), 3.0);
  const auto& ball = dynamic_cast<const SpherePrimitive&>(world.primitive(3));
  EXPECT_DOUBLE_EQ(ball.radius(), 1.5);
  const auto& ground = dynamic_cast<const HeightfieldPrimitive&>(world.primitive(4));
  ASSERT_EQ(ground.waves().size(), 1u);
  EXPECT_DOUBLE_EQ(ground.waves()[0].kx_rad_m, 0.3);
  EXPECT_NEAR(ground.Height(1.0, 2.0), 0.5 + 0.1 * std::sin(0.3) * std::cos(0.4), 1e-15);
  for (int i = 0; i < 8; ++i) {
    const auto& car = dynamic_cast<const BoxPrimitive&>(world.primitive(5 + i));
    EXPECT_TRUE(car.center().isApprox(Eigen::Vector3d(10 + 12.5 * i, 0, 1))) << "copy " << i;
    EXPECT_TRUE(car.size().isApprox(Eigen::Vector3d(12, 3, 3)));
  }
  // Casting works straight away: from inside the tunnel, up to the ceiling.
  const auto hit = world.Cast(Ray{Eigen::Vector3d(100, 0, 3.5), Eigen::Vector3d::UnitZ()}, 0.0, 50.0);
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->primitive_index, 0);
  EXPECT_NEAR(hit->range_m, 3.5, 1e-12);
}

TEST(WorldLoader, OrientationIsRzRyRxInDegreesAndOptionalKeysDefault) {
  const World world = Load(R"(world:
  - {type: box, center: [0, 0, 0], size: [2, 4, 6], rpy_deg: [0, 0, 90]}
  - {type: plane, center: [0, 0, 0], size: [1, 1], rpy_deg: [90, 0, 0]}
  - {type: box, center: [0, 0, 0], size: [1, 1, 1]}
  - {type: heightfield, center: [0, 0, 2], size: [3, 3]}
)");
  const auto& turned = dynamic_cast<const BoxPrimitive&>(world.primitive(0));
  EXPECT_TRUE(turned.Bounds().max().isApprox(Eigen::Vector3d(2, 1, 3), 1e-12));
  const auto& wall = dynamic_cast<const PlanePrimitive&>(world.primitive(1));
  EXPECT_TRUE(wall.normal().isApprox(Eigen::Vector3d(0, -1, 0), 1e-12));
  EXPECT_TRUE(dynamic_cast<const BoxPrimitive&>(world.primitive(2)).rotation().isIdentity(0.0));
  const auto& flat = dynamic_cast<const HeightfieldPrimitive&>(world.primitive(3));
  EXPECT_TRUE(flat.waves().empty());
  EXPECT_DOUBLE_EQ(flat.Height(0.5, 0.5), 2.0);
}

TEST(WorldLoader, EmptyListGivesAnEmptyWorld) {
  const World world = Load("world: []\n");
  EXPECT_EQ(world.size(), 0u);
  EXPECT_FALSE(world.Cast(Ray{}, 0.0, 10.0));
}

TEST(WorldLoader, DescribesTheWorld) {
  const World world = Load(R"(world:
  - {type: sphere, center: [0, 0, 0], radius: 1}
  - {type: sphere, center: [4, 0, 0], radius: 1}
  - {type: box, center: [0, 0, 0], size: [2, 2, 2]}
)");
  EXPECT_EQ(DescribeWorld(world), "3 primitives (1 box, 2 sphere), bounds [-1, -1, -1] .. [5, 1, 1] m");
}

// One malformed world and what its error must say.
struct BadWorld {
  std::string name;    // test label
  std::string yaml;    // the document (line 1 is `world:`)
  int line;            // expected 1-based line
  std::string key;     // expected key
  std::string reason;  // expected part of the reason
};

// Test names show the label, not the bytes.
void PrintTo(const BadWorld& bad, std::ostream* out) { *out << bad.name; }

class WorldLoaderErrors : public ::testing::TestWithParam<BadWorld> {};

TEST_P(WorldLoaderErrors, NameFileLineKeyAndReason) {
  const BadWorld& bad = GetParam();
  const ConfigError error = ErrorOf(bad.yaml);
  EXPECT_EQ(error.file(), kFile);
  EXPECT_EQ(error.line(), bad.line);
  EXPECT_EQ(error.key(), bad.key);
  EXPECT_NE(error.reason().find(bad.reason), std::string::npos) << error.what();
  EXPECT_NE(std::string(error.what()).find(kFile), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(
    WorldLoader, WorldLoaderErrors,
    ::testing::Values(
        BadWorld{"NotAList", "world: {type: box}\n", 1, "world", "expected a list of primitives"},
        BadWorld{"Missing", "other: 1\n", 0, "world", "expected a list of primitives, got nothing"},
        BadWorld{"EntryNotAMap", "world:\n  - 42\n", 2, "type", "world entry 1: expected a map"},
        BadWorld{"MissingType", "world:\n  - {center: [0, 0, 0], radius: 1}\n", 2, "type", "missing key 'type'"},
        BadWorld{"UnknownType", "world:\n  - {type: sphere, center: [0, 0, 0], radius: 1}\n  - {type: cube, size: 1}\n",
                 3, "type", "world entry 2: unknown type 'cube'; expected one of: box, plane"},
        BadWorld{"UnknownKey", "world:\n  - type: box\n    center: [0, 0, 0]\n    size: [1, 1, 1]\n    colour: red\n",
                 5, "colour", "world entry 1 (box): unknown key; expected one of: type, center, size"},
        BadWorld{"MissingKey", "world:\n  - {type: box, center: [0, 0, 0]}\n", 2, "size", "missing key 'size'"},
        BadWorld{"WrongLength", "world:\n  - type: box\n    center: [0, 0, 0]\n    size: [1, 2]\n", 4, "size",
                 "expected a list of 3 numbers, got a list of 2"},
        BadWorld{"PlaneSizeHasTwo", "world:\n  - {type: plane, center: [0, 0, 0], size: [1, 2, 3]}\n", 2, "size",
                 "expected a list of 2 numbers"},
        BadWorld{"NotANumber", "world:\n  - type: sphere\n    center: [0, a, 0]\n    radius: 1\n", 3, "center",
                 "got 'a'"},
        BadWorld{"NotFinite", "world:\n  - type: sphere\n    center: [0, .nan, 0]\n    radius: 1\n", 3, "center",
                 "must be finite"},
        BadWorld{"ZeroSize", "world:\n  - type: box\n    center: [0, 0, 0]\n    size: [1, 0, 1]\n", 4, "size",
                 "every size must be > 0"},
        BadWorld{"NegativeRadius", "world:\n  - type: sphere\n    center: [0, 0, 0]\n    radius: -1\n", 4, "radius",
                 "must be > 0, got -1"},
        BadWorld{"ZeroHeight", "world:\n  - {type: cylinder, base: [0, 0, 0], axis: [0, 0, 1], radius: 1, height: 0}\n",
                 2, "height", "must be > 0"},
        BadWorld{"ZeroAxis",
                 "world:\n  - type: cylinder\n    base: [0, 0, 0]\n    axis: [0, 0, 0]\n    radius: 1\n"
                 "    height: 1\n",
                 4, "axis", "must not be zero"},
        BadWorld{"RadiusNotScalar", "world:\n  - {type: sphere, center: [0, 0, 0], radius: [1]}\n", 2, "radius",
                 "expected a number, got a list of 1"},
        BadWorld{"RpyWrongLength",
                 "world:\n  - type: box\n    center: [0, 0, 0]\n    size: [1, 1, 1]\n    rpy_deg: [0, 0]\n", 5,
                 "rpy_deg", "expected a list of 3 numbers"},
        BadWorld{"DuplicateKey", "world:\n  - type: sphere\n    center: [0, 0, 0]\n    radius: 1\n    radius: 2\n", 5,
                 "radius", "set twice (first on line 4)"},
        BadWorld{"WaveWrongLength",
                 "world:\n  - type: heightfield\n    center: [0, 0, 0]\n    size: [4, 4]\n    waves:\n"
                 "      - [0.1, 0.3, 0.2, 0.0, 0.0]\n      - [0.1, 0.3, 0.2, 0.0]\n",
                 7, "waves", "expected a list of 5 numbers, got a list of 4"},
        BadWorld{"WavesNotAList", "world:\n  - {type: heightfield, center: [0, 0, 0], size: [4, 4], waves: 3}\n", 2,
                 "waves", "expected a list of [amplitude, kx, ky, phi, psi] lists"},
        BadWorld{"RepeatNotAMap", "world:\n  - {type: sphere, center: [0, 0, 0], radius: 1, repeat: 3}\n", 2, "repeat",
                 "expected {count: n, step: [dx, dy, dz]}"},
        BadWorld{"RepeatZeroCount",
                 "world:\n  - type: sphere\n    center: [0, 0, 0]\n    radius: 1\n    repeat:\n"
                 "      count: 0\n      step: [1, 0, 0]\n",
                 6, "repeat.count", "must be between 1 and 100000, got 0"},
        BadWorld{"RepeatFractionalCount",
                 "world:\n  - type: sphere\n    center: [0, 0, 0]\n    radius: 1\n    repeat:\n"
                 "      count: 2.5\n      step: [1, 0, 0]\n",
                 6, "repeat.count", "expected a whole number, got '2.5'"},
        BadWorld{"RepeatUnknownKey",
                 "world:\n  - type: sphere\n    center: [0, 0, 0]\n    radius: 1\n    repeat:\n"
                 "      count: 2\n      stride: [1, 0, 0]\n",
                 7, "repeat.stride", "unknown key; expected one of: count, step"},
        BadWorld{"RepeatMissingStep",
                 "world:\n  - type: sphere\n    center: [0, 0, 0]\n    radius: 1\n    repeat:\n"
                 "      count: 2\n",
                 6, "repeat.step", "missing key 'repeat.step'"}),
    [](const ::testing::TestParamInfo<BadWorld>& param_info) { return param_info.param.name; });

}  // namespace
}  // namespace unimap::sim
