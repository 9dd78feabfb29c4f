// Unzueta's Table 10 benchmark (thesis §4.7.1): a solver fed a true motion's end-effectors frame
// by frame, scored by normalised position, orientation error and median time per frame.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "models/motion.h"
#include "tracker/unzueta/sik.h"
#include "tracker/unzueta/sik_ik_solver.h"
#include "tracker/unzueta/sik_limb.h"
#include "tracker/unzueta/sik_pelvis.h"
#include "tracker/unzueta/sik_spine.h"

namespace simcap {

// The scored joints, like the thesis' 22 ("all the joints except those that derive from wrists
// and ankles"): every joint that is not a site and not below a wrist or an ankle, with the bones
// between humanoid_root and the hips counted once (the thesis' humanoid has one sacroiliac where
// CMU's skeleton has LHipJoint and RHipJoint; the first is kept). 22 joints on CMU clips.
std::vector<int> table10_joints(const SikBody& body);

// The thesis' humanoid height: calf + thigh + pelvis + torso + neck lengths (sides averaged) in
// the neutral pose, i.e. |knee-ankle| + |hip-knee| + (root height above the hips) +
// |root-vc7| + |vc7-skullbase| (|root-skullbase| when there is no vc7).
double table10_height(const SikBody& body);

// The elbow and knee flexion axes of a motion's skeleton, read off the motion: for each, the
// principal axis of its rotations (weighted by angle), when it bends by more than 0.2 rad in some
// frame. The thesis scores solvers on "a humanoid identical to the original"; a BVH file holds the
// joint frames but not the axes its hinges turn about, so they are identified once per clip.
SikHingeAxes hinge_axes_from_motion(const SikBody& body, const Motion& motion);

// A motion clip as the benchmark uses it: the clip's own skeleton (joints renamed to H-Anim,
// segment lengths as in the file) with its hinge axes, and its motion.
struct IkClip {
  SikBody body;
  Motion motion;
};
// Reads a BVH file. With identify_hinges, elbows and knees get hinge_axes_from_motion();
// otherwise the anatomical axes. `max_frames` > 0 keeps the first frames only.
IkClip load_ik_clip(const std::filesystem::path& bvh, bool identify_hinges, int max_frames = 0);

// The settings the solvers share in the benchmark, SIK's defaults as SikOptions'.
struct IkSolverSettings {
  // The travel weight is sik's and tgbsik's only: the baselines keep the thesis' estimate, so
  // Table 10's rows other than SIK's are the thesis' methods.
  SikPelvisWeights pelvis_weights{.travel = kSikPelvisTravel};
  bool limits = true;
  double dls_damping = 0.75;                     // metres (see DlsOptions::damping)
  SikSwivel sik_swivel = SikSwivel::neutral;     // sik's limb swivel (tgbsik: least_rotation)
  SikSpineBend spine_bend = SikSpineBend::lean;  // sik's and tgbsik's
};
// The solvers simcap implements: sik, ccd, pinv, dls, dls-svd, sdls, pik, tgbsik, kma.
const std::vector<std::string>& ik_solver_names();
// One of ik_solver_names() on `body`; throws Error for another name.
std::unique_ptr<IkSolver> make_ik_solver(std::string_view method, const SikBody& body,
                                         const IkSolverSettings& settings);

// A column of the thesis' Table 10: the averages over its Boxing, Jump Kick and Playground clips
// (Pentium 4, 2.66 GHz). `method` is simcap's name where simcap implements it.
struct Table10Column {
  std::string method;
  double position_error, orientation_error, ms_per_frame;
};
const std::vector<Table10Column>& thesis_table10();

struct IkEvalResult {
  std::vector<int> joints;  // scored joint indices
  double height = 0.0;      // normaliser, metres
  // Per frame: sum over joints of the position error / (height * joints), and of the
  // orientation error (radians) / joints; solve time in milliseconds.
  std::vector<double> frame_position, frame_orientation, frame_ms;
  // Per frame and scored joint: position error (metres) and orientation error (radians).
  std::vector<std::vector<double>> joint_position, joint_orientation;
  // Table 10's figures: RMS over frames of the per-frame values, and the median time.
  double position_error = 0.0, orientation_error = 0.0, ms_per_frame = 0.0;
};

// What the targets carry besides Table 10's six positions (SIK uses both; the baselines ignore
// them): the true pelvis and head orientations (Alg. 10-11), the true elbows and knees.
struct IkEvalExtras {
  bool known_orientations = false;
  bool middle_targets = false;
};

// Runs `solver` (reset first) on the end-effectors of every frame of `truth`, a motion of the
// solver's own skeleton. The orientation of a joint is compared relative to its parent (the
// root's in the world) as the magnitude of the exponential map of R_true^-1 R_solved.
IkEvalResult evaluate_ik(IkSolver& solver, const Motion& truth, const std::vector<int>& joints,
                         double height, IkEvalExtras extras = {});

}  // namespace simcap
