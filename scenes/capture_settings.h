// The nuisances of a real capture a scene can switch on, each off by default: a calibration that
// is slightly wrong, cameras out of sync, a rolling shutter, automatic exposure, changing light.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

namespace simcap {

// rig.calibration_error: how far the calibration written to calibration/ is from the cameras the
// images were rendered with. Each camera is off by exactly these amounts, in random directions
// drawn from (seed, camera name): a rotation of rotation_deg about a random axis, its centre moved
// by translation_m, fx and fy scaled by 1 + focal_rel or 1 - focal_rel, the principal point moved
// by principal_px.
struct CalibrationError {
  double rotation_deg = 0;
  double translation_m = 0;
  double focal_rel = 0;
  double principal_px = 0;
  std::uint64_t seed = 1;

  bool any() const {
    return rotation_deg > 0 || translation_m > 0 || focal_rel > 0 || principal_px > 0;
  }
};

// rig.sync, rig.readout_ms and rig.auto_exposure: when and how each camera captures. Camera c's
// row r of dataset frame i is captured at (first_frame + i) / fps + offset_c + readout * r /
// (height - 1). Kept in milliseconds, as written, so that the resolved scene reads back exactly.
struct CaptureTiming {
  // Per camera in rig order (offset_ms), or empty: then offset_sigma_ms and seed draw a Gaussian
  // offset per camera from (seed, camera name); both empty and zero: every camera is in sync.
  std::vector<double> offset_ms;
  double offset_sigma_ms = 0;
  std::uint64_t seed = 1;
  double readout_ms = 0;  // rolling shutter: time from the first row's capture to the last's
  bool auto_exposure = false;

  bool synchronised() const {
    return offset_sigma_ms == 0 &&
           std::all_of(offset_ms.begin(), offset_ms.end(), [](double o) { return o == 0; });
  }
};

// One keyframe of a light (lights[i].keyframes): at scene time time_s the light has the values
// given; each value is interpolated linearly between the keyframes that give it (directions are
// normalised after interpolation) and held before the first and after the last.
struct LightKeyframe {
  double time_s = 0;
  std::optional<double> intensity;
  std::optional<Eigen::Vector3d> position;   // point lights
  std::optional<Eigen::Vector3d> direction;  // directional lights, non-zero, as written
};

}  // namespace simcap
