// The arm bones' shading as a depth cue (simcap's addition): a bone and its kinematic flip (H4)
// cover the same pixels, but under a directional light the two are shaded differently. Each arm
// bone is a Lambert cylinder whose image grey is an affine function, per colour class, of its
// mean visible-normal Lambert term, compared with the grey of the pixels the hypothesis draws.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <vector>

#include "core/camera.h"
#include "models/skeleton.h"
#include "tracker/gomez/body_shape.h"
#include "tracker/gomez/colour_classes.h"
#include "tracker/gomez/frame_cues.h"
#include "tracker/gomez/label_renderer.h"

namespace simcap::tracker::gomez {

// Mean of max(0, n . l) over the half of a cylinder's surface the camera sees, each normal
// weighted by the width it projects to (so the mean over the cylinder's image pixels):
// `axis` its direction, `to_camera` from it towards the camera, `to_light` the unit direction
// towards the light, all in one frame. A cylinder seen end-on gives its cap's max(0, v . l).
double lambert_cylinder_mean(const Eigen::Vector3d& axis, const Eigen::Vector3d& to_camera,
                             const Eigen::Vector3d& to_light);

// Upper arms and forearms, left then right.
inline constexpr int kShadedBones = 4;

// A directional light and each colour class's grey under it: grey = albedo * lambert + offset
// (the offset holds the ambient term); camera coordinates.
struct Lighting {
  Eigen::Vector3d to_light = Eigen::Vector3d::Zero();  // unit; zero: not known yet
  std::array<double, kMaxColourClasses + 1> albedo{}, offset{};
  bool known() const { return to_light.squaredNorm() > 0; }
};

// One bone as posed: its axis and the direction from its middle towards the camera (camera
// coordinates), its colour class and its image pixels' mean grey.
struct BoneSample {
  Eigen::Vector3d axis = Eigen::Vector3d::Zero(), to_camera = Eigen::Vector3d::Zero();
  std::uint8_t cls = 0;
  double grey = 0;
  int pixels = 0;
};

class BoneShading {
 public:
  // A bone is compared only where it shows at least this many working pixels of its class.
  static constexpr int kMinPixels = 5;

  BoneShading() = default;
  // The arm bones' capsules of `shape` (carried by the shoulders and elbows) and the class most
  // of their cells have; only those cells' pixels are compared (a short sleeve's skin is not).
  BoneShading(const BodyShape& shape, const Skeleton& skeleton,
              const std::vector<std::uint8_t>& cell_class);
  bool available() const { return capsule_[kShadedBones - 1] >= 0; }

  // The bones of `labels` (rendered for `world` in `cues.view`) against the image's grey where
  // the image's class is the bone's.
  std::array<BoneSample, kShadedBones> observe(const LabelImage& labels,
                                               const std::vector<Eigen::Isometry3d>& world,
                                               const FrameCues& cues) const;

 private:
  std::array<int, kShadedBones> capsule_{-1, -1, -1, -1};
  std::array<Capsule, kShadedBones> bone_{};
  std::array<std::uint8_t, kShadedBones> class_{};
  std::vector<std::int8_t> cell_bone_;  // per colour cell: its bone, -1 when not compared
};

// The grey `lighting` predicts for a bone.
double predicted_grey(const BoneSample& bone, const Lighting& lighting);
// The bone's depth flip: its axis reflected through the plane across its line of sight (the same
// image, the other depth; H4's flip of that bone alone).
BoneSample depth_flip(const BoneSample& bone);
// The sum over the bones showing at least BoneShading::kMinPixels of how much worse each bone's
// squared grey difference is than its depth flip's (0 where the pose's side explains the grey
// better). The two share the pixels, so what the Lambert cylinder does not model (the mesh,
// shadows, a bone's pixels mixed with the trunk's) moves both alike: only the side is judged, not
// where the bone lies in the image.
double flip_penalty(const std::array<BoneSample, kShadedBones>& bones, const Lighting& lighting);

}  // namespace simcap::tracker::gomez
