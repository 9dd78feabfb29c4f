#include "models/pose_from_joints.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>

#include "core/error.h"
#include "models/humanoid.h"

namespace simcap {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// Orthonormal frame with `up` as its Y axis and `side` (made perpendicular) as its X axis.
Matrix3d frame(const Vector3d& side, const Vector3d& up) {
  const Vector3d y = up.normalized();
  const Vector3d x = (side - side.dot(y) * y).normalized();
  Matrix3d f;
  f << x, y, x.cross(y);
  return f;
}

Matrix3d swing(const Vector3d& from, const Vector3d& to) {
  return Eigen::Quaterniond::FromTwoVectors(from, to).toRotationMatrix();
}

// Signed angle about unit `axis` from a to b (both perpendicular to it).
double angle_about(const Vector3d& axis, const Vector3d& a, const Vector3d& b) {
  return std::atan2(axis.dot(a.cross(b)), a.dot(b));
}

class Fitter {
 public:
  explicit Fitter(const Skeleton& s) : s_(s) {}

  Pose fit(const std::map<std::string, Vector3d>& p) const {
    auto P = [&](const std::string& n) { return p.at(n); };
    auto C = [&](const std::string& n) { return s_[s_.require(n)].center; };
    std::vector<Matrix3d> world(s_.size(), Matrix3d::Identity());
    std::vector<bool> set(s_.size(), false);
    auto put = [&](const std::string& n, const Matrix3d& w) {
      world[s_.require(n)] = w;
      set[s_.require(n)] = true;
    };
    const Matrix3d pelvis =
        frame(P("l_hip") - P("r_hip"), P("vc7") - P("humanoid_root")) *
        frame(C("l_hip") - C("r_hip"), C("vc7") - C("humanoid_root")).transpose();
    put("humanoid_root", pelvis);
    const Matrix3d chest =
        frame(P("l_shoulder") - P("r_shoulder"), P("vc7") - P("humanoid_root")) *
        frame(C("l_shoulder") - C("r_shoulder"), C("vc7") - C("humanoid_root")).transpose();
    put("vt1", chest);
    put("vc7", swing(chest * (C("skullbase") - C("vc7")), P("skullbase") - P("vc7")) * chest);
    // The spine below vt1 turns with the pelvis, so vt1 sits where the pelvis carries it.
    const Vector3d vt1 = P("humanoid_root") + pelvis * (C("vt1") - C("humanoid_root"));
    for (const char* side : {"l_", "r_"}) {
      const std::string x(side);
      // The clavicle turns towards the tracked shoulder: a shrug or a reach moves the shoulder
      // centre off the chest's neutral place, and the whole arm with it.
      const std::string sc = x + "sternoclavicular";
      const Vector3d sc_at = vt1 + chest * (C(sc) - C("vt1"));
      const Matrix3d clavicle =
          swing(chest * (C(x + "shoulder") - C(sc)), P(x + "shoulder") - sc_at) * chest;
      put(sc, clavicle);
      limb(x + "shoulder", x + "elbow", x + "radiocarpal", clavicle, false, P, C, put);
      limb(x + "hip", x + "knee", x + "talocrural", pelvis, true, P, C, put);
    }
    Pose pose = Pose::neutral(s_);
    for (int j = 0; j < s_.size(); ++j) {
      const int parent = s_[j].parent;
      if (!set[j]) world[j] = parent < 0 ? Matrix3d::Identity() : world[parent];
      if (s_[j].is_site) continue;
      pose.rotations[j] = Eigen::Quaterniond(
          parent < 0 ? world[j] : Matrix3d(world[parent].transpose() * world[j]));
    }
    pose.root_position = P("humanoid_root");
    return pose;
  }

