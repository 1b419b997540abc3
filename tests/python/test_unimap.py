"""Python bindings (module `unimap`): a simulated dataset mapped through
Python gives unimap run's results; bad input raises. Run by ctest
(python.unimap) with PYTHONPATH at the built module and UNIMAP_EXE at the
unimap executable; UNIMAP_SOURCE_DIR is the repository."""
import os
import subprocess
import tempfile
import threading
import unittest

import numpy as np

import unimap

EXE = os.environ["UNIMAP_EXE"]
SOURCE = os.environ["UNIMAP_SOURCE_DIR"]
HOKUYO = os.path.join(SOURCE, "configs/platforms/rotating_hokuyo.yaml")
VLP16 = os.path.join(SOURCE, "configs/platforms/fixed_vlp16.yaml")


def tum_rows(path):
    return np.array([[float(v) for v in line.split()] for line in open(path)
                     if line.strip() and not line.startswith("#")])


class MappingTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.data = os.path.join(cls.tmp.name, "data")
        cls.run_dir = os.path.join(cls.tmp.name, "run")
        subprocess.run([EXE, "simulate", "--quiet", "--scenario", os.path.join(SOURCE, "configs/scenarios/tunnel.yaml"),
                        "--duration-s", "20", "--out", cls.data], check=True, stdout=subprocess.DEVNULL)
        subprocess.run([EXE, "run", "--quiet", "--platform", HOKUYO, "--data", cls.data, "--out", cls.run_dir],
                       check=True, stdout=subprocess.DEVNULL)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_dataset_events_in_time_order(self):
        dataset = unimap.read_dataset(self.data)
        self.assertEqual(dataset.info["payload"], "rotating_2d")
        self.assertTrue(dataset.info["has_imu"])
        kinds, last = {}, -1.0
        for kind, sample in dataset:
            t = sample.start_time_s + (len(sample.ranges_m) - 1) * sample.time_increment_s if kind == "line" \
                else sample.time_s
            self.assertGreaterEqual(t, last)
            last = t
            kinds[kind] = kinds.get(kind, 0) + 1
        self.assertEqual(set(kinds), {"imu", "encoder", "line"})
        self.assertEqual(kinds["line"], 800)  # 20 s of 40 Hz lines
        self.assertEqual(dataset.ground_truth().shape[1], 8)

    def test_synchronous_mapping_equals_unimap_run(self):
        mapper = unimap.Mapper(HOKUYO)
        self.assertEqual(mapper.payload, "rotating_2d")
        seen = []
        mapper.set_pose_callback(lambda t, T, matched: seen.append(t))
        for event in unimap.read_dataset(self.data):
            mapper.add(event)
        mapper.finish()
        poses, trajectory = mapper.poses(), mapper.trajectory()
        np.testing.assert_array_equal(poses, tum_rows(os.path.join(self.run_dir, "trajectory_odometry.tum")))
        np.testing.assert_array_equal(trajectory, tum_rows(os.path.join(self.run_dir, "trajectory.tum")))
        self.assertEqual(seen, list(poses[:, 0]))
        status = mapper.status()
        self.assertEqual(status["scans_added"], 800)
        self.assertEqual(status["scans_processed"], 800)
        self.assertGreater(status["scans_matched"], 700)
        points = mapper.map_points()
        self.assertEqual(points.shape[1], 3)
        self.assertEqual(points.dtype, np.float32)
        out = os.path.join(self.tmp.name, "map.ply")
        mapper.write_map(out)
        with open(out, "rb") as mine, open(os.path.join(self.run_dir, "map.ply"), "rb") as theirs:
            self.assertEqual(mine.read(), theirs.read())

    def test_streams_added_out_of_order_across_streams(self):
        # All IMU and encoder samples first, then the lines: the mapper
        # merges the streams by time, so the result is the same.
        by_kind = {"imu": [], "encoder": [], "line": []}
        for kind, sample in unimap.read_dataset(self.data):
            by_kind[kind].append((kind, sample))
        mapper = unimap.Mapper(HOKUYO)
        for kind in ("line", "encoder", "imu"):
            for event in by_kind[kind]:
                mapper.add(event)
        mapper.finish()
        np.testing.assert_array_equal(mapper.poses(), tum_rows(os.path.join(self.run_dir, "trajectory_odometry.tum")))


    def test_one_thread_per_stream(self):
        # Three Python threads add their streams concurrently (the mapper
        # releases the GIL while it processes): the same poses.
        by_kind = {"imu": [], "encoder": [], "line": []}
        for kind, sample in unimap.read_dataset(self.data):
            by_kind[kind].append((kind, sample))
        mapper = unimap.Mapper(HOKUYO)

        def feed(events):
            for event in events:
                mapper.add(event)
        threads = [threading.Thread(target=feed, args=(events,)) for events in by_kind.values()]
        for thread in threads:
            thread.start()
        for thread in threads:
            thread.join()
        mapper.finish()
        np.testing.assert_array_equal(mapper.poses(), tum_rows(os.path.join(self.run_dir, "trajectory_odometry.tum")))


class InputTest(unittest.TestCase):
    def test_bad_platform_file_names_it(self):
        with self.assertRaisesRegex(ValueError, "no_such_platform.yaml"):
            unimap.Mapper("no_such_platform.yaml")

    def test_bad_motion_and_threads(self):
        with self.assertRaisesRegex(ValueError, "motion 'wheels'"):
            unimap.Mapper(HOKUYO, motion="wheels")
        with self.assertRaisesRegex(ValueError, "threads 0"):
            unimap.Mapper(HOKUYO, threads=0)

    def test_sweep_arrays_are_checked(self):
        mapper = unimap.Mapper(VLP16)
        with self.assertRaisesRegex(ValueError, r"\(N, 3\) or \(N, 4\)"):
            mapper.add_scan(np.zeros((10, 2)), end_time_s=1.0)
        with self.assertRaisesRegex(ValueError, "one time per point"):
            mapper.add_scan(np.zeros((10, 3)), times=np.zeros(9))
        with self.assertRaisesRegex(ValueError, "times= .* or end_time_s="):
            mapper.add_scan(np.zeros((10, 3)))

    def test_time_going_backwards_in_a_stream(self):
        mapper = unimap.Mapper(VLP16)
        mapper.add_imu(1.0, [0, 0, 0], [0, 0, 9.81])
        with self.assertRaisesRegex(ValueError, "IMU time 0.5 s is before"):
            mapper.add_imu(0.5, [0, 0, 0], [0, 0, 9.81])
        with self.assertRaisesRegex(ValueError, "non-finite"):
            mapper.add_imu(float("nan"), [0, 0, 0], [0, 0, 9.81])

    def test_no_data_after_finish(self):
        mapper = unimap.Mapper(VLP16)
        mapper.finish()
        with self.assertRaisesRegex(ValueError, "finished"):
            mapper.add_imu(1.0, [0, 0, 0], [0, 0, 9.81])
        self.assertEqual(mapper.poses().shape, (0, 8))


if __name__ == "__main__":
    unittest.main()
