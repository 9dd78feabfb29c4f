// Gomez Jauregui's real-time particle filter (thesis §4.4.4): CONDENSATION over the body's DOF
// state with five heuristics, each of which can be switched off -- H1 deterministic
// weight-proportional resampling with elitism, H2 hierarchical partitioned diffusion of only the
// parts whose region overlap dropped, H3 groups of at least n + 1 children turned into a
// Nelder-Mead simplex, H4 kinematic flipping of the arms about the camera rays, H5 arms diffused
// as wrist positions in camera coordinates plus the elbow's swivel angle; and simcap's additions:
// arms proposed reaching the hands' image regions (H5 from the image), arms and legs proposed
// reaching the silhouette's geodesic extremities (limb ends), and for a walking body its
// reflection across the camera ray (front/back), tested as H4 tests flips, and its root slid
// in depth to meet the silhouette's feet and top rows.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "tracker/gomez/arm_kinematics.h"
#include "tracker/gomez/body_mirror.h"
#include "tracker/gomez/hand_blobs.h"
#include "tracker/gomez/pose_scorer.h"
#include "tracker/gomez/silhouette_ends.h"

namespace simcap::tracker::gomez {

struct FilterOptions {
  int particles = 200;
  bool h1_resampling = true;   // else CONDENSATION's random resampling
  bool h2_partitioned = true;  // else every DOF is diffused
  bool h3_simplex = true;      // else every child is diffused
  bool h4_flipping = true;
  bool h5_end_effector = true;  // else the arms' angles are diffused
  double diffusion = 1.0;       // S of eq. 4.13: multiplies every DOF's step
  // H2: a part moved when its overlap dropped by this fraction of what it was (alpha^k, eq. 4.20).
  double motion_fraction = 0.05;
  // The root moves on at its last velocity before diffusion (simcap's addition for walking: the
  // thesis's seated user kept his place).
  bool root_velocity = true;
  // H5: the wrists' diffusion in camera coordinates (the thesis's 70, 70 and 150 mm along the
  // depth), and the elbow swivel's, radians.
  Eigen::Vector3d wrist_sigma_m = Eigen::Vector3d(0.07, 0.07, 0.15);
  double swivel_sigma = 0.2;
  // H3: the share of a simplex group's iterations spent on the region energy before the rest
  // goes to the edge energy from the same simplex (thesis §3.6.2.2: regions first, then edges).
  double simplex_region_share = 0.5;
  // H4: how many groups, largest first, have their best particle flipped.
  int flip_groups = 2;
  // The front/back ambiguity of a silhouette (simcap's addition): how many groups, largest first,
  // have their best particle reflected through the vertical plane across the camera ray
  // (BodyMirror::reflect), joining the pool only when it beats every particle, and only on a
  // body whose colours tell front from back (tells_front_from_back); 0 is off.
  int mirror_groups = 1;
  // H5 driven by the image (simcap's addition): the far ends of the regions of the hands' colour
  // class (hand_blobs) that no hand of the best particle explains are reached by the arms whose
  // hand explains none, at this many depths along their camera ray (ArmKinematics::reach_ray);
  // the poses join the pool as H4's flips do. A lost arm comes back from where the image shows
  // its hand, not from diffusion about the last pose. Off on a body whose hands have the trunk's
  // class (no region of their own); 0 is off.
  int hand_depths = 2;
  // Limb ends from the silhouette (simcap's addition, for hands and feet whatever their colour):
  // the geodesic extremities of the silhouette from the best particle's trunk (silhouette_ends)
  // that no hand, foot, elbow, knee or head of that pose explains are each claimed by the nearest
  // hand or foot that explains none (assign_ends), and that limb is proposed reaching it: at its
  // present depth (the ray's point nearest it), and at this many depths minus one spread along
  // the ray's stretch it reaches (ArmKinematics::reach_point, reach_ray; the legs' too); the poses
  // join the pool as H4's flips do. 0 is off.
  int limb_end_depths = 0;
  // Whether the feet are moved to the extremities they claim (else they still claim them, so that
  // a hand is not sent to a foot's extremity, but stay).
  bool limb_end_legs = false;
  // The root's depth from the silhouette's feet and top rows (simcap's addition for the full
  // body on the floor): how many groups, largest first, have their best particle slid along the
  // ground under its camera ray to where its image extent meets those rows
  // (root_depth_proposal); a slid pose joins the pool only when it beats every particle (as a
  // reflection does). A step towards the camera changes the costs too little for the diffusion
  // to follow it; 0 is off.
  int depth_groups = 1;
  std::uint64_t seed = 1;
};

struct FilterStep {
  State best;
  State mean;  // the particles' weighted mean
  Score score;
  Energy energy;
  int evaluations = 0;
  int groups = 0;                        // parents with children
  int simplex_groups = 0;                // of which refined by Nelder-Mead (H3)
  int flips = 0;                         // kinematic flips tested (H4)
  int reflected = 0;                     // front/back reflections that joined (beat every particle)
  int hand_proposals = 0;                // image-driven hand proposals tested (H5)
  int limb_end_proposals = 0;            // limbs reaching the silhouette's extremities tested
  int depth_proposals = 0;               // root depths from the feet and top rows tested
  std::array<bool, kPartCount> moved{};  // H2's motion detection
};

// Whether H2 diffuses `dof` when the parts `moved` moved: the DOFs of those parts, and the root's
// translation also when a leg moved. The translation belongs to the torso, but a walk's slow
// start shifts the torso by about a pixel a frame, too little for H2 to see, while the legs'
// stride shows (simcap's addition for the full body; the thesis's seated user did not walk).
bool h2_diffuses(const Dof& dof, const std::array<bool, kPartCount>& moved);

class ParticleFilter {
 public:
  // Keeps references to the scorer, the arms (`arms` may be null when H4 and H5 are off) and the
  // legs (may be null: no leg proposals).
  ParticleFilter(const PoseScorer& scorer, const ArmKinematics* arms, const FilterOptions& options,
                 const ArmKinematics* legs = nullptr);

