#pragma once
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>

#include "io/DatasetConversion.hpp"

namespace unimap::io {

// A recording (KITTI sequence, CARMEN log, ROS 1 or ROS 2 bag) read as a
// dataset without writing one: the conversion `unimap convert` would run
// (io::Convert) runs on a thread of its own into bounded per-stream queues,
// and the Next* calls take from them, so a run maps the recording as it is
// read (DatasetReader's raw-input constructor). Each stream comes in time
// order (the conversion's reorder window); the queues hold at most
// QueueLimits, so memory does not grow with the recording.
class LiveConversion {
 public:
  // How much the queues hold before the conversion waits for the reader.
  struct QueueLimits {
    std::size_t max_items = 100000;         // items of every sensor stream together
    std::size_t max_scans = 64;             // scans
    std::size_t max_scan_points = 1000000;  // points (beams) of the scans held (~8 HDL-64 sweeps)
  };

  // Starts the conversion of options.input as `format` (options.output and
  // open_sink are not used) and waits for the dataset's metadata; throws what
  // the conversion throws before it has any (InputError: the recording
  // cannot be opened, a topic choice is ambiguous, ...).
  LiveConversion(std::string format, ConversionOptions options, QueueLimits limits);
  LiveConversion(std::string format, ConversionOptions options)
      : LiveConversion(std::move(format), std::move(options), QueueLimits{}) {}
  // Stops the conversion (if it is still reading) and waits for its thread.
  ~LiveConversion();
  LiveConversion(const LiveConversion&) = delete;
  LiveConversion& operator=(const LiveConversion&) = delete;

  const DatasetMetadata& metadata() const { return metadata_; }

  // The stream's next item. Waits while the stream is empty and the
  // conversion is still reading with room in its queues; std::nullopt when
  // the stream is empty and the conversion has ended, or when the queues are
  // full (then the stream has nothing to give before the items held: it is
  // absent or sparse; a later call may still return an item). Once every
  // queue is empty after a conversion that failed, throws its error (once).
  std::optional<ImuSample> NextImu();
  std::optional<EncoderSample> NextEncoder();
  std::optional<OdometrySample> NextOdometry();
  std::optional<ScanRecord> NextScan();
  // The next ground-truth pose received so far (does not wait).
  std::optional<StampedPose> NextGroundTruth();
  // Whether any ground truth has been received so far.
  bool has_groundtruth() const;
  // The conversion's report once it has ended by itself (std::nullopt while
  // it reads, or when it was stopped by the destructor or failed).
  std::optional<ConversionReport> report() const;

 private:
  class Sink;
  // Items are held by pointer: moving a std::variant through a deque trips
  // GCC 12's -Wmaybe-uninitialized false positive (as in TimeReorderBuffer).
  template <typename T>
  using Queue = std::deque<std::unique_ptr<T>>;
  template <typename T>
  std::optional<T> Take(Queue<T>* queue);
  bool Full() const;  // (mutex held)
  void Produce(const std::string& format, ConversionOptions options);

  mutable std::mutex mutex_;
  std::condition_variable changed_;
  DatasetMetadata metadata_;
  bool has_metadata_ = false;
  bool done_ = false;       // the conversion has ended (finished, failed or stopped)
  bool cancelled_ = false;  // the destructor asks the conversion to stop
  std::atomic<bool> stop_{false};
  std::exception_ptr error_;
  std::optional<ConversionReport> report_;
  QueueLimits limits_;
  std::size_t items_ = 0;        // items held in the four sensor queues
  std::size_t scan_points_ = 0;  // points (beams) of the scans held
  Queue<ImuSample> imu_;
  Queue<EncoderSample> encoder_;
  Queue<OdometrySample> odometry_;
  Queue<ScanRecord> scans_;
  Queue<StampedPose> groundtruth_;
  bool any_groundtruth_ = false;
  std::thread thread_;
};

}  // namespace unimap::io
