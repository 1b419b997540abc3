// The Python module `unimap` (pybind11): the online mapper API of
// include/unimap/Mapper.hpp and Dataset.hpp, with numpy arrays for points
// and poses. docs/library.md shows its use.
#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "unimap/Dataset.hpp"
#include "unimap/Errors.hpp"
#include "unimap/Mapper.hpp"

namespace py = pybind11;

namespace {

using FloatRows = py::array_t<double, py::array::c_style | py::array::forcecast>;

// Poses as an (N, 8) array of TUM rows: time x y z qx qy qz qw.
template <class Pose, class Transform>
py::array_t<double> PoseRows(const std::vector<Pose>& poses, Transform transform) {
  py::array_t<double> out({static_cast<py::ssize_t>(poses.size()), py::ssize_t{8}});
  auto rows = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const Eigen::Isometry3d& T = transform(poses[i]);
    const Eigen::Quaterniond q(T.linear());
    const double row[8] = {
        poses[i].time_s, T.translation().x(), T.translation().y(), T.translation().z(), q.x(), q.y(), q.z(), q.w()};
    for (py::ssize_t c = 0; c < 8; ++c) rows(static_cast<py::ssize_t>(i), c) = row[c];
  }
  return out;
}
py::array_t<double> PoseRows(const std::vector<unimap::StampedPose>& poses) {
  return PoseRows(poses, [](const unimap::StampedPose& p) -> const Eigen::Isometry3d& { return p.T_map_body; });
}

// A sweep from an (N, 3) or (N, 4) array (x y z [intensity], LiDAR frame),
// optional per-point times and rings.
unimap::RawScan MakeSweep(const FloatRows& points, std::optional<FloatRows> times, std::optional<double> start_time_s,
                          std::optional<double> end_time_s, std::optional<py::array_t<std::uint16_t>> rings) {
  if (points.ndim() != 2 || (points.shape(1) != 3 && points.shape(1) != 4)) {
    std::string shape;
    for (py::ssize_t a = 0; a < points.ndim(); ++a) shape += (a > 0 ? ", " : "") + std::to_string(points.shape(a));
    throw unimap::InputError("add_scan: points must be an (N, 3) or (N, 4) array, got shape (" + shape + ")");
  }
  const py::ssize_t n = points.shape(0);
  if (times && (times->ndim() != 1 || times->shape(0) != n)) {
    throw unimap::InputError("add_scan: times must hold one time per point (" + std::to_string(n) + ")");
  }
  if (rings && (rings->ndim() != 1 || rings->shape(0) != n)) {
    throw unimap::InputError("add_scan: rings must hold one ring per point (" + std::to_string(n) + ")");
  }
  unimap::RawScan scan;
  scan.has_point_time = times.has_value();
  scan.points.resize(static_cast<std::size_t>(n));
  const auto p = points.unchecked<2>();
  double t_min = INFINITY, t_max = -INFINITY;
  for (py::ssize_t i = 0; i < n; ++i) {
    unimap::Point& point = scan.points[static_cast<std::size_t>(i)];
    point.position_m = Eigen::Vector3d(p(i, 0), p(i, 1), p(i, 2));
    if (points.shape(1) == 4) point.intensity = static_cast<float>(p(i, 3));
    if (times) {
      point.time_s = times->at(i);
      t_min = std::min(t_min, point.time_s);
      t_max = std::max(t_max, point.time_s);
    }
    if (rings) point.ring = rings->at(i);
  }
  if (!times && !end_time_s) throw unimap::InputError("add_scan: give times= (per point) or end_time_s=");
  scan.end_time_s = end_time_s ? *end_time_s : t_max;
  scan.start_time_s = start_time_s ? *start_time_s : (times ? t_min : scan.end_time_s);
  return scan;
}

// A dataset event as a Python tuple: ("imu", ImuSample), ("encoder", ...),
// ("odometry", ...), ("scan", RawScan) or ("line", LineScan).
py::tuple EventTuple(unimap::DatasetEvent&& event) {
  if (auto* imu = std::get_if<unimap::ImuSample>(&event)) return py::make_tuple("imu", *imu);
  if (auto* encoder = std::get_if<unimap::EncoderSample>(&event)) return py::make_tuple("encoder", *encoder);
  if (auto* odometry = std::get_if<unimap::OdometrySample>(&event)) return py::make_tuple("odometry", *odometry);
  if (auto* sweep = std::get_if<unimap::RawScan>(&event)) return py::make_tuple("scan", std::move(*sweep));
  return py::make_tuple("line", std::move(std::get<unimap::LineScan>(event)));
}

}  // namespace

