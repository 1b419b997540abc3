// Runs KISS-ICP's C++ pipeline (the peer in ../shared/peers, built by
// scripts/peer_kiss_icp.sh, not by the project) over a folder of binary PCD
// sweeps with a times.txt, one thread, deskew off (the sweeps carry no
// per-point time), its default settings for a generic sequence
// (max_range 100 m, voxel 1 m). Writes the poses as TUM lines (LiDAR frame
// of the first sweep) and prints the registration time per sweep; file
// reading is not timed.
//   kiss_icp_runner FOLDER OUT.tum
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <tbb/global_control.h>
#include <Eigen/Geometry>

#include "kiss_icp/pipeline/KissICP.hpp"

namespace {

// The xyz of a binary PCD whose fields are all 4-byte floats (the KITTI
// demo files: x y z intensity normal_x normal_y normal_z curvature).
std::vector<Eigen::Vector3d> ReadPcd(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(file.string() + ": cannot open");
  std::string line;
  int fields = 0;
  std::size_t points = 0;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string key;
    words >> key;
    if (key == "FIELDS") {
      std::string name;
      while (words >> name) ++fields;
    } else if (key == "POINTS") {
      words >> points;
    } else if (key == "TYPE") {
      std::string type;
      while (words >> type) {
        if (type != "F") throw std::runtime_error(file.string() + ": only float fields are read");
      }
    } else if (key == "DATA") {
      std::string kind;
      words >> kind;
      if (kind != "binary") throw std::runtime_error(file.string() + ": only DATA binary is read");
      break;
    }
  }
  if (fields < 3 || points == 0) throw std::runtime_error(file.string() + ": no x y z points");
  std::vector<float> data(points * static_cast<std::size_t>(fields));
  in.read(reinterpret_cast<char*>(data.data()), static_cast<std::streamsize>(data.size() * sizeof(float)));
  if (!in) throw std::runtime_error(file.string() + ": truncated");
  std::vector<Eigen::Vector3d> xyz(points);
  for (std::size_t i = 0; i < points; ++i) {
    const float* p = data.data() + i * static_cast<std::size_t>(fields);
    xyz[i] = Eigen::Vector3d(p[0], p[1], p[2]);
  }
  return xyz;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: kiss_icp_runner FOLDER OUT.tum\n";
    return 2;
  }
  const std::filesystem::path folder = argv[1];
  std::vector<std::filesystem::path> sweeps;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.path().extension() == ".pcd") sweeps.push_back(entry.path());
  }
  std::sort(sweeps.begin(), sweeps.end());
  std::vector<double> times;
  std::ifstream time_file(folder / "times.txt");
  for (double t; time_file >> t;) times.push_back(t);
  if (sweeps.empty() || times.size() < sweeps.size()) {
    std::cerr << folder << ": needs *.pcd sweeps and a times.txt line per sweep\n";
    return 2;
  }
  const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  kiss_icp::pipeline::KISSConfig config;
  config.max_num_threads = 1;
  config.deskew = false;
  kiss_icp::pipeline::KissICP odometry(config);
  std::ofstream out(argv[2]);
  out.precision(9);
  out << "# time_s x y z qx qy qz qw (KISS-ICP, LiDAR frame of the first sweep)\n";
  double total_ms = 0.0;
  std::vector<double> per_sweep_ms;
  for (std::size_t k = 0; k < sweeps.size(); ++k) {
    const std::vector<Eigen::Vector3d> frame = ReadPcd(sweeps[k]);
    const auto start = std::chrono::steady_clock::now();
    odometry.RegisterFrame(frame, {});
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    total_ms += ms;
    per_sweep_ms.push_back(ms);
    const Eigen::Matrix4d T = odometry.pose().matrix();
    const Eigen::Quaterniond q(T.block<3, 3>(0, 0));
    out << times[k] << ' ' << T(0, 3) << ' ' << T(1, 3) << ' ' << T(2, 3) << ' ' << q.x() << ' ' << q.y() << ' '
        << q.z() << ' ' << q.w() << '\n';
  }
  std::sort(per_sweep_ms.begin(), per_sweep_ms.end());
  std::printf("kiss-icp: %zu sweeps, registration %.1f ms in all, median %.1f ms/sweep, %.1f sweeps/s\n", sweeps.size(),
              total_ms, per_sweep_ms[per_sweep_ms.size() / 2], 1000.0 * static_cast<double>(sweeps.size()) / total_ms);
  return 0;
}
