#include "tracker/unzueta/sik_track_job.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <random>

#include "core/csv.h"
#include "core/error.h"
#include "core/progress.h"
#include "models/body_mesh.h"
#include "models/humanoid.h"
#include "tracker/unzueta/sik.h"
#include "tracker/unzueta/unzueta_job.h"

namespace simcap {
namespace {

// Mean distance between two tracked joints over the frames that have both; NaN when none.
double mean_distance(const JointTrack& truth, int a, int b) {
  double sum = 0.0;
  int n = 0;
  for (const auto& frame : truth.positions) {
    const double d = (frame[a] - frame[b]).norm();
    if (std::isfinite(d)) {
      sum += d;
      ++n;
    }
  }
  return n ? sum / n : NAN;
}

Skeleton humanoid_of_height(double height) {
  BodyParameters body;
  body.height = height;
  return build_humanoid(body);
}

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

// Axes with Y from `from` to `to` and X toward `left` from `right` across Y; nullopt when
// degenerate or not finite.
std::optional<Eigen::Matrix3d> frame_axes(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                                          const Eigen::Vector3d& left,
                                          const Eigen::Vector3d& right) {
  const Eigen::Vector3d up = to - from;
  if (!up.allFinite() || !(left - right).allFinite() || up.norm() < 1e-9) return std::nullopt;
  const Eigen::Vector3d y = up.normalized();
  Eigen::Vector3d x = left - right;
  x -= x.dot(y) * y;
  if (x.norm() < 1e-9) return std::nullopt;
  x.normalize();
  Eigen::Matrix3d axes;
  axes << x, y, x.cross(y);
  return axes;
}

// A body frame named by four joints (from, to, left, right: frame_axes) with its origin at
// `from`, and where a joint sits in it.
struct BodyFrame {
  std::array<std::string, 4> joints;

