#pragma once
// A temporary run folder for the report tests: a straight 10 m flight along
// x at z = 1, the truth beside it, a floor map at z = 0.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/PlyWriter.hpp"
#include "io/TumTrajectory.hpp"

namespace unimap::report::testing {

inline std::vector<StampedPose> Line(std::size_t n, double y) {
  std::vector<StampedPose> poses;
  for (std::size_t i = 0; i < n; ++i) {
    StampedPose p;
    p.time_s = 100.0 + 0.1 * static_cast<double>(i);
    p.T_map_body = Eigen::Isometry3d::Identity();
    p.T_map_body.translation() = Eigen::Vector3d(0.1 * static_cast<double>(i), y, 1.0);
    poses.push_back(p);
  }
  return poses;
}

class RunFolderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::path(::testing::TempDir()) / ("unimap_report_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_ / "data");
    std::filesystem::create_directories(dir_ / "run");
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // trajectory.tum (n poses), data/groundtruth.tum, run.json naming data/, map.ply (points on z = 0).
  void WriteRun(std::size_t n, std::size_t map_points) {
    io::WriteTumTrajectory(dir_ / "run" / "trajectory.tum", Line(n, 0.0));
    io::WriteTumTrajectory(dir_ / "data" / "groundtruth.tum", Line(n, 0.0));
    std::ofstream(dir_ / "run" / "run.json") << "{\"payload\": \"rotating_2d\", \"dataset\": \""
                                             << (dir_ / "data").string() << "\", \"realtime_factor\": 4.5}\n";
    std::vector<Eigen::Vector3f> points;
    for (std::size_t i = 0; i < map_points; ++i) points.emplace_back(0.01f * static_cast<float>(i), 1.0f, 0.0f);
    io::WritePly(dir_ / "run" / "map.ply", points);
  }

  std::filesystem::path dir_;
};

}  // namespace unimap::report::testing