  // Every particle at `x0`, scored on `cues`.
  void reset(const State& x0, const FrameCues& cues);
  // One frame: resample, predict (H2, H3, H5), flip (H4), measure. `previous` is the last
  // frame's cues (for H2), `frame` seeds this frame's random numbers.
  FilterStep step(const FrameCues& previous, const FrameCues& current, int frame);

  const std::vector<State>& particles() const { return particles_; }
  const std::vector<double>& energies() const { return energies_; }

 private:
  struct Rng;
  State diffuse(const State& x, const std::array<bool, kPartCount>& parts, Rng& rng,
                const Eigen::Matrix3d& camera_to_world) const;
  // Poses of `x` with a free arm reaching an unexplained hand region of `cues` (hand_depths).
  std::vector<State> hand_proposals(const State& x, const FrameCues& cues) const;
  // Poses of `x` with a hand or foot reaching an unexplained extremity of the silhouette of
  // `cues` (limb_end_depths).
  std::vector<State> limb_end_proposals(const State& x, const FrameCues& cues) const;
  // Pixels of each part of `x` whose colour class the image shows there (full resolution).
  std::array<double, kPartCount> part_overlap(const State& x, const FrameCues& cues) const;

  const PoseScorer* scorer_;
  const ArmKinematics* arms_;
  const ArmKinematics* legs_;
  BodyMirror mirror_;
  bool mirror_tells_ = false;  // tells_front_from_back of the scorer's body
  // The hands' capsules (left, right; -1: none), their colour class when it differs from the
  // trunk's (0: no hand proposals), and the face's capsule.
  int hand_capsule_[2] = {-1, -1};
  int foot_capsule_[2] = {-1, -1};
  std::uint8_t hand_class_ = 0;
  int face_capsule_ = -1;
  FilterOptions options_;
  std::vector<State> particles_;
  std::vector<double> energies_;
  std::vector<Score> scores_;
  State best_, previous_best_;
};

}  // namespace simcap::tracker::gomez
