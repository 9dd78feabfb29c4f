// The colours of the body's parts, learned on a frame whose pose is known, so that a silhouette
// ray through a forearm held in front of the torso is known to belong to an arm.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "tracker/moschini/body_surface.h"
#include "tracker/moschini/icp_targets.h"
#include "tracker/moschini/stick_model.h"

namespace simcap::tracker {

struct AppearanceOptions {
  // A ray teaches a part's colour only when it passes this fraction of the part's radius inside
  // it (grazing rays mix the part with what lies behind it).
  double inside_fraction = 0.4;
  int min_samples = 20;  // a part seen by fewer rays keeps no colour model and is never excluded
  // A colour may belong to a part when the squared Mahalanobis distance of its chromaticity to
  // the part's Gaussian is below this (χ² with 2 degrees of freedom, 99.9%).
  double max_distance2 = 13.8;
  double noise_floor = 0.02;   // added to the chromaticity's standard deviations
  double min_brightness = 90;  // sum of the channels below which a colour says nothing
  int max_materials = 6;
  double min_share = 0.1;  // a part wears a material that makes up this share of its samples
};

class AppearanceModel {
 public:
  // All parts allowed for every colour.
  AppearanceModel();
  // From the rays of one frame (with their colours) and the pose of that frame. Left and right
  // parts share one model: a limb hidden on this frame takes its partner's colours.
  AppearanceModel(const StickModel& model, const BodySurface& surface, const StickPose& pose,
                  const std::vector<SilhouetteRay>& rays, const AppearanceOptions& options = {});
  // The parts (bit s = Segment s) a pixel of this colour may show; every part when the colour
  // fits none of the learned ones (a foot, a shadow).
  std::uint16_t parts(const std::array<std::uint8_t, 3>& colour) const {
    return table_[code(colour)];
  }
  // Learns what the other people in view wear from colours of their pixels (those the person
  // gate dropped), so that foreign() also tells colours closer to theirs than to the person's.
  void learn_others(const std::vector<std::array<std::uint8_t, 3>>& colours,
                    const AppearanceOptions& options = {});
  // Whether a pixel of this colour is someone else's: it is bright enough to say and fits none
  // of the materials the person wears, or fits a material of the others' (learn_others) better.
  // Never before learning.
  bool foreign(const std::array<std::uint8_t, 3>& colour) const {
    return !foreign_.empty() && foreign_[code(colour)];
  }
  // Whether a pixel of this colour is the person's alone: it fits a material the person wears
  // and none of the others' (learn_others). Never before learning.
  bool distinct(const std::array<std::uint8_t, 3>& colour) const {
    return !distinct_.empty() && distinct_[code(colour)];
  }
  // How many parts have a colour model.
  int learned_parts() const { return learned_; }

 private:
  static int code(const std::array<std::uint8_t, 3>& colour) {
    return (colour[0] >> 3) << 10 | (colour[1] >> 3) << 5 | (colour[2] >> 3);
  }
  struct Material {
    Eigen::Vector2d mean;
    Eigen::Matrix2d inverse;  // of the chromaticity's covariance
    // Squared Mahalanobis distance of chromaticity c.
    double distance2(const Eigen::Vector2d& c) const {
      return (c - mean).dot(inverse * (c - mean));
    }
  };
  std::vector<Material> dress_;         // the person's materials
  std::vector<std::uint16_t> table_;    // per colour quantized to 5 bits per channel
  std::vector<std::uint8_t> foreign_;   // per quantized colour, when learned
  std::vector<std::uint8_t> distinct_;  // per quantized colour, when learned
  int learned_ = 0;
};

}  // namespace simcap::tracker
