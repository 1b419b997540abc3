#include "config/PlatformFile.hpp"

#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "unimap/Errors.hpp"

namespace unimap {
namespace {

namespace fs = std::filesystem;

// Passes when text contains part; the failure message shows both.
::testing::AssertionResult Contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

// The ConfigError that parsing text throws (a failure if none).
ConfigError ParseError(const std::string& text) {
  try {
    PlatformFile::Parse(text, "inline.yaml");
  } catch (const ConfigError& e) {
    return e;
  }
  ADD_FAILURE() << "no ConfigError for:\n" << text;
  return ConfigError("", 0, "", "");
}

// Expects parsing text to fail at line with key and a reason containing words.
void ExpectParseError(const std::string& text, int line, const std::string& key, const std::string& words) {
  const ConfigError e = ParseError(text);
  EXPECT_EQ(e.file(), "inline.yaml") << e.what();
  EXPECT_EQ(e.line(), line) << e.what();
  EXPECT_EQ(e.key(), key) << e.what();
  EXPECT_TRUE(Contains(e.reason(), words));
}

TEST(ParseScalarTest, IntegersOnlyWhenTheWholeTextIsAnInteger) {
  EXPECT_EQ(ParseScalar("40"), ParameterValue(std::int64_t{40}));
  EXPECT_EQ(ParseScalar("-7"), ParameterValue(std::int64_t{-7}));
  EXPECT_EQ(ParseScalar("+3"), ParameterValue(std::int64_t{3}));
  EXPECT_EQ(ParseScalar("9223372036854775807"), ParameterValue(std::int64_t{9223372036854775807}));
  // One past int64: a (finite) number instead.
  EXPECT_EQ(ParseScalar("9223372036854775808"), ParameterValue(9223372036854775808.0));
}

TEST(ParseScalarTest, DecimalNumbers) {
  EXPECT_EQ(ParseScalar("0.1"), ParameterValue(0.1));
  EXPECT_EQ(ParseScalar("-2.5"), ParameterValue(-2.5));
  EXPECT_EQ(ParseScalar("1e3"), ParameterValue(1000.0));
  EXPECT_EQ(ParseScalar("2E-1"), ParameterValue(0.2));
  EXPECT_EQ(ParseScalar(".5"), ParameterValue(0.5));
  EXPECT_EQ(ParseScalar("1."), ParameterValue(1.0));
}

TEST(ParseScalarTest, BooleansThenWords) {
  EXPECT_EQ(ParseScalar("true"), ParameterValue(true));
  EXPECT_EQ(ParseScalar("False"), ParameterValue(false));
  EXPECT_EQ(ParseScalar("TRUE"), ParameterValue(true));
  for (const std::string word : {"cw", "yes", "1.2.3", "0x10", "nan",  "inf", "12 m", "",   "+",  "-",
                                 ".",  "e5",  "1e",    "1e+",  "+.e1", "--1", "1.5.", " 1", "1 ", "1e5.0"}) {
    EXPECT_EQ(ParseScalar(word), ParameterValue(word)) << word;
  }
}

// A 300,000-digit value overflowed the stack of the std::regex that
// recognised numbers (a crash of `unimap config`); out of a double's range
// it stays text, which the parameter's reader then refuses by name.
TEST(ParseScalarTest, VeryLongNumbersDoNotCrash) {
  const std::string digits(300000, '1');
  EXPECT_EQ(ParseScalar(digits), ParameterValue(digits));
  EXPECT_EQ(ParseScalar("1." + std::string(300000, '0')), ParameterValue(1.0));
  const std::string underflow = "0." + std::string(300000, '0') + "1";  // below the smallest double
  EXPECT_EQ(ParseScalar(underflow), ParameterValue(underflow));
}

TEST(PlatformFileTest, FlattensNestedParametersWithLines) {
  const PlatformFile file = PlatformFile::Parse(
      "# a comment\n"                            // 1
      "plugin: rotating_2d   # trailing note\n"  // 2
      "parameters:\n"                            // 3
      "  scans_per_3d_scan: 40\n"                // 4
      "  distance_map_resolution_m: 0.1\n"       // 5
      "  extrinsic:\n"                           // 6
      "    body_motor:\n"                        // 7
      "      translation_m: [0.0, 0, 1e-1]\n"    // 8
      "      rpy_deg: [0, 0, 0]\n"               // 9
      "  motor.direction: cw\n"                  // 10
      "  quoted: \"40\"\n"                       // 11
      "  flag: false\n",                         // 12
      "inline.yaml");
  EXPECT_EQ(file.file(), "inline.yaml");
  EXPECT_EQ(file.plugin(), "rotating_2d");
  EXPECT_EQ(file.plugin_line(), 2);
  const std::vector<ParameterOverride> expected = {
      {"scans_per_3d_scan", std::int64_t{40}, 4},
      {"distance_map_resolution_m", 0.1, 5},
      {"extrinsic.body_motor.translation_m", std::vector<double>{0.0, 0.0, 0.1}, 8},
      {"extrinsic.body_motor.rpy_deg", std::vector<double>{0.0, 0.0, 0.0}, 9},
      {"motor.direction", std::string("cw"), 10},
      {"quoted", std::string("40"), 11},  // quotes make a string
      {"flag", false, 12}};
  ASSERT_EQ(file.overrides().size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(file.overrides()[i].key, expected[i].key);
    EXPECT_EQ(file.overrides()[i].value, expected[i].value) << expected[i].key;
    EXPECT_EQ(file.overrides()[i].line, expected[i].line) << expected[i].key;
  }
}

TEST(PlatformFileTest, PluginAloneOrEmptyParametersOverrideNothing) {
  EXPECT_TRUE(PlatformFile::Parse("plugin: fixed_3d\n", "a").overrides().empty());
  EXPECT_TRUE(PlatformFile::Parse("plugin: fixed_3d\nparameters:\n", "a").overrides().empty());
  EXPECT_TRUE(PlatformFile::Parse("plugin: fixed_3d\nparameters: {}\n", "a").overrides().empty());
  EXPECT_EQ(PlatformFile::Parse("parameters: {}\nplugin: ./lib/x.so\n", "a").plugin(), "./lib/x.so");
}

TEST(PlatformFileTest, YamlSyntaxErrorGivesTheLine) {
  ExpectParseError("plugin: fixed_3d\nparameters:\n  a: [1, 2\n  b: 3\n", 4, "", "YAML syntax error");
  ExpectParseError("plugin: fixed_3d\nparameters:\n  a: 1\n   b: 2\n", 4, "", "YAML syntax error");
}

TEST(PlatformFileTest, TopLevelErrors) {
  ExpectParseError("", 0, "plugin", "missing 'plugin'");
  ExpectParseError("# only a comment\n", 0, "plugin", "missing 'plugin'");
  ExpectParseError("parameters:\n  a: 1\n", 0, "plugin", "missing 'plugin'");
  ExpectParseError("- plugin\n- fixed_3d\n", 1, "", "expected a map");
  ExpectParseError("plugin: fixed_3d\nparameter:\n  a: 1\n", 2, "parameter", "unknown top-level key");
  ExpectParseError("plugin: fixed_3d\nplugin: rotating_2d\n", 2, "plugin", "set twice (first on line 1)");
  ExpectParseError("plugin:\n", 1, "plugin", "expected a payload name");
  ExpectParseError("plugin: [a, b]\n", 1, "plugin", "got a list");
  ExpectParseError("plugin: x\nparameters: [1, 2]\n", 2, "parameters", "expected a map");
  ExpectParseError("plugin: x\nparameters: 3\n", 2, "parameters", "got '3'");
}

TEST(PlatformFileTest, MapperSectionIsKeptApartWithLines) {
  const PlatformFile file = PlatformFile::Parse(
      "plugin: x\nparameters:\n  a: 1\nmapper:\n  gpf:\n    num_particles: 200\n  scan_sigma_position_m: 0.2\n",
      "inline.yaml");
  ASSERT_EQ(file.overrides().size(), 1u);
  ASSERT_EQ(file.mapper_settings().size(), 2u);
  EXPECT_EQ(file.mapper_settings()[0].key, "gpf.num_particles");
  EXPECT_EQ(std::get<std::int64_t>(file.mapper_settings()[0].value), 200);
  EXPECT_EQ(file.mapper_settings()[0].line, 6);
  EXPECT_EQ(file.mapper_settings()[1].key, "scan_sigma_position_m");
  EXPECT_EQ(file.mapper_settings()[1].line, 7);
  EXPECT_TRUE(PlatformFile::Parse("plugin: x\nmapper:\n", "inline.yaml").mapper_settings().empty());
  ExpectParseError("plugin: x\nmapper: 3\n", 2, "mapper", "expected a map of mapper settings");
  ExpectParseError("plugin: x\nmapper:\n  gpf:\n    a: 1\n    a: 2\n", 5, "mapper.gpf.a", "set twice");
  ExpectParseError("plugin: x\nmapper:\n  gpf:\n    a:\n", 4, "mapper.gpf.a", "no value given");
}

TEST(PlatformFileTest, ParameterValueErrors) {
  ExpectParseError("plugin: x\nparameters:\n  a:\n  b: 1\n", 3, "a", "no value given");
  ExpectParseError("plugin: x\nparameters:\n  g:\n    a: ~\n", 4, "g.a", "no value given");
  ExpectParseError("plugin: x\nparameters:\n  v: [1, two, 3]\n", 3, "v",
                   "expected a list of numbers, but element 2 is 'two'");
  ExpectParseError("plugin: x\nparameters:\n  v: [1, \"2\"]\n", 3, "v", "element 2 is '2'");
  ExpectParseError("plugin: x\nparameters:\n  v:\n    - 1\n    - [2]\n", 5, "v", "element 2 is a list");
  ExpectParseError("plugin: x\nparameters:\n  g: {}\n", 3, "g", "empty group");
  ExpectParseError("plugin: x\nparameters:\n  [a]: 1\n", 3, "", "plain word");
}

TEST(PlatformFileTest, DuplicateParameterNamesTheFirstLine) {
  ExpectParseError("plugin: x\nparameters:\n  a: 1\n  a: 2\n", 4, "a", "set twice (first on line 3)");
  // The same dotted key written nested and flat.
  ExpectParseError("plugin: x\nparameters:\n  g:\n    k: 1\n  g.k: 2\n", 5, "g.k", "set twice (first on line 4)");
}

TEST(PlatformFileTest, YamlAliasCyclesAreErrorsNotEndlessRecursion) {
  // A group holding an alias to itself, directly or through a child group.
  ExpectParseError("plugin: x\nparameters: &a\n  g: *a\n", 3, "g", "a cycle");
  ExpectParseError("plugin: x\nparameters:\n  g: &a\n    h:\n      k: *a\n", 5, "g.h.k", "a cycle");
  // A list holding itself is a list element that is not a number.
  ExpectParseError("plugin: x\nparameters:\n  x: &a [*a]\n", 3, "x", "element 1 is a list");
  // An alias to a group elsewhere is fine: its keys are repeated under the new name.
  const PlatformFile file = PlatformFile::Parse("plugin: x\nparameters:\n  a: &g\n    k: 1\n  b: *g\n", "inline.yaml");
  ASSERT_EQ(file.overrides().size(), 2u);
  EXPECT_EQ(file.overrides()[1].key, "b.k");
}

TEST(PlatformFileTest, AliasExpansionIsBounded) {
  // Ten groups of ten aliases to the previous group: 10^10 keys if expanded.
  std::string text =
      "plugin: x\nparameters:\n  l0: &l0 {a: 1, b: 2, c: 3, d: 4, e: 5, f: 6, g: 7, h: 8, i: 9, j: 10}\n";
  for (int level = 1; level <= 10; ++level) {
    const std::string previous = "*l" + std::to_string(level - 1);
    text += "  l" + std::to_string(level) + ": &l" + std::to_string(level) + " {";
    for (char c = 'a'; c <= 'j'; ++c) text += std::string(c == 'a' ? "" : ", ") + c + ": " + previous;
    text += "}\n";
  }
  const ConfigError e = ParseError(text);
  EXPECT_TRUE(Contains(e.reason(), "more than 10000 parameters")) << e.what();
}

TEST(PlatformFileTest, ReadsFilesAndNamesThemInErrors) {
  const fs::path folder = fs::temp_directory_path() / ("unimap_platform_file_test_" + std::to_string(getpid()));
  fs::create_directories(folder);
  const fs::path good = folder / "good.yaml";
  const fs::path bad = folder / "bad.yaml";
  std::ofstream(good) << "plugin: fixed_3d\nparameters:\n  scans_per_3d_scan: 3\n";
  std::ofstream(bad) << "plugin: fixed_3d\nextra: 1\n";

  const PlatformFile file = PlatformFile::Read(good);
  EXPECT_EQ(file.file(), good.string());
  ASSERT_EQ(file.overrides().size(), 1u);
  EXPECT_EQ(file.overrides()[0].line, 3);

  try {
    PlatformFile::Read(bad);
    ADD_FAILURE() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.file(), bad.string());
    EXPECT_EQ(e.line(), 2);
    EXPECT_TRUE(Contains(e.what(), bad.string() + ":2: key 'extra': "));
  }
  try {
    PlatformFile::Read(folder / "absent.yaml");
    ADD_FAILURE() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.file(), (folder / "absent.yaml").string());
    EXPECT_TRUE(Contains(e.reason(), "not found"));
  }
  try {
    PlatformFile::Read(folder);
    ADD_FAILURE() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_TRUE(Contains(e.reason(), "directory"));
  }
  fs::remove_all(folder);
}

}  // namespace
}  // namespace unimap
