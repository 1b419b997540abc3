#pragma once
#include <string>

#include <Eigen/Geometry>

#include "unimap/BodyScan.hpp"
#include "unimap/Deskew.hpp"
#include "unimap/EncoderTrack.hpp"
#include "unimap/ParameterMap.hpp"
#include "unimap/ParameterSet.hpp"
#include "unimap/RawScan.hpp"

namespace unimap {

// A LiDAR payload's sensor model. One per plugin library, created by the
// factory that UNIMAP_EXPORT_PAYLOAD_PLUGIN exports. Methods marked const are
// safe to call concurrently once configured.
class PayloadPlugin {
 public:
  PayloadPlugin() = default;
  PayloadPlugin(const PayloadPlugin&) = delete;
  PayloadPlugin& operator=(const PayloadPlugin&) = delete;
  virtual ~PayloadPlugin() = default;

  // Payload name, equal to the library's: libunimap_payload_<Name()>.so.
  virtual std::string Name() const = 0;
  // One line describing the sensor rig.
  virtual std::string Description() const = 0;
  // Every parameter understood: CoreParameters keys plus payload-specific ones.
  virtual ParameterSet Defaults() const = 0;
  // Applies effective parameters (all keys of Defaults()); throws ConfigError; repeatable.
  virtual void Configure(const ParameterMap& parameters) = 0;
  // True when scans need motor encoder samples (a LiDAR on a motor).
  virtual bool UsesEncoder() const = 0;
  // Motor angle (rad) at time_s from the encoder; 0 without a motor; throws InputError outside coverage.
  virtual double MotorAngleAt(const EncoderTrack& encoder, double time_s) const = 0;
  // T_body_lidar at time_s; throws InputError outside encoder coverage.
  virtual Eigen::Isometry3d BodyFromLidarAt(const EncoderTrack& encoder, double time_s) const = 0;
  // The scan's points in the body frame at its end time; throws InputError on bad input.
  virtual BodyScan Deskew(const RawScan& scan, const EncoderTrack& encoder,
                          const MotionQuery& T_world_body_at) const = 0;
};

}  // namespace unimap
