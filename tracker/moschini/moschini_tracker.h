// Moschini's tracking loop (Alg. 3) on observed frames: articulated ICP from the previous pose,
// a final refinement, then the EKF; detects lost tracking and re-initializes instead of drifting.
#pragma once

#include <optional>

#include <string>
#include <vector>

#include "tracker/moschini/articulated_icp.h"
#include "tracker/moschini/ekf.h"
#include "tracker/moschini/perception.h"
#include "tracker/moschini/pose_init.h"
#include "tracker/moschini/stick_model.h"

namespace simcap::tracker {

// Lost tracking is declared when, for `lost_frames` frames in a row, the ICP residual exceeds
// `lost_distance_m` or more than `lost_outside_fraction` of the model's sticks lie outside the
// hull. The tracker then searches upright hypotheses (plus the current pose) and restarts the
// filter from the best-scoring one.
struct RecoveryOptions {
  double lost_distance_m = 0.05;
  // A high residual alone does not mean lost: a person standing with the legs together and the
  // arms at the sides gives one centerline down the middle, far from every stick, while the
  // model lies wholly inside the hull; the recovery would trade that fit for merged limbs.
  double lost_distance_outside = 0.01;
  double lost_outside_fraction = 0.25;
  int lost_frames = 3;
  // Each search makes the next wait twice as many lost frames in a row, up to this many, until a
  // frame is tracked again: a search costs about a second, and on silhouettes too noisy to track
  // one every three frames would make the tracker a hundred times slower for nothing.
  int max_lost_frames = 48;
  int headings = 12;  // upright hypotheses around the circle
  int searched = 4;   // of them, the best fits whose limbs are searched (search_limbs)...
  // ...when tracking is lost, only those whose fit costs less than this many times the current
  // pose: the limb search lowered a hypothesis' cost by at most 2.3 times on the motion suite,
  // and a hypothesis replaces the current pose only below `margin` of its cost. A torso bent
  // over its legs reads as lost for dozens of frames, and each of its searches (a fifth of a
  // second) found the upright hypotheses 2.4 to 10 times costlier than its fit.
  double search_within = 2.0;
  // A recovered pose replaces the current fit only when it costs less than this fraction of
  // it: on a hard frame a wrong pose can cost a little less than a right one. It must pass
  // twice: by the joint refinement's cost (centerline included), and, with
  // TrackerOptions::trust_silhouettes, by the silhouette cost alone, which the centerline's
  // centroids between merged limbs cannot mislead (with the silhouette start,
  // scenes/occluders.yaml's frame 217 otherwise took a hypothesis half a metre off, four times
  // costlier by the silhouettes, for the whole rest of the clip).
  double margin = 0.8;
};

// An arm lost into the trunk's volume (the hull merges them; the walks' swinging arms) has no
// cue to pull it out, but the silhouette of the real arm is then left unexplained in the cameras
// that see it: when two do, both arms are restarted from search_limbs' typical configurations,
// fitted by the silhouettes alone, and the best kept if the polish then favours it.
struct UnexplainedOptions {
  double miss_m = 0.05;    // a silhouette ray missing every capsule by more is unexplained
  double fraction = 0.01;  // of one camera's rays, that trigger the search; 0: off
  int cameras = 2;         // ...in at least this many cameras
  int ray_every = 4;       // the rays counted: every n-th (the check runs on every frame)
  int max_wait = 16;       // frames between searches while they find nothing better
  // How each arm's restarts are fitted and compared, by the silhouettes alone and coarser than
  // the polish (which then fits the best): a search must not cost more than a few frames.
  RefineOptions restart = [] {
    RefineOptions o;
    o.centerline_weight = 0;
    o.ray_every = 2;
    o.rim_step_m = 0.08;
    o.iterations = 4;
    return o;
  }();
};

struct TrackerOptions {
  JointSet joints = JointSet::urdf;
  // The urdf joint set's limits (MoschiniOptions::limits read through urdfdom).
  std::vector<JointLimits> urdf_limits = humanoid_joint_limits();
  // The hypotheses' refinements need only find the right basin: a quarter of the rays and a
  // coarser outline.
  IcpOptions icp = [] {
    IcpOptions o;
    o.refine.ray_every = 2;
    o.refine.rim_step_m = 0.08;
    return o;
  }();
  // The last refinement of each frame, once the hypotheses are decided: without the centerline
  // points. They carry the hull's phantom volume (the centroid of a slice through two merged
  // legs lies between them) and pull the fit off the body, yet they keep the search on it.
  RefineOptions polish = [] {
    RefineOptions o;
    o.centerline_weight = 0;
    o.iterations = 8;
    return o;
  }();
  // Each frame also starts once from the previous pose with the silhouette cues alone (the
  // polish's cues, this many steps) and keeps that fit when the silhouettes favour it over the
  // polished one. The centerline leads the first refinement off the body wherever the hull
  // merges parts (a trunk bent over the legs, arms hanging against the shins, legs together
  // whose four-corner-camera hull also shows them a quarter turn off): on the motion suite the
  // pose it led to cost 6 to 18 times more by the silhouettes than a start from the truth.
  // More steps fit better and cost more (MOSCHINI.md); 0: off.
  RefineOptions silhouette_start = [] {
    RefineOptions o;
    o.centerline_weight = 0;
    o.iterations = 2;
    return o;
  }();
  // The capsules were fitted at a known pose (--init gt's first frame, --init auto's tracked
  // pose of its fifth), so their silhouette cost may overrule the centerline: the silhouette
  // start runs, and a recovery must lower that cost too. Fitted at a guessed pose (--init
  // auto's first frame) they explain the silhouettes worse at the right pose than at the guess,
  // and both kept wrong starts (motion suite, --init auto: 36.6 mm without them, 47.9 with the
  // silhouette start from frame 0, 47.4 with the recovery's test alone).
  bool trust_silhouettes = true;
  FilterNoise filter;
  RecoveryOptions recovery;
  bool use_filter = true;
  // Each frame also tries Moschini's hierarchical traversal (Alg. 2) from the previous pose and
  // keeps whichever fit costs less. Off, the joint refinement alone starts from the previous
  // pose; the traversal then only serves recovery and --init auto (its jumps to where the
  // centerline is lose more limbs than they find on simcap's datasets, see MOSCHINI.md).
  bool traversal = false;
  // Every n-th frame each left/right pair of limbs is also fitted exchanged (the left leg where
  // the right one is) and the exchange kept when it costs less, crossed or not: a tracker that
  // took the wrong leg for the forward one in a stride, or after a jump with the feet together,
  // finds out within n frames. 0: only limbs that cross are tried.
  int swap_check_every = 4;
  UnexplainedOptions unexplained;
};

// Limbs as search_limbs takes them, one bit each.
enum LimbBit : unsigned {
  kLeftArm = 1,
  kRightArm = 2,
  kLeftLeg = 4,
  kRightLeg = 8,
  kAllLimbs = 15
};

struct TrackStep {
  StickPose pose;  // the estimate for this frame
  IcpResult icp;
  double outside_fraction = 0;  // of points sampled along the sticks, outside the hull
  bool reinitialized = false;
  std::string reason;  // why tracking was declared lost
  double icp_ms = 0, filter_ms = 0;
};

class MoschiniTracker {
 public:
  MoschiniTracker(const BodyDimensions& dims, const BodySurface& surface,
                  const TrackerOptions& options = {});
  const StickModel& model() const { return model_; }
  const BodySurface& surface() const { return surface_; }

