#include "tracker/unzueta/ik_eval.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/error.h"
#include "models/bvh.h"
#include "models/bvh_skeleton.h"
#include "tracker/unzueta/ccd.h"
#include "tracker/unzueta/dls.h"
#include "tracker/unzueta/sik.h"

namespace simcap {

std::vector<int> table10_joints(const SikBody& body) {
  const Skeleton& sk = body.skeleton();
  std::vector<int> ends;
  for (int side : {kLeft, kRight}) {
    ends.push_back(body.arm(side).c);
    ends.push_back(body.leg(side).c);
  }
  bool pelvis_bone_kept = false;
  std::vector<int> joints;
  for (int j = 0; j < sk.size(); ++j) {
    if (sk[j].is_site) continue;
    const int p = sk[j].parent;
    if (p >= 0 &&
        std::any_of(ends.begin(), ends.end(), [&](int end) { return sk.is_descendant(p, end); })) {
      continue;
    }
    // A bone from the root toward a hip (sacroiliac, LHipJoint, RHipJoint) counts once.
    const int hip_l = body.leg(kLeft).a, hip_r = body.leg(kRight).a;
    const bool pelvis_bone = p == body.root() && j != hip_l && j != hip_r &&
                             (sk.is_descendant(hip_l, j) || sk.is_descendant(hip_r, j));
    if (pelvis_bone && pelvis_bone_kept) continue;
    pelvis_bone_kept = pelvis_bone_kept || pelvis_bone;
    joints.push_back(j);
  }
  return joints;
}

double table10_height(const SikBody& body) {
  const Skeleton& sk = body.skeleton();
  auto at = [&](int j) { return sk[j].center; };
  double legs = 0.0, pelvis = 0.0;
  for (int side : {kLeft, kRight}) {
    const SikLimb& leg = body.leg(side);
    legs += 0.5 * ((at(leg.b) - at(leg.c)).norm() + (at(leg.a) - at(leg.b)).norm());
    pelvis += 0.5 * (at(body.root()).y() - at(leg.a).y());
  }
  const int vc7 = sk.find("vc7");
  const double trunk = vc7 >= 0
                           ? (at(vc7) - at(body.root())).norm() + (at(body.head()) - at(vc7)).norm()
                           : (at(body.head()) - at(body.root())).norm();
  return legs + pelvis + trunk;
}

SikHingeAxes hinge_axes_from_motion(const SikBody& body, const Motion& motion) {
  constexpr double kMinBend = 0.2;  // radians; smaller turns say little about the axis
  auto principal = [&](int joint) -> std::optional<Eigen::Vector3d> {
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    for (const Pose& pose : motion.frames) {
      const Eigen::AngleAxisd turn(pose.rotations[joint]);
      if (turn.angle() > kMinBend) scatter += turn.angle() * turn.axis() * turn.axis().transpose();
    }
    if (scatter.isZero()) return std::nullopt;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scatter);
    return eigen.eigenvectors().col(2);
  };
  SikHingeAxes axes;
  for (int side : {kLeft, kRight}) {
    axes.elbow[side] = principal(body.arm(side).b);
    axes.knee[side] = principal(body.leg(side).b);
  }
  return axes;
}

IkClip load_ik_clip(const std::filesystem::path& bvh, bool identify_hinges, int max_frames) {
  BvhSkeleton clip = skeleton_from_bvh(read_bvh(bvh));
  if (max_frames > 0 && static_cast<int>(clip.motion.frames.size()) > max_frames) {
    clip.motion.frames.resize(max_frames);
  }
  try {
    SikBody body(clip.skeleton);
    if (!identify_hinges) return {std::move(body), std::move(clip.motion)};
    SikHingeAxes axes = hinge_axes_from_motion(body, clip.motion);
    return {SikBody(std::move(clip.skeleton), axes), std::move(clip.motion)};
  } catch (const Error& e) {
    throw Error(bvh.string() + ": " + e.what());
  }
}