PYBIND11_MODULE(unimap, m) {
  m.doc() = "unimap: real-time 3D mapping from any LiDAR payload (docs/library.md)";
  m.attr("api_version") = unimap::kMapperApiVersion;
  // The most derived last: pybind11 tries translators newest first.
  py::register_exception<unimap::Error>(m, "Error", PyExc_RuntimeError);
  py::register_exception<unimap::PluginError>(m, "PluginError", PyExc_RuntimeError);
  py::register_exception<unimap::ConfigError>(m, "ConfigError", PyExc_ValueError);
  py::register_exception<unimap::InputError>(m, "InputError", PyExc_ValueError);

  py::class_<unimap::ImuSample>(m, "ImuSample")
      .def(py::init<>())
      .def_readwrite("time_s", &unimap::ImuSample::time_s)
      .def_readwrite("accel_m_s2", &unimap::ImuSample::accel_m_s2)
      .def_readwrite("gyro_rad_s", &unimap::ImuSample::gyro_rad_s);
  py::class_<unimap::EncoderSample>(m, "EncoderSample")
      .def(py::init<>())
      .def_readwrite("time_s", &unimap::EncoderSample::time_s)
      .def_readwrite("angle_rad", &unimap::EncoderSample::angle_rad);
  py::class_<unimap::OdometrySample>(m, "OdometrySample")
      .def(py::init<>())
      .def_readwrite("time_s", &unimap::OdometrySample::time_s)
      .def_property(
          "T_odom_body", [](const unimap::OdometrySample& s) { return Eigen::Matrix4d(s.T_odom_body.matrix()); },
          [](unimap::OdometrySample& s, const Eigen::Matrix4d& T) { s.T_odom_body.matrix() = T; });
  py::class_<unimap::RawScan>(m, "RawScan")
      .def(py::init<>())
      .def_readwrite("start_time_s", &unimap::RawScan::start_time_s)
      .def_readwrite("end_time_s", &unimap::RawScan::end_time_s)
      .def_readwrite("has_point_time", &unimap::RawScan::has_point_time)
      .def_property_readonly("points",  // (N, 4): x y z intensity
                             [](const unimap::RawScan& s) {
                               py::array_t<double> out({static_cast<py::ssize_t>(s.points.size()), py::ssize_t{4}});
                               auto rows = out.mutable_unchecked<2>();
                               for (std::size_t i = 0; i < s.points.size(); ++i) {
                                 const auto r = static_cast<py::ssize_t>(i);
                                 for (int a = 0; a < 3; ++a) rows(r, a) = s.points[i].position_m[a];
                                 rows(r, 3) = s.points[i].intensity;
                               }
                               return out;
                             })
      .def_property_readonly("times",
                             [](const unimap::RawScan& s) {
                               py::array_t<double> out(static_cast<py::ssize_t>(s.points.size()));
                               auto t = out.mutable_unchecked<1>();
                               for (std::size_t i = 0; i < s.points.size(); ++i)
                                 t(static_cast<py::ssize_t>(i)) = s.points[i].time_s;
                               return out;
                             })
      .def_property_readonly("rings", [](const unimap::RawScan& s) {
        py::array_t<std::uint16_t> out(static_cast<py::ssize_t>(s.points.size()));
        auto r = out.mutable_unchecked<1>();
        for (std::size_t i = 0; i < s.points.size(); ++i) r(static_cast<py::ssize_t>(i)) = s.points[i].ring;
        return out;
      });
  py::class_<unimap::LineScan>(m, "LineScan")
      .def(py::init<>())
      .def_readwrite("start_time_s", &unimap::LineScan::start_time_s)
      .def_readwrite("angle_min_rad", &unimap::LineScan::angle_min_rad)
      .def_readwrite("angle_increment_rad", &unimap::LineScan::angle_increment_rad)
      .def_readwrite("time_increment_s", &unimap::LineScan::time_increment_s)
      .def_readwrite("range_min_m", &unimap::LineScan::range_min_m)
      .def_readwrite("range_max_m", &unimap::LineScan::range_max_m)
      .def_readwrite("ranges_m", &unimap::LineScan::ranges_m)
      .def_readwrite("intensities", &unimap::LineScan::intensities);

  py::class_<unimap::Mapper>(m, "Mapper",
                             "The online mapper (include/unimap/Mapper.hpp): add data per stream in time "
                             "order, read poses, trajectory and map.")
      .def(py::init([](const std::string& platform_file, bool live, const std::string& motion, bool encoder,
                       bool odometry, int threads, bool loop_closure) {
             unimap::MapperSettings s;
             s.platform_file = platform_file;
             s.mode = live ? unimap::MapperMode::kLive : unimap::MapperMode::kSynchronous;
             if (motion == "imu") {
               s.motion = unimap::MotionModel::kImu;
             } else if (motion == "odometry") {
               s.motion = unimap::MotionModel::kOdometry;
             } else if (motion == "constant-velocity") {
               s.motion = unimap::MotionModel::kConstantVelocity;
             } else {
               throw unimap::InputError("motion '" + motion + "': use imu, odometry or constant-velocity");
             }
             s.encoder_stream = encoder;
             s.odometry_stream = odometry;
             s.threads = threads;
             s.loop_closure = loop_closure;
             return std::make_unique<unimap::Mapper>(s);
           }),
           py::arg("platform_file"), py::arg("live") = false, py::arg("motion") = "imu", py::arg("encoder") = true,
           py::arg("odometry") = false, py::arg("threads") = 1, py::arg("loop_closure") = true)
      .def(
          "add_imu",
          [](unimap::Mapper& self, double time_s, const Eigen::Vector3d& gyro_rad_s,
             const Eigen::Vector3d& accel_m_s2) {
            self.AddImu({time_s, accel_m_s2, gyro_rad_s});
          },
          py::arg("time_s"), py::arg("gyro_rad_s"), py::arg("accel_m_s2"), py::call_guard<py::gil_scoped_release>())
      .def(
          "add_encoder",
          [](unimap::Mapper& self, double time_s, double angle_rad) {
            self.AddEncoder({time_s, angle_rad});
          },
          py::arg("time_s"), py::arg("angle_rad"), py::call_guard<py::gil_scoped_release>())
      .def(
          "add_odometry",
          [](unimap::Mapper& self, double time_s, const Eigen::Matrix4d& T_odom_body) {
            unimap::OdometrySample s;
            s.time_s = time_s;
            s.T_odom_body.matrix() = T_odom_body;
            self.AddOdometry(s);
          },
          py::arg("time_s"), py::arg("T_odom_body"), py::call_guard<py::gil_scoped_release>())
      .def(
          "add_scan",
          [](unimap::Mapper& self, const FloatRows& points, std::optional<FloatRows> times,
             std::optional<double> start_time_s, std::optional<double> end_time_s,
             std::optional<py::array_t<std::uint16_t>> rings) {
            const unimap::RawScan scan =
                MakeSweep(points, std::move(times), start_time_s, end_time_s, std::move(rings));
            const py::gil_scoped_release release;  // other Python threads run while the scan is processed
            self.AddScan(scan);
          },
          py::arg("points"), py::arg("times") = py::none(), py::arg("start_time_s") = py::none(),
          py::arg("end_time_s") = py::none(), py::arg("rings") = py::none())
      .def(
          "add",
          [](unimap::Mapper& self, const py::tuple& event) {
            // An event of read_dataset.
            // (Cast with the GIL held; processed without it.)
            const std::string kind = event[0].cast<std::string>();
            if (kind == "imu") {
              const auto sample = event[1].cast<unimap::ImuSample>();
              const py::gil_scoped_release release;
              return self.AddImu(sample);
            }
            if (kind == "encoder") {
              const auto sample = event[1].cast<unimap::EncoderSample>();
              const py::gil_scoped_release release;
              return self.AddEncoder(sample);
            }
            if (kind == "odometry") {
              const auto sample = event[1].cast<unimap::OdometrySample>();
              const py::gil_scoped_release release;
              return self.AddOdometry(sample);
            }
            if (kind == "scan") {
              const auto& scan = event[1].cast<const unimap::RawScan&>();
              const py::gil_scoped_release release;
              return self.AddScan(scan);
            }
            if (kind == "line") {
              const auto& scan = event[1].cast<const unimap::LineScan&>();
              const py::gil_scoped_release release;
              return self.AddScan(scan);
            }
            throw unimap::InputError("add: unknown event kind '" + kind + "'");
          },
          py::arg("event"))
      .def("set_pose_callback",
           [](unimap::Mapper& self, std::function<void(double, Eigen::Matrix4d, bool)> callback) {
             self.SetPoseCallback([callback](const unimap::MapperPose& pose) {
               py::gil_scoped_acquire gil;
               callback(pose.time_s, pose.T_odom_body.matrix(), pose.matched);
             });
           })
      .def("finish", &unimap::Mapper::Finish, py::call_guard<py::gil_scoped_release>())
      .def(
          "poses",
          [](const unimap::Mapper& self) {
            return PoseRows(self.Poses(),
                            [](const unimap::MapperPose& p) -> const Eigen::Isometry3d& { return p.T_odom_body; });
          },
          "The filter's scan poses (odometry frame) as (N, 8) TUM rows")
      .def(
          "trajectory", [](const unimap::Mapper& self) { return PoseRows(self.Trajectory()); },
          "The optimised trajectory (world frame) as (N, 8) TUM rows")
      .def(
          "map_points",
          [](const unimap::Mapper& self, double voxel_m) {
            const std::vector<Eigen::Vector3f> points = self.MapPoints(voxel_m);
            py::array_t<float> out({static_cast<py::ssize_t>(points.size()), py::ssize_t{3}});
            auto rows = out.mutable_unchecked<2>();
            for (std::size_t i = 0; i < points.size(); ++i) {
              for (int a = 0; a < 3; ++a) rows(static_cast<py::ssize_t>(i), a) = points[i][a];
            }
            return out;
          },
          py::arg("voxel_m") = 0.1)
      .def("write_map", &unimap::Mapper::WriteMap, py::arg("path"), py::arg("voxel_m") = 0.1)
      .def("status",
           [](const unimap::Mapper& self) {
             const unimap::MapperStatus s = self.Status();
             py::dict d;
             d["scans_added"] = s.scans_added;
             d["scans_processed"] = s.scans_processed;
             d["scans_matched"] = s.scans_matched;
             d["key_scans"] = s.key_scans;
             d["submaps"] = s.submaps;
             d["loop_closures"] = s.loop_closures;
             d["lag_s"] = s.lag_s;
             d["events_waiting"] = s.events_waiting;
             return d;
           })
      .def_property_readonly("payload", &unimap::Mapper::PayloadName);

  py::class_<unimap::Dataset>(m, "Dataset",
                              "A dataset folder's events in time order: iterate for (kind, sample) tuples, "
                              "kind one of imu, encoder, odometry, scan, line.")
      .def(py::init<const std::string&>(), py::arg("folder"))
      .def("__iter__", [](unimap::Dataset& self) -> unimap::Dataset& { return self; })
      .def("__next__",
           [](unimap::Dataset& self) {
             std::optional<unimap::DatasetEvent> event = self.Next();
             if (!event) throw py::stop_iteration();
             return EventTuple(std::move(*event));
           })
      .def_property_readonly("info",
                             [](const unimap::Dataset& self) {
                               const unimap::DatasetInfo& i = self.info();
                               py::dict d;
                               d["payload"] = i.payload;
                               d["scenario"] = i.scenario;
                               d["duration_s"] = i.duration_s;
                               d["has_imu"] = i.has_imu;
                               d["has_encoder"] = i.has_encoder;
                               d["has_odometry"] = i.has_odometry;
                               d["has_groundtruth"] = i.has_groundtruth;
                               return d;
                             })
      .def("ground_truth", [](const unimap::Dataset& self) { return PoseRows(self.GroundTruth()); });
  m.def(
      "read_dataset", [](const std::string& folder) { return std::make_unique<unimap::Dataset>(folder); },
      py::arg("folder"), "The events of a dataset folder (a Dataset to iterate).");
}
