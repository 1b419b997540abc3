// online_mapper: replays a unimap dataset into unimap::Mapper the way a
// robot delivers data, one thread per sensor stream at sensor rate, and
// prints each pose with the processing lag. Built against the installed
// package (find_package(unimap); see README.md).
//
//   online_mapper --platform P.yaml --data DATASET [--live] [--rate R]
//                 [--odometry-out F.tum] [--trajectory-out F.tum] [--map-out F.ply]
//
// --rate R replays at R times the sensor rate (default 1; 0: as fast as
// the threads go). The dataset is loaded into memory first.
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <thread>
#include <variant>
#include <vector>

#include <unimap/Dataset.hpp>
#include <unimap/Errors.hpp>
#include <unimap/Mapper.hpp>

namespace {

struct Arguments {
  std::string platform, data, odometry_out, trajectory_out, map_out;
  bool live = false;
  double rate = 1.0;
};

bool Parse(int argc, char** argv, Arguments* args) {
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    const bool has_value = i + 1 < argc;
    if (flag == "--live") {
      args->live = true;
    } else if (flag == "--platform" && has_value) {
      args->platform = argv[++i];
    } else if (flag == "--data" && has_value) {
      args->data = argv[++i];
    } else if (flag == "--rate" && has_value) {
      args->rate = std::atof(argv[++i]);
    } else if (flag == "--odometry-out" && has_value) {
      args->odometry_out = argv[++i];
    } else if (flag == "--trajectory-out" && has_value) {
      args->trajectory_out = argv[++i];
    } else if (flag == "--map-out" && has_value) {
      args->map_out = argv[++i];
    } else {
      std::cerr << "unknown or incomplete option: " << flag << '\n';
      return false;
    }
  }
  if (args->platform.empty() || args->data.empty() || !(args->rate >= 0.0)) {
    std::cerr << "usage: online_mapper --platform P.yaml --data DATASET [--live] [--rate R >= 0]\n"
                 "       [--odometry-out F.tum] [--trajectory-out F.tum] [--map-out F.ply]\n";
    return false;
  }
  return true;
}

double TimeOf(const unimap::DatasetEvent& event) {
  if (const auto* imu = std::get_if<unimap::ImuSample>(&event)) return imu->time_s;
  if (const auto* encoder = std::get_if<unimap::EncoderSample>(&event)) return encoder->time_s;
  if (const auto* odometry = std::get_if<unimap::OdometrySample>(&event)) return odometry->time_s;
  if (const auto* sweep = std::get_if<unimap::RawScan>(&event)) return sweep->end_time_s;
  const auto& line = std::get<unimap::LineScan>(event);
  const std::size_t n = line.ranges_m.size();
  return line.start_time_s + (n > 0 ? static_cast<double>(n - 1) * line.time_increment_s : 0.0);
}

void Feed(unimap::Mapper& mapper, const unimap::DatasetEvent& event) {
  if (const auto* imu = std::get_if<unimap::ImuSample>(&event)) {
    mapper.AddImu(*imu);
  } else if (const auto* encoder = std::get_if<unimap::EncoderSample>(&event)) {
    mapper.AddEncoder(*encoder);
  } else if (const auto* odometry = std::get_if<unimap::OdometrySample>(&event)) {
    mapper.AddOdometry(*odometry);
  } else if (const auto* sweep = std::get_if<unimap::RawScan>(&event)) {
    mapper.AddScan(*sweep);
  } else {
    mapper.AddScan(std::get<unimap::LineScan>(event));
  }
}

// TUM rows (time x y z qx qy qz qw), every number round-tripping exactly.
void WriteTum(const std::string& file, const std::vector<unimap::StampedPose>& poses) {
  std::ofstream out(file);
  out << std::setprecision(17);
  for (const unimap::StampedPose& pose : poses) {
    const Eigen::Quaterniond q(pose.T_map_body.linear());
    const Eigen::Vector3d& p = pose.T_map_body.translation();
    out << pose.time_s << ' ' << p.x() << ' ' << p.y() << ' ' << p.z() << ' ' << q.x() << ' ' << q.y() << ' ' << q.z()
        << ' ' << q.w() << '\n';
  }
  if (!out.flush()) throw unimap::InputError(file + ": cannot be written");
}

}  // namespace