  // Starts from a known pose (--init gt).
  void start(const StickPose& pose);
  // Starts from the hull of a person standing upright (--init auto): the best of
  // upright_hypotheses() after ICP.
  void start_upright(const Observation& obs);

  // Fits `pose` to `obs` as recovery fits an upright hypothesis (the traversal, then each
  // limb restarted from typical configurations) without moving the tracker.
  StickPose fit_hypothesis(const Observation& obs, StickPose pose) const;
  // The same by the silhouettes alone: the final refinement from `pose`, then each limb
  // restarted from typical configurations, without the traversal and the centerline.
  StickPose fit_hypothesis_to_silhouettes(const Observation& obs, StickPose pose) const;

  TrackStep step(const Observation& obs);
  int reinitializations() const { return reinitializations_; }

  // What ICP fits on this frame.
  static IcpTargets targets_of(const Observation& obs);
  // Lower is better: the joint refinement's cost (centerline, hull, silhouette rays and
  // outlines, priors).
  double score(const StickPose& pose, const Observation& obs) const;
  // The final refinement's cost, without the centerline points: how well the capsules explain
  // the silhouettes alone. The centerline's centroids lie between merged limbs and off a trunk
  // whose hull carries phantom volume; scored with them, a person standing still with the
  // legs together fits a quarter turn off better than at the true pose.
  double silhouette_score(const StickPose& pose, const Observation& obs) const;
  // Fraction of points sampled every voxel along the sticks that lie off the hull.
  double outside_fraction(const StickPose& pose, const Occupancy& hull) const;

 private:
  // The ICP residual and the fraction of the sticks off the hull: what lost tracking is judged by.
  void diagnose(const StickPose& pose, const Observation& obs, TrackStep& out) const;
  StickPose best_upright(const Observation& obs, const StickPose* current) const;
  // For each limb in turn, restarts it from a few typical configurations (hanging, bent forward,
  // across the body, back, raised) and keeps the refinement that scores best: far from the
  // data, a limb's refinement stays in whatever basin it starts in. Returns the cost of the
  // pose kept; `cost`, when known, is the cost of `pose` as given.
  // `by`: the refinement that fits and scores each restart (the joint refinement unless given).
  // `which`: the limbs searched (LimbBit), the others left as they are.
  double search_limbs(const IcpTargets& targets, StickPose& pose, std::optional<double> cost = {},
                      const PoseRefiner* by = nullptr, unsigned which = kAllLimbs) const;
  // Tries each left/right pair of limbs exchanged (the left leg's angles for the right leg's and
  // back) and keeps whichever fit the data favour: when the pair crosses (the left foot or knee,
  // hand or elbow, right of the right one in the torso's frame), and on every frame when
  // `every_pair`. Walking legs pass close by each other, an arm held across the body meets the
  // other, the centerline can then lead each limb onto the other's data, and a stride read
  // with the wrong leg forward fits almost as well as the right one.
  void resolve_swapped_limbs(const IcpTargets& targets, StickPose& pose, bool every_pair) const;
  // Whether `pose` leaves at least UnexplainedOptions::fraction of the silhouette rays of at
  // least UnexplainedOptions::cameras cameras unexplained (missing every capsule by miss_m).
  bool leaves_silhouette_unexplained(const IcpTargets& targets, const StickPose& pose) const;

  StickModel model_;
  BodySurface surface_;
  TrackerOptions options_;
  ArticulatedIcp icp_;
  PoseRefiner refiner_;
  PoseRefiner polisher_;
  PoseRefiner silhouette_starter_;
  PoseRefiner arm_searcher_;
  PoseFilter filter_;
  StickPose pose_;
  bool started_ = false;
  int lost_streak_ = 0;
  int patience_ = 0;  // lost frames in a row that start a recovery search now
  int reinitializations_ = 0;
  int steps_ = 0;
  int unexplained_wait_ = 0;     // frames until the silhouette is checked again
  int unexplained_backoff_ = 1;  // the wait after the next search that finds nothing
};

}  // namespace simcap::tracker
