#include "report/RunSections.hpp"

#include <gtest/gtest.h>

namespace unimap::report {
namespace {

using Json = nlohmann::ordered_json;

TEST(RunSectionsTest, DisplaysValuesReadably) {
  EXPECT_EQ(DisplayValue(Json(36509)), "36,509");
  EXPECT_EQ(DisplayValue(Json(0.018234)), "0.01823");
  EXPECT_EQ(DisplayValue(Json(3.91)), "3.91");
  EXPECT_EQ(DisplayValue(Json(12345.6)), "12,346");
  EXPECT_EQ(DisplayValue(Json(nullptr)), "n/a");
  EXPECT_EQ(DisplayValue(Json(true)), "yes");
  EXPECT_EQ(DisplayValue(Json::array({0.34, 0.06, 0.06})), "0.34 / 0.06 / 0.06");
  EXPECT_EQ(DisplayValue(Json("imu")), "imu");
}

TEST(RunSectionsTest, ReadsAnyRunJsonGenerically) {
  const Json run = Json::parse(R"({
    "realtime_factor": 3.9, "payload": "rotating_2d", "brand_new_key_s": 1.5,
    "localizer": {"scans_matched": 10, "messages": ["scan 3: skipped"]},
    "stages": {"matching_s": 12.5, "deeper": {"edt_s": 3.0}},
    "parameters": {"scans_per_3d_scan": {"value": "40", "symbol": "N", "source": "a.yaml:3", "meaning": "m"}}
  })");
  const Json metrics = Json::parse(R"({"ate_rmse_m": 0.071, "map_entropy_mean": -1.5})");
  const Json s = RunSections(run, metrics);

  ASSERT_EQ(s["sections"].size(), 3u);  // Run, Localizer, Stages
  EXPECT_EQ(s["sections"][0]["title"], "Run");
  const Json& top = s["sections"][0]["rows"];
  ASSERT_EQ(top.size(), 3u);
  EXPECT_EQ(top[2]["label"], "Brand new key");
  EXPECT_EQ(top[2]["unit"], "s");
  EXPECT_EQ(top[2]["value"], "1.5");
  EXPECT_EQ(s["sections"][2]["title"], "Stages");
  EXPECT_EQ(s["sections"][2]["rows"][1]["key"], "stages.deeper.edt_s");
  EXPECT_EQ(s["sections"][2]["rows"][1]["label"], "Deeper edt");

  ASSERT_EQ(s["messages"].size(), 1u);
  EXPECT_EQ(s["messages"][0]["source"], "localizer");
  EXPECT_EQ(s["messages"][0]["text"], "scan 3: skipped");

  ASSERT_EQ(s["parameters"].size(), 1u);
  EXPECT_EQ(s["parameters"][0]["source"], "a.yaml:3");
  EXPECT_EQ(s["parameters"][0]["symbol"], "N");

  ASSERT_EQ(s["metrics"].size(), 2u);
  EXPECT_EQ(s["metrics"][0]["label"], "ATE RMSE (SE(3)-aligned)");
  EXPECT_NE(s["metrics"][0]["meaning"].get<std::string>().find("Umeyama"), std::string::npos);
  EXPECT_EQ(s["metrics"][1]["label"], "Map entropy mean");

  // Cards: those present, in order.
  ASSERT_EQ(s["cards"].size(), 3u);
  EXPECT_EQ(s["cards"][0]["key"], "payload");
  EXPECT_EQ(s["cards"][1]["key"], "realtime_factor");
  EXPECT_EQ(s["cards"][2]["key"], "ate_rmse_m");
}

TEST(RunSectionsTest, ValuesOfUnexpectedTypesAreShownNotRejected) {
  const Json run = Json::parse(R"({"payload": 3, "parameters": {"n": {"value": 4, "source": 7}, "m": "x"},
                                  "messages": "not a list", "mapping": {"messages": [1, 2]}})");
  const Json s = RunSections(run, Json::object());
  EXPECT_EQ(s["parameters"][0]["source"], "7");
  EXPECT_EQ(s["parameters"][1]["value"], "x");
  EXPECT_EQ(s["cards"][0]["value"], "3");
  EXPECT_TRUE(s["messages"].empty());
  EXPECT_EQ(s["sections"][1]["rows"][0]["value"], "1 / 2");
}

TEST(RunSectionsTest, ALostRunSaysSoInACardAndAWarning) {
  const Json run = Json::parse(R"({"localizer": {"tracking": {"lost": true, "first_poor_time_s": 615.7,
                                  "messages": ["the scans stopped matching the map at 615.669 s"]}}})");
  const Json s = RunSections(run, Json::object());
  ASSERT_EQ(s["cards"].size(), 1u);
  EXPECT_EQ(s["cards"][0]["key"], "localizer.tracking.lost");
  EXPECT_EQ(s["cards"][0]["label"], "Odometry lost (scans stopped matching the map)");
  EXPECT_EQ(s["cards"][0]["value"], "yes");
  ASSERT_EQ(s["messages"].size(), 1u);
  EXPECT_EQ(s["messages"][0]["source"], "localizer");
  EXPECT_EQ(s["messages"][0]["text"], "the scans stopped matching the map at 615.669 s");
}

TEST(RunSectionsTest, EmptyFilesGiveEmptyTables) {
  const Json s = RunSections(Json::object(), Json::object());
  EXPECT_TRUE(s["sections"].empty());
  EXPECT_TRUE(s["metrics"].empty());
  EXPECT_TRUE(s["cards"].empty());
}

}  // namespace
}  // namespace unimap::report