int main(int argc, char** argv) {
  Arguments args;
  if (!Parse(argc, argv, &args)) return 2;
  try {
    // Each stream's events in time order (the dataset's merge keeps it).
    unimap::Dataset dataset(args.data);
    std::vector<std::vector<unimap::DatasetEvent>> streams(4);
    while (std::optional<unimap::DatasetEvent> event = dataset.Next()) {
      streams[event->index() < 3 ? event->index() : 3].push_back(std::move(*event));
    }
    unimap::MapperSettings settings;
    settings.platform_file = args.platform;
    settings.mode = args.live ? unimap::MapperMode::kLive : unimap::MapperMode::kSynchronous;
    settings.motion = dataset.info().has_imu        ? unimap::MotionModel::kImu
                      : dataset.info().has_odometry ? unimap::MotionModel::kOdometry
                                                    : unimap::MotionModel::kConstantVelocity;
    settings.odometry_stream = dataset.info().has_odometry;
    settings.encoder_stream = dataset.info().has_encoder;
    unimap::Mapper mapper(settings);
    std::atomic<std::size_t> poses{0};
    mapper.SetPoseCallback([&poses](const unimap::MapperPose& pose) {
      // Every 50th pose: where the body is and how far processing is behind.
      if (poses++ % 50 == 0) {
        const Eigen::Vector3d p = pose.T_odom_body.translation();
        std::printf("pose t=%.3f x=%.3f y=%.3f z=%.3f matched=%d\n", pose.time_s, p.x(), p.y(), p.z(),
                    pose.matched ? 1 : 0);
      }
    });
    double first_time = 0.0;
    bool any = false;
    for (const auto& stream : streams) {
      if (stream.empty()) continue;
      const double t = TimeOf(stream.front());
      first_time = any ? std::min(first_time, t) : t;
      any = true;
    }
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::thread> threads;
    std::atomic<bool> failed{false};
    for (const auto& stream : streams) {
      threads.emplace_back([&, &events = stream] {
        try {
          for (const unimap::DatasetEvent& event : events) {
            if (args.rate > 0.0) {
              const double at_s = (TimeOf(event) - first_time) / args.rate;
              std::this_thread::sleep_until(start + std::chrono::duration<double>(at_s));
            }
            Feed(mapper, event);
          }
        } catch (const unimap::Error& e) {
          std::cerr << "error: " << e.what() << '\n';
          failed = true;
        }
      });
    }
    for (std::thread& thread : threads) thread.join();
    const unimap::MapperStatus before = mapper.Status();
    std::printf("lag at end of data: %.3f s (%zu events waiting)\n", before.lag_s, before.events_waiting);
    mapper.Finish();
    if (failed) return 1;
    const unimap::MapperStatus status = mapper.Status();
    std::printf("scans: %zu added, %zu processed, %zu matched; %zu 3D scans, %d submaps, %zu loop closures\n",
                status.scans_added, status.scans_processed, status.scans_matched, status.key_scans, status.submaps,
                status.loop_closures);
    if (!args.odometry_out.empty()) {
      std::vector<unimap::StampedPose> odometry;
      for (const unimap::MapperPose& pose : mapper.Poses()) odometry.push_back({pose.time_s, pose.T_odom_body});
      WriteTum(args.odometry_out, odometry);
    }
    if (!args.trajectory_out.empty()) WriteTum(args.trajectory_out, mapper.Trajectory());
    if (!args.map_out.empty()) mapper.WriteMap(args.map_out);
    return 0;
  } catch (const unimap::Error& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 1;
  }
}