  std::optional<Eigen::Matrix3d> axes(const std::array<Eigen::Vector3d, 4>& p) const {
    return frame_axes(p[0], p[1], p[2], p[3]);
  }
  // The median over the truth's frames of `joint`'s coordinates in this frame; nullopt when the
  // truth lacks a joint or no frame has them all.
  std::optional<Eigen::Vector3d> median_in_truth(const JointTrack& truth,
                                                 const std::string& joint) const {
    std::array<int, 5> t{};
    for (int i = 0; i < 5; ++i) {
      t[i] = truth.joint_index(i < 4 ? joints[i] : joint);
      if (t[i] < 0) return std::nullopt;
    }
    std::array<std::vector<double>, 3> local;
    for (const auto& p : truth.positions) {
      const auto r = axes({p[t[0]], p[t[1]], p[t[2]], p[t[3]]});
      const Eigen::Vector3d q = r ? Eigen::Vector3d(r->transpose() * (p[t[4]] - p[t[0]]))
                                  : Eigen::Vector3d::Constant(NAN);
      if (!q.allFinite()) continue;
      for (int k = 0; k < 3; ++k) local[k].push_back(q[k]);
    }
    if (local[0].empty()) return std::nullopt;
    return Eigen::Vector3d(median(local[0]), median(local[1]), median(local[2]));
  }
  // The world point at `local` in this frame of the neutral centres; nullopt when degenerate.
  std::optional<Eigen::Vector3d> in_skeleton(const Skeleton& skeleton,
                                             const std::vector<Eigen::Vector3d>& centre,
                                             const Eigen::Vector3d& local) const {
    std::array<Eigen::Vector3d, 4> p;
    for (int i = 0; i < 4; ++i) p[i] = centre[skeleton.require(joints[i])];
    const auto r = axes(p);
    if (!r) return std::nullopt;
    return Eigen::Vector3d(p[0] + *r * local);
  }
};

void shift_subtree(const Skeleton& skeleton, int top, const Eigen::Vector3d& shift,
                   std::vector<Eigen::Vector3d>& centre) {
  for (int j = 0; j < skeleton.size(); ++j) {
    if (skeleton.is_descendant(j, top)) centre[j] += shift;
  }
}

// `skeleton` with its neutral joint centres moved to `centre`.
Skeleton with_centres(const Skeleton& skeleton, const std::vector<Eigen::Vector3d>& centre) {
  Skeleton moved;
  for (int j = 0; j < skeleton.size(); ++j) {
    Joint joint = skeleton[j];
    joint.center = centre[j];
    moved.add(std::move(joint));
  }
  return moved;
}

bool has_joints(const Skeleton& skeleton, std::initializer_list<const char*> names) {
  return std::all_of(names.begin(), names.end(),
                     [&](const char* n) { return skeleton.find(n) >= 0; });
}

// Lengths alone miss the rest shape of the trunk the motion carries (a body retargeted from CMU
// keeps its clavicles turned ~25 degrees up and forward in every frame, its thorax curled
// forward), which SIK's neutral spine and clavicles never reproduce: its shoulders were 10-15 cm
// off. So vc7 moves to the truth's median position in the trunk frame (humanoid_root, Y to
// skullbase, X across the hips), the shift spread evenly over the vertebrae below it with
// skullbase kept; then each shoulder, with its arm, to the truth's median in the thorax frame
// (vc7, Y from humanoid_root, X across the shoulders). Unchanged where the truth lacks a joint.
Skeleton place_trunk(const JointTrack& truth, const Skeleton& skeleton) {
  if (!has_joints(skeleton, {"humanoid_root", "vc7", "skullbase", "l_hip", "r_hip", "l_shoulder",
                             "r_shoulder"})) {
    return skeleton;
  }
  std::vector<Eigen::Vector3d> centre;
  for (const Joint& j : skeleton.joints()) centre.push_back(j.center);
  const int root = skeleton.require("humanoid_root"), vc7 = skeleton.require("vc7"),
            skullbase = skeleton.require("skullbase");

  const BodyFrame trunk{{"humanoid_root", "skullbase", "l_hip", "r_hip"}};
  const auto vc7_local = trunk.median_in_truth(truth, "vc7");
  const auto vc7_at = vc7_local ? trunk.in_skeleton(skeleton, centre, *vc7_local) : std::nullopt;
  if (vc7_at) {
    std::vector<int> path;
    for (int j = vc7; j != root; j = skeleton[j].parent) path.push_back(j);
    const Eigen::Vector3d shift = *vc7_at - centre[vc7];
    for (int j : path) shift_subtree(skeleton, j, shift / static_cast<double>(path.size()), centre);
    for (int c : skeleton.children(vc7)) {
      if (skeleton.is_descendant(skullbase, c)) shift_subtree(skeleton, c, -shift, centre);
    }
  }

  const BodyFrame thorax{{"vc7", "humanoid_root", "l_shoulder", "r_shoulder"}};
  const std::array<const char*, 2> shoulders = {"l_shoulder", "r_shoulder"};
  std::array<std::optional<Eigen::Vector3d>, 2> local;
  for (int side = 0; side < 2; ++side) local[side] = thorax.median_in_truth(truth, shoulders[side]);
  // The shoulders span the frame's X, so moving them turns it: a few passes settle both.
  for (int pass = 0; pass < 4; ++pass) {
    for (int side = 0; side < 2; ++side) {
      const int j = skeleton.require(shoulders[side]);
      const auto at =
          local[side] ? thorax.in_skeleton(skeleton, centre, *local[side]) : std::nullopt;
      if (at) shift_subtree(skeleton, j, *at - centre[j], centre);
    }
  }
  return with_centres(skeleton, centre);
}

}  // namespace

Skeleton sik_humanoid_for_track(const JointTrack& truth) {
  const Skeleton unit = humanoid_of_height(1.0);
  // Each tracked joint with a tracked ancestor sizes the bones between them.
  struct Sized {
    int joint, anchor;  // in the skeleton
    double length;      // in the truth
  };
  std::vector<Sized> sized;
  std::vector<double> heights;
  for (int j = 1; j < unit.size(); ++j) {
    const int tj = truth.joint_index(unit[j].name);
    if (tj < 0) continue;
    int anchor = unit[j].parent;
    while (anchor >= 0 && truth.joint_index(unit[anchor].name) < 0) anchor = unit[anchor].parent;
    if (anchor < 0) continue;
    const double d = mean_distance(truth, tj, truth.joint_index(unit[anchor].name));
    const double neutral = (unit[j].center - unit[anchor].center).norm();
    if (!std::isfinite(d) || neutral < 1e-9) continue;
    sized.push_back({j, anchor, d});
    heights.push_back(d / neutral);
  }
  if (heights.empty()) {
    throw Error("the truth tracks no two joints that size the humanoid (e.g. l_hip and l_knee)");
  }
  std::nth_element(heights.begin(), heights.begin() + heights.size() / 2, heights.end());
  const Skeleton base = humanoid_of_height(heights[heights.size() / 2]);

  // Bones on the way from an anchor to its joint take the joint's factor, unless a joint listed
  // earlier (nearer the root) already sized them.
  std::vector<double> scale(base.size(), NAN);
  for (const Sized& s : sized) {
    const double factor = s.length / (base[s.joint].center - base[s.anchor].center).norm();
    for (int j = s.joint; j != s.anchor; j = base[j].parent) {
      if (std::isnan(scale[j])) scale[j] = factor;
    }
  }
  Skeleton fitted;
  std::vector<Eigen::Vector3d> centre(base.size());
  for (int j = 0; j < base.size(); ++j) {
    Joint joint = base[j];
    const double k = std::isnan(scale[j]) ? 1.0 : scale[j];
    centre[j] = joint.parent < 0 ? joint.center
                                 : Eigen::Vector3d(centre[joint.parent] + k * base.offset(j));
    joint.center = centre[j];
    fitted.add(std::move(joint));
  }
  return fitted;
}

Skeleton sik_humanoid_with_truth_trunk(const JointTrack& truth) {
  return place_trunk(truth, sik_humanoid_for_track(truth));
}

TrackSummary track_dataset_sik(const std::filesystem::path& dataset,
                               const std::filesystem::path& out, const SikTrackOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::filesystem::path gt = dataset / "gt" / "joints3d.csv";
  if (!(options.noise_sigma_m >= 0.0)) throw Error("SIK noise sigma must be >= 0");
  const JointTrack truth = read_joint_track(gt);
  auto need = [&](const std::string& name) {
    const int i = truth.joint_index(name);
    if (i < 0) throw_input_error(gt, 0, "joint", "SIK needs the joint '" + name + "'");
    return i;
  };
  const int pelvis = need("humanoid_root");
  const int skullbase = truth.joint_index("skullbase");
  const int head = skullbase >= 0 ? skullbase : truth.joint_index("skull_tip");
  if (head < 0) throw_input_error(gt, 0, "joint", "SIK needs the joint 'skullbase' or 'skull_tip'");
  const std::array<int, 2> wrist = {need("l_radiocarpal"), need("r_radiocarpal")};
  const std::array<int, 2> ankle = {need("l_talocrural"), need("r_talocrural")};
  std::array<int, 2> elbow = {-1, -1}, knee = {-1, -1};
  if (options.middle_targets) {
    elbow = {need("l_elbow"), need("r_elbow")};
    knee = {need("l_knee"), need("r_knee")};
  }

  const Skeleton skeleton = sik_humanoid_with_truth_trunk(truth);
  // A skull_tip target stands in for skullbase one neutral head height below it.
  const double head_drop = skullbase >= 0 ? 0.0
                                          : (skeleton[skeleton.require("skull_tip")].center -
                                             skeleton[skeleton.require("skullbase")].center)
                                                .norm();
  SikSolver solver(SikBody(skeleton), build_body_mesh(skeleton), options.solver);
  const SikBody& body = solver.body();

  std::vector<int> output_joints;
  JointTrack track;
  for (const std::string& name : he15_joints()) {
    output_joints.push_back(skeleton.require(name));
    track.joints.push_back(name);
  }
  std::mt19937_64 rng(options.seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  auto noisy = [&](Eigen::Vector3d p) {
    if (options.noise_sigma_m > 0.0) {
      for (int i = 0; i < 3; ++i) p[i] += options.noise_sigma_m * gauss(rng);
    }
    return p;
  };

  const size_t frames = options.max_frames < 0 ? truth.frames.size()
                                               : std::min(truth.frames.size(),
                                                          static_cast<size_t>(options.max_frames));
  Progress progress("sik", static_cast<long>(frames), options.quiet);
  std::vector<Eigen::Quaterniond> rotation;
  std::vector<Eigen::Vector3d> position;
  for (size_t f = 0; f < frames; ++f) {
    const auto& p = truth.positions[f];
    progress.advance();
    const std::array<int, 6> used = {pelvis, head, wrist[0], wrist[1], ankle[0], ankle[1]};
    const bool complete =
        std::all_of(used.begin(), used.end(), [&](int j) { return p[j].allFinite(); });
    if (!complete) continue;
    SikTargets targets;
    targets.pelvis = noisy(p[pelvis]);
    targets.head = noisy(p[head]);
    for (int side : {kLeft, kRight}) targets.wrist[side] = noisy(p[wrist[side]]);
    for (int side : {kLeft, kRight}) targets.ankle[side] = noisy(p[ankle[side]]);
    for (int side : {kLeft, kRight}) {
      if (elbow[side] >= 0 && p[elbow[side]].allFinite())
        targets.elbow[side] = noisy(p[elbow[side]]);
      if (knee[side] >= 0 && p[knee[side]].allFinite()) targets.knee[side] = noisy(p[knee[side]]);
    }
    if (head_drop > 0.0) {
      targets.head -= head_drop * (targets.head - targets.pelvis).normalized();
    }
    body.forward(solver.solve(targets), rotation, position);
    std::vector<Eigen::Vector3d> row;
    for (int j : output_joints) row.push_back(position[j]);
    track.add_frame(truth.frames[f], std::move(row));
  }
  progress.finish();

  CsvWriter neutral(out / "diagnostics" / "sik_humanoid.csv", {"joint", "x", "y", "z"});
  char line[160];
  for (const Joint& j : skeleton.joints()) {
    std::snprintf(line, sizeof line, "%s,%.7f,%.7f,%.7f\n", j.name.c_str(), j.center.x(),
                  j.center.y(), j.center.z());
    neutral.out() << line;
  }
  neutral.commit();
  write_joint_track(out / "joints3d.csv", track);
  TrackSummary summary;
  summary.frames = static_cast<int>(track.frames.size());
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  summary.track = out;
  return summary;
}

TrackSummary track_sik(const std::filesystem::path& dataset, const std::filesystem::path& out,
                       const SikTrackOptions& options) {
  if (options.effectors == EffectorSource::gt) return track_dataset_sik(dataset, out, options);
  // The pixel pipeline tracks no elbow or knee (CFOF follows head, hands and feet).
  if (options.middle_targets) throw Error("--middle-targets needs --effectors gt");
  return tracker::track_dataset_unzueta(dataset, out, options);
}

}  // namespace simcap
