#include "StageInputs.hpp"

#include <unistd.h>

#include <filesystem>
#include <map>
#include <stdexcept>
#include <variant>

#include "Scenario.hpp"
#include "Simulator.hpp"
#include "io/DatasetReader.hpp"
#include "matching/VoxelDownsampler.hpp"
#include "unimap/CoreParameters.hpp"
#include "unimap/LineScan.hpp"

namespace unimap::bench {
namespace {

std::filesystem::path Source(const std::string& relative) {
  return std::filesystem::path(UNIMAP_SOURCE_DIR) / relative;
}

std::unique_ptr<StageInputs> Make(const std::string& scenario, const std::string& platform_name, double duration_s) {
  auto in = std::make_unique<StageInputs>();
  in->name = scenario + " / " + platform_name;
  const std::filesystem::path platform_file = Source("configs/platforms/" + platform_name + ".yaml");
  in->platform = LoadPlatform(platform_file);
  in->options = pipeline::LocalizerOptions::FromPlatform(CoreParameters::FromMap(in->platform.parameters));
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("unimap_bench_" + std::to_string(::getpid()) + "_" + scenario);
  sim::SimulationOptions simulation;
  simulation.out_dir = dir;
  simulation.duration_s = duration_s;
  simulation.payload = platform_file.string();
  sim::Simulator(sim::LoadScenario(Source("configs/scenarios/" + scenario + ".yaml")), simulation).Run();
  in->duration_s = duration_s;

  io::DatasetReader reader(dir);
  while (const auto pose = reader.NextGroundTruth()) in->truth.Add(pose->time_s, pose->T_map_body);
  std::vector<EncoderSample> encoder;
  while (const auto sample = reader.NextEncoder()) encoder.push_back(*sample);
  in->encoder = EncoderTrack(encoder, 0.5);
  while (auto record = reader.NextScan()) {
    if (const auto* line = std::get_if<LineScan>(&*record)) {
      in->raw_scans.push_back(LineScanToRawScan(*line).scan);
    } else {
      in->raw_scans.push_back(std::get<RawScan>(*record));
    }
  }
  std::filesystem::remove_all(dir);

  const PayloadPlugin& plugin = *in->platform.plugin.plugin;
  const MotionQuery truth = [&in](double t) { return in->truth.At(t); };
  std::vector<Eigen::Vector3f> accumulated;
  Eigen::Vector3f sensor_sum = Eigen::Vector3f::Zero();
  int in_key = 0;
  for (const RawScan& raw : in->raw_scans) {
    if (raw.points.empty()) continue;
    const BodyScan body = plugin.Deskew(raw, in->encoder, truth);
    const Eigen::Isometry3d T_map_body = in->truth.At(body.reference_time_s);
    std::vector<Eigen::Vector3f> points;
    points.reserve(body.points.size());
    for (const Point& p : body.points) points.push_back(p.position_m.cast<float>());
    for (const Eigen::Vector3f& p : points) accumulated.push_back(T_map_body.cast<float>() * p);
    sensor_sum += (T_map_body * plugin.BodyFromLidarAt(in->encoder, body.reference_time_s).translation()).cast<float>();
    in->body_scans.push_back(std::move(points));
    in->body_poses.push_back(T_map_body);
    if (++in_key == in->options.scans_per_3d_scan) {
      KeyScanInput key;
      key.points_map = matching::VoxelDownsample(accumulated, in->options.map.resolution_m, 0, 0);
      key.sensor_map = sensor_sum / static_cast<float>(in_key);
      in->key_scans.push_back(std::move(key));
      accumulated.clear();
      sensor_sum.setZero();
      in_key = 0;
    }
  }
  if (in->key_scans.empty())
    throw std::runtime_error(in->name + ": no 3D scan in " + std::to_string(duration_s) + " s");
  return in;
}

}  // namespace

const StageInputs& Inputs(const std::string& scenario, const std::string& platform, double duration_s) {
  static std::map<std::string, std::unique_ptr<StageInputs>> cache;
  const std::string key = scenario + "/" + platform + "/" + std::to_string(duration_s);
  auto it = cache.find(key);
  if (it == cache.end()) it = cache.emplace(key, Make(scenario, platform, duration_s)).first;
  return *it->second;
}

}  // namespace unimap::bench