std::unique_ptr<IkSolver> make_ik_solver(std::string_view method, const SikBody& body,
                                         const IkSolverSettings& settings) {
  if (method == "sik" || method == "tgbsik") {
    SikOptions o;
    o.pelvis_weights = settings.pelvis_weights;
    o.limits = settings.limits;
    o.swivel = method == "tgbsik" ? SikSwivel::least_rotation : settings.sik_swivel;
    o.spine_bend = settings.spine_bend;
    return std::make_unique<SikSolver>(body, o);
  }
  SikPelvisWeights thesis_pelvis = settings.pelvis_weights;
  thesis_pelvis.travel = 0.0;
  if (method == "ccd" || method == "kma") {
    CcdOptions o;
    o.pelvis_weights = thesis_pelvis;
    o.limits = settings.limits;
    return std::make_unique<CcdSolver>(body, o,
                                       method == "kma" ? CcdVariant::kma : CcdVariant::ccd);
  }
  for (JacobianUpdate update :
       {JacobianUpdate::kPseudoinverse, JacobianUpdate::kDls, JacobianUpdate::kDlsSvd,
        JacobianUpdate::kSdls, JacobianUpdate::kPrioritized}) {
    if (method != jacobian_update_name(update)) continue;
    DlsOptions o;
    o.pelvis_weights = thesis_pelvis;
    o.limits = settings.limits;
    o.damping = settings.dls_damping;
    o.update = update;
    return std::make_unique<DlsSolver>(body, o);
  }
  throw Error("unknown inverse-kinematics method '" + std::string(method) +
              "' (expected sik, ccd, pinv, dls, dls-svd, sdls, pik, tgbsik or kma)");
}

const std::vector<std::string>& ik_solver_names() {
  static const std::vector<std::string> names = {"sik",  "ccd", "pinv",   "dls", "dls-svd",
                                                 "sdls", "pik", "tgbsik", "kma"};
  return names;
}

const std::vector<Table10Column>& thesis_table10() {
  static const std::vector<Table10Column> columns = {
      {"kma", 0.0277, 0.3050, 1.09},      {"ccd", 0.0294, 0.4544, 0.89},
      {"pinv", 0.0279, 0.3452, 18.23},    {"dls", 0.0291, 0.3313, 9.35},
      {"dls-svd", 0.0292, 0.3315, 16.92}, {"sdls", 0.0268, 0.3268, 15.10},
      {"pik", 0.0264, 0.3392, 32.17},     {"sik", 0.0246, 0.2942, 0.44},
      {"tgbsik", 0.0262, 0.3108, 1.90}};
  return columns;
}

IkEvalResult evaluate_ik(IkSolver& solver, const Motion& truth, const std::vector<int>& joints,
                         double height, IkEvalExtras extras) {
  const SikBody& body = solver.body();
  if (joints.empty() || !(height > 0.0)) throw Error("ik-eval: no joints to score");
  IkEvalResult r;
  r.joints = joints;
  r.height = height;
  const double n = static_cast<double>(joints.size());
  std::vector<Eigen::Quaterniond> true_rotation, solved_rotation;
  std::vector<Eigen::Vector3d> true_position, solved_position;
  solver.reset();
  for (const Pose& pose : truth.frames) {
    if (static_cast<int>(pose.rotations.size()) != body.size()) {
      throw Error("ik-eval: the motion is not of the solver's skeleton");
    }
    body.forward(pose, true_rotation, true_position);
    SikTargets targets = body.targets(true_position);
    if (extras.known_orientations) {
      targets.pelvis_orientation = true_rotation[body.root()];
      targets.head_orientation = true_rotation[body.head()];
    }
    if (extras.middle_targets) {
      for (int side : {kLeft, kRight}) {
        targets.elbow[side] = true_position[body.arm(side).b];
        targets.knee[side] = true_position[body.leg(side).b];
      }
    }
    const auto start = std::chrono::steady_clock::now();
    const Pose& solved = solver.solve(targets);
    const auto stop = std::chrono::steady_clock::now();
    r.frame_ms.push_back(std::chrono::duration<double, std::milli>(stop - start).count());
    body.forward(solved, solved_rotation, solved_position);

    std::vector<double> position, orientation;
    double position_sum = 0.0, orientation_sum = 0.0;
    for (int j : joints) {
      position.push_back((solved_position[j] - true_position[j]).norm());
      orientation.push_back(
          Eigen::AngleAxisd(pose.rotations[j].conjugate() * solved.rotations[j]).angle());
      position_sum += position.back();
      orientation_sum += orientation.back();
    }
    r.frame_position.push_back(position_sum / (height * n));
    r.frame_orientation.push_back(orientation_sum / n);
    r.joint_position.push_back(std::move(position));
    r.joint_orientation.push_back(std::move(orientation));
  }
  if (r.frame_ms.empty()) throw Error("ik-eval: the motion has no frames");
  auto rms = [](const std::vector<double>& v) {
    double s = 0.0;
    for (double x : v) s += x * x;
    return std::sqrt(s / v.size());
  };
  r.position_error = rms(r.frame_position);
  r.orientation_error = rms(r.frame_orientation);
  std::vector<double> ms = r.frame_ms;
  std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
  r.ms_per_frame = ms[ms.size() / 2];
  return r;
}

}  // namespace simcap