 private:
  // Upper and lower limb: the middle joint bends about +X of its neutral frame, positively
  // (knees) or negatively (elbows); `parent` is the world rotation of the limb root's parent.
  // The hinge axis a must make with the tracked upper bone the angle X makes with the neutral
  // one, and with the tracked lower bone the angle X makes with the neutral lower bone: of the
  // two such axes, the one on the side the track bends the limb to.
  template <class Pos, class Centre, class Put>
  void limb(const std::string& top, const std::string& middle, const std::string& end,
            const Matrix3d& parent, bool positive, const Pos& P, const Centre& C,
            const Put& put) const {
    const Vector3d u_n = (C(middle) - C(top)).normalized(), f_n = (C(end) - C(middle)).normalized();
    const Vector3d u_t = (P(middle) - P(top)).normalized(), f_t = (P(end) - P(middle)).normalized();
    const Vector3d bend = positive ? u_t.cross(f_t) : f_t.cross(u_t);
    const double cos_b = u_n.x(), cos_a = f_n.x();  // angles of X to the neutral bones
    const Vector3d e1 = u_t;
    const Vector3d e2 = (f_t - f_t.dot(e1) * e1);
    const double s1 = e2.norm();
    Matrix3d upper;
    bool solved = false;
    if (s1 > 1e-6) {
      const double c1 = f_t.dot(e1);
      const double y = (cos_a - cos_b * c1) / s1;
      const double zz = 1 - cos_b * cos_b - y * y;
      if (zz >= 0) {
        const Vector3d e3 = e1.cross(e2 / s1);
        double z = std::sqrt(zz);
        if (e3.dot(bend) < 0) z = -z;
        const Vector3d axis = cos_b * e1 + y * (e2 / s1) + z * e3;
        upper = frame(axis, u_t) * frame(Vector3d::UnitX(), u_n).transpose();
        solved = true;
      }
    }
    if (!solved) upper = swing(parent * u_n, u_t) * parent;  // straight: no bend plane
    put(top, upper);
    // Both lower bones now make the same angle with X: the hinge turns one onto the other.
    auto across = [](const Vector3d& v) { return Vector3d(0, v.y(), v.z()); };
    const double theta =
        angle_about(Vector3d::UnitX(), across(f_n), across(upper.transpose() * f_t));
    put(middle, upper * Eigen::AngleAxisd(theta, Vector3d::UnitX()).toRotationMatrix());
  }

  const Skeleton& s_;
};

}  // namespace

Skeleton humanoid_for_track(const JointTrack& track) {
  const Skeleton unit = build_humanoid({.height = 1.0, .proportions = {}});
  std::vector<double> ratios;
  for (const char* side : {"l_", "r_"}) {
    const std::string x(side);
    for (const auto& [a, b] : {std::pair{x + "hip", x + "knee"},
                               {x + "knee", x + "talocrural"},
                               {x + "shoulder", x + "elbow"},
                               {x + "elbow", x + "radiocarpal"}}) {
      const int ta = track.joint_index(a), tb = track.joint_index(b);
      if (ta < 0 || tb < 0) throw Error("track: no '" + (ta < 0 ? a : b) + "' joint");
      double sum = 0;
      int n = 0;
      for (const auto& frame : track.positions) {
        const double d = (frame[ta] - frame[tb]).norm();
        if (std::isfinite(d)) {
          sum += d;
          ++n;
        }
      }
      const double neutral = (unit[unit.require(a)].center - unit[unit.require(b)].center).norm();
      if (n > 0) ratios.push_back(sum / n / neutral);
    }
  }
  if (ratios.empty()) throw Error("track: no frame has the limb joints");
  std::nth_element(ratios.begin(), ratios.begin() + ratios.size() / 2, ratios.end());
  const double height = std::clamp(ratios[ratios.size() / 2], 0.6, 2.5);
  return build_humanoid({.height = height, .proportions = {}});
}

TrackMotion motion_from_track(const JointTrack& track, const Skeleton& skeleton, double fps) {
  if (track.frames.empty()) throw Error("track: no frames");
  const Fitter fitter(skeleton);
  TrackMotion out;
  out.motion.fps = fps;
  Pose previous = Pose::neutral(skeleton);
  size_t row = 0;
  for (int f = track.frames.front(); f <= track.frames.back(); ++f) {
    std::map<std::string, Vector3d> joints;
    bool complete = row < track.frames.size() && track.frames[row] == f;
    if (complete) {
      for (const std::string& name : he15_joints()) {
        const int j = track.joint_index(name);
        if (j < 0 || !track.positions[row][j].allFinite()) {
          complete = false;
          break;
        }
        joints[name] = track.positions[row][j];
      }
      ++row;
    }
    if (complete) {
      previous = fitter.fit(joints);
    } else {
      ++out.held;
    }
    out.motion.frames.push_back(previous);
  }
  return out;
}

}  // namespace simcap
