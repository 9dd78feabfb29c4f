#include "models/gesture_motion.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>

#include "core/error.h"
#include "models/pose.h"

namespace simcap {
namespace {

constexpr double kPi = std::numbers::pi;
using Vec = Eigen::Vector3d;

// Single-stroke digits as the subject sees them (x to the subject's right, y up, unit box),
// after the air-drawn digits of the thesis' Fig. 75; the stroke passes the points in order.
const std::vector<std::vector<Eigen::Vector2d>>& digit_strokes() {
  static const std::vector<std::vector<Eigen::Vector2d>> strokes = {
      {{0.5, 1.0}, {0.12, 0.75}, {0.1, 0.25}, {0.5, 0.0}, {0.9, 0.25}, {0.88, 0.75}, {0.5, 1.0}},
      {{0.25, 0.75}, {0.5, 1.0}, {0.5, 0.5}, {0.5, 0.0}},
      {{0.1, 0.75}, {0.45, 1.0}, {0.85, 0.8}, {0.5, 0.4}, {0.1, 0.0}, {0.9, 0.0}},
      {{0.1, 0.9}, {0.6, 1.0}, {0.85, 0.78}, {0.4, 0.52}, {0.88, 0.28}, {0.55, 0.0}, {0.1, 0.1}},
      {{0.7, 0.0}, {0.7, 1.0}, {0.1, 0.3}, {0.95, 0.3}},
      {{0.85, 1.0}, {0.2, 1.0}, {0.15, 0.55}, {0.7, 0.6}, {0.85, 0.3}, {0.5, 0.0}, {0.1, 0.1}},
      {{0.8, 0.95}, {0.3, 0.7}, {0.12, 0.25}, {0.45, 0.0}, {0.82, 0.2}, {0.7, 0.45}, {0.25, 0.35}},
      {{0.1, 1.0}, {0.9, 1.0}, {0.6, 0.5}, {0.4, 0.0}},
      {{0.8, 0.88},
       {0.5, 1.0},
       {0.2, 0.82},
       {0.5, 0.5},
       {0.82, 0.2},
       {0.5, 0.0},
       {0.18, 0.2},
       {0.5, 0.5},
       {0.8, 0.88}},
      {{0.85, 0.78}, {0.5, 1.0}, {0.15, 0.78}, {0.45, 0.5}, {0.85, 0.7}, {0.85, 0.35}, {0.8, 0.0}}};
  return strokes;
}

// Minimum-jerk progress (Flash & Hogan 1985): 0 -> 1 with zero speed and acceleration at both
// ends; its peak speed is 1.875 times its mean.
double min_jerk(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * t * (10 - 15 * t + 6 * t * t);
}

// A smooth curve through points (uniform Catmull-Rom), sampled densely and walked by arc length.
class Stroke {
 public:
  explicit Stroke(const std::vector<Vec>& p) {
    const int n = static_cast<int>(p.size());
    auto at = [&](int i) { return p[std::clamp(i, 0, n - 1)]; };
    for (int i = 0; i + 1 < n; ++i) {
      const Vec p0 = at(i - 1), p1 = at(i), p2 = at(i + 1), p3 = at(i + 2);
      for (int k = 0; k < 32; ++k) {
        const double t = k / 32.0, t2 = t * t, t3 = t2 * t;
        samples_.push_back(0.5 * (2 * p1 + (-p0 + p2) * t + (2 * p0 - 5 * p1 + 4 * p2 - p3) * t2 +
                                  (-p0 + 3 * p1 - 3 * p2 + p3) * t3));
      }
    }
    samples_.push_back(p.back());
    length_.push_back(0);
    for (size_t i = 1; i < samples_.size(); ++i)
      length_.push_back(length_.back() + (samples_[i] - samples_[i - 1]).norm());
  }
  double length() const { return length_.back(); }
  // The point at fraction u of the arc length.
  Vec at(double u) const {
    const double s = std::clamp(u, 0.0, 1.0) * length();
    const size_t i = std::upper_bound(length_.begin(), length_.end(), s) - length_.begin();
    if (i >= samples_.size()) return samples_.back();
    const double w = (s - length_[i - 1]) / std::max(length_[i] - length_[i - 1], 1e-12);
    return samples_[i - 1] + w * (samples_[i] - samples_[i - 1]);
  }

 private:
  std::vector<Vec> samples_;
  std::vector<double> length_;
};

// Deterministic uniform numbers from the seed (independent of the library's distributions).
class Draw {
 public:
  explicit Draw(std::uint64_t seed) : rng_(seed) {}
  double uniform(double lo, double hi) { return lo + (hi - lo) * ((rng_() >> 11) * 0x1.0p-53); }
  size_t index(size_t n) { return static_cast<size_t>(uniform(0, static_cast<double>(n))) % n; }

 private:
  std::mt19937_64 rng_;
};

// One stretch of the timeline: where each wrist is (body frame) over local time [0, duration].
struct Move {
  double duration = 0;
  std::function<Vec(double)> hand[2];  // by side: 0 left, 1 right
  std::vector<MotionLabel> labels;     // times relative to the move's start
};

class Corpus {
 public:
  Corpus(const GestureSpec& spec, const Skeleton& s) : spec_(spec), s_(s), draw_(spec.seed) {
    if (spec.repetitions < 1) throw Error("gestures: repetitions must be at least 1");
    if (!(spec.min_speed > 0 && spec.max_speed >= spec.min_speed)) {
      throw Error("gestures: the speed range must be positive and ordered");
    }
    if (!(spec.min_size > 0 && spec.max_size >= spec.min_size)) {
      throw Error("gestures: the size range must be positive and ordered");
    }
    if (!(spec.transition_speed > 0)) throw Error("gestures: transition_speed must be positive");
    root_ = s.require("humanoid_root");
    for (int side = 0; side < 2; ++side) {
      const std::string p = side == 0 ? "l_" : "r_";
      shoulder_[side] = s.require(p + "shoulder");
      elbow_[side] = s.require(p + "elbow");
      wrist_[side] = s.require(p + "radiocarpal");
      hip_[side] = s.require(p + "hip");
      ankle_[side] = s.require(p + "talocrural");
      upper_[side] = (c(elbow_[side]) - c(shoulder_[side])).norm();
      lower_[side] = (c(wrist_[side]) - c(elbow_[side])).norm();
      // Resting: hanging with the elbows a little bent and the hands a little forward.
      rest_[side] = c(wrist_[side]) + Vec(side == 0 ? 0.02 : -0.02, 0.02, 0.06);
      // The calibration posture: hands beside the head.
      const double reach = upper_[side] + lower_[side];
      calibration_[side] =
          c(shoulder_[side]) + Vec(side == 0 ? 0.42 * reach : -0.42 * reach, 0.55 * reach, 0.05);
    }
    speed_ = draw_.uniform(spec.min_speed, spec.max_speed);
    size_ = draw_.uniform(spec.min_size, spec.max_size);
    aspect_ = draw_.uniform(0.55, 0.75);
    slant_ = draw_.uniform(-0.15, 0.15);
  }

  Motion build(double fps) {
    std::vector<std::string> kinds = spec_.gestures.empty() ? gesture_kinds() : spec_.gestures;
    // Each non-digit gesture is performed by both hands.
    std::vector<std::pair<std::string, int>> todo;
    for (int r = 0; r < spec_.repetitions; ++r) {
      for (const std::string& k : kinds) {
        if (std::find(gesture_kinds().begin(), gesture_kinds().end(), k) == gesture_kinds().end()) {
          std::string known;
          for (const auto& g : gesture_kinds()) known += (known.empty() ? "" : ", ") + g;
          throw Error("gestures: unknown gesture '" + k + "' (expected one of " + known + ")");
        }
        if (k.size() == 1 && std::isdigit(static_cast<unsigned char>(k[0]))) {
          todo.emplace_back(k, 1);
        } else {
          todo.emplace_back(k, 0);
          todo.emplace_back(k, 1);
        }
      }
    }
    for (size_t i = todo.size(); i > 1; --i) std::swap(todo[i - 1], todo[draw_.index(i)]);

    hand_ = calibration_;
    hold(1.0);
    go(0, rest_[0]);
    go(1, rest_[1]);
    hold(0.5);
    for (const auto& [kind, side] : todo) perform(kind, side);
    go(0, rest_[0]);
    go(1, rest_[1]);
    hold(0.5);

    Motion motion;
    motion.fps = fps;
    double total = 0;
    for (const Move& m : moves_) total += m.duration;
    const int frames = static_cast<int>(std::floor(total * fps)) + 1;
    size_t k = 0;
    double start = 0;
    for (int f = 0; f < frames; ++f) {
      const double t = f / fps;
      while (k + 1 < moves_.size() && t > start + moves_[k].duration) start += moves_[k++].duration;
      const double local = std::min(t - start, moves_[k].duration);
      motion.frames.push_back(pose({moves_[k].hand[0](local), moves_[k].hand[1](local)}));
    }
    start = 0;
    for (const Move& m : moves_) {
      for (MotionLabel l : m.labels) {
        l.start_s += start;
        l.end_s += start;
        motion.labels.push_back(std::move(l));
      }
      start += m.duration;
    }
    return motion;
  }

 private:
  Vec c(int j) const { return s_[j].center; }
  static std::string limb(int side) { return side == 0 ? "l_hand" : "r_hand"; }

  // Both hands stay where they are; with a `pose` label, `side`'s hand holds that static pose.
  void hold(double duration, int side = 0, const std::string& pose = "") {
    Move m;
    m.duration = duration;
    for (int s = 0; s < 2; ++s) {
      const Vec p = hand_[s];
      m.hand[s] = [p](double) { return p; };
    }
    if (!pose.empty()) m.labels = {{0, duration, limb(side), "static", pose}};
    moves_.push_back(std::move(m));
  }
  // One hand moves to `to` by a minimum-jerk reach of `duration`, the other holds.
  Move reach(int side, const Vec& to, double duration) {
    Move m;
    m.duration = duration;
    const Vec from = hand_[side], other = hand_[1 - side];
    m.hand[side] = [from, to, duration](double t) {
      return from + min_jerk(t / duration) * (to - from);
    };
    m.hand[1 - side] = [other](double) { return other; };
    hand_[side] = to;
    return m;
  }
  // One hand follows `path` with minimum-jerk progress along it, the other holds.
  Move along(int side, const Stroke& path, double duration) {
    Move m;
    m.duration = duration;
    const Vec other = hand_[1 - side];
    m.hand[side] = [path, duration](double t) { return path.at(min_jerk(t / duration)); };
    m.hand[1 - side] = [other](double) { return other; };
    hand_[side] = path.at(1.0);
    return m;
  }
  // A slow transition (peak speed transition_speed): not a gesture.
  void go(int side, const Vec& to) {
    const double d = (to - hand_[side]).norm();
    if (d < 1e-6) return;
    moves_.push_back(reach(side, to, std::max(0.4, 1.875 * d / spec_.transition_speed)));
  }
  double pause() { return draw_.uniform(0.3, 0.5); }
  double performance_speed() { return speed_ * draw_.uniform(0.85, 1.15); }

  void perform(const std::string& kind, int side) {
    const std::string who = limb(side);
    const double lateral = side == 0 ? 1.0 : -1.0;  // +X is the subject's left
    const Vec shoulder = c(shoulder_[side]);
    const double reach_len = upper_[side] + lower_[side];
    if (kind == "point" || kind == "raise") {
      go(side, rest_[side]);
      hold(pause(), side, "down");
      // The arm swings about the shoulder: forward to point, out to the side and up to raise
      // (as people do; a straight line would sweep the hand across the chest and face).
      const Vec down = (hand_[side] - shoulder).normalized();
      const Vec out = Vec(lateral, 0, 0);
      const std::vector<Vec> ways =
          kind == "point" ? std::vector<Vec>{down, (down + Vec::UnitZ()).normalized(),
                                             Vec(lateral * 0.08, -0.03, 1).normalized()}
                          : std::vector<Vec>{down, (down + out).normalized(), out,
                                             (out + Vec::UnitY()).normalized(),
                                             Vec(lateral * 0.06, 1, 0.05).normalized()};
      const double r0 = (hand_[side] - shoulder).norm(), r1 = 0.92 * reach_len;
      std::vector<Vec> points;
      for (size_t i = 0; i < ways.size(); ++i) {
        points.push_back(shoulder + (r0 + (r1 - r0) * i / (ways.size() - 1.0)) * ways[i]);
      }
      const Stroke path(points);
      Move m = along(side, path, path.length() / performance_speed());
      m.labels = {{0, m.duration, who, "dynamic", kind}};
      moves_.push_back(std::move(m));
      hold(draw_.uniform(0.8, 1.2), side, kind == "point" ? "forward" : "up");
      std::reverse(points.begin(), points.end());
      const Stroke back(points);
      moves_.push_back(along(side, back, 1.875 * back.length() / spec_.transition_speed));
      return;
    }
    if (kind == "wave") {
      const Vec centre = shoulder + Vec(lateral * 0.22, 0.6 * reach_len, 0.15);
      go(side, centre);
      hold(pause());
      const double amplitude = 0.12 * size_ / 0.375, cycles = 3;
      const double duration = cycles * 4 * amplitude / performance_speed();
      Move m;
      m.duration = duration;
      const Vec other = hand_[1 - side];
      m.hand[side] = [centre, amplitude, cycles, duration](double t) {
        return Vec(centre + Vec(amplitude * std::sin(2 * kPi * cycles * t / duration), 0, 0));
      };
      m.hand[1 - side] = [other](double) { return other; };
      m.labels = {{0, duration, who, "dynamic", kind}};
      moves_.push_back(std::move(m));
      hold(pause());
      return;
    }
    // A digit, drawn in a vertical plane beside and in front of the right shoulder (clear of the
    // face, as seen from in front).
    const auto& stroke = digit_strokes()[kind[0] - '0'];
    const double height = size_ * draw_.uniform(0.9, 1.1), width = aspect_ * height;
    const Vec centre = shoulder + Vec(lateral * 0.22, -0.1, 0.3) * (reach_len / 0.6);
    std::vector<Vec> points;
    for (const Eigen::Vector2d& q : stroke) {
      const double x = (q.x() - 0.5) * width + slant_ * (q.y() - 0.5) * height;
      points.push_back(centre + Vec(-x, (q.y() - 0.5) * height, 0));  // subject's right is -X
    }
    const Stroke path(points);
    go(side, points.front());
    hold(pause());
    Move m = along(side, path, path.length() / performance_speed());
    m.labels = {{0, m.duration, who, "dynamic", kind}};
    moves_.push_back(std::move(m));
    hold(pause());
  }

  // The pose with the wrists at `hands` (body frame): arms by two-bone IK with the elbows out and
  // down, feet apart. The root does not sway: the legs have no IK, so the feet would slide.
  Pose pose(const std::array<Vec, 2>& hands) const {
    Pose p = Pose::neutral(s_);
    const double abduction = 0.07;
    const double leg = (c(hip_[0]) - c(ankle_[0])).norm();
    p.root_position = c(root_) + Vec(0, -leg * (1 - std::cos(abduction)), 0);
    for (int side = 0; side < 2; ++side) {
      const double sign = side == 0 ? 1.0 : -1.0;
      p.rotations[hip_[side]] = Eigen::AngleAxisd(sign * abduction, Vec::UnitZ());
      p.rotations[ankle_[side]] = Eigen::AngleAxisd(-sign * abduction, Vec::UnitZ());
    }
    const auto world = forward_kinematics(s_, p);
    for (int side = 0; side < 2; ++side) arm(side, hands[side], world, p);
    return p;
  }

  void arm(int side, const Vec& target_body, const std::vector<Eigen::Isometry3d>& world,
           Pose& p) const {
    const double sign = side == 0 ? 1.0 : -1.0;
    const Vec shoulder = world[shoulder_[side]].translation();
    // Body frame -> world: the root moves, it does not turn.
    const Vec target = target_body + (p.root_position - c(root_));
    const double a = upper_[side], b = lower_[side];
    Vec to = target - shoulder;
    const double d = std::clamp(to.norm(), std::abs(a - b) + 1e-6, a + b - 1e-6);
    const Vec u = to.normalized();
    const Vec pole = Vec(sign * 0.5, -1.0, -0.3).normalized();  // elbow out, down and back
    Vec w = pole - pole.dot(u) * u;
    if (w.norm() < 1e-6) w = u.unitOrthogonal();
    w.normalize();
    const double cos_a = (a * a + d * d - b * b) / (2 * a * d);
    const Vec elbow = shoulder + a * (cos_a * u + std::sqrt(std::max(0.0, 1 - cos_a * cos_a)) * w);
    const Vec wrist = shoulder + d * u;
    // Upper arm and forearm frames share their third axis (the elbow's hinge), so the forearm
    // turns about the elbow's flexion axis; their second axis points where the limb bends.
    const Vec upper = (elbow - shoulder).normalized(), lower = (wrist - elbow).normalized();
    Vec bend = lower - lower.dot(upper) * upper;
    if (bend.norm() < 1e-6) bend = -w - (-w).dot(upper) * upper;
    bend.normalize();
    const Vec hinge = upper.cross(bend);
    auto frame = [](const Vec& along, const Vec& third) {
      const Vec n = (third - third.dot(along) * along).normalized();
      Eigen::Matrix3d m;
      m << along, n.cross(along), n;
      return m;
    };
    const Vec rest_upper = (c(elbow_[side]) - c(shoulder_[side])).normalized();
    const Vec rest_lower = (c(wrist_[side]) - c(elbow_[side])).normalized();
    const Vec rest_hinge = rest_upper.cross(Vec::UnitZ()).normalized();
    const Eigen::Quaterniond q_upper(frame(upper, hinge) *
                                     frame(rest_upper, rest_hinge).transpose());
    const Eigen::Quaterniond q_lower(frame(lower, hinge) *
                                     frame(rest_lower, rest_hinge).transpose());
    const Eigen::Quaterniond parent(world[s_[shoulder_[side]].parent].linear());
    p.rotations[shoulder_[side]] = (parent.conjugate() * q_upper).normalized();
    p.rotations[elbow_[side]] = (q_upper.conjugate() * q_lower).normalized();
  }

  GestureSpec spec_;
  const Skeleton& s_;
  Draw draw_;
  int root_ = 0;
  int shoulder_[2], elbow_[2], wrist_[2], hip_[2], ankle_[2];
  double upper_[2], lower_[2];
  std::array<Vec, 2> rest_, calibration_, hand_;
  double speed_ = 1, size_ = 0.35, aspect_ = 0.65, slant_ = 0;
  std::vector<Move> moves_;
};

}  // namespace

const std::vector<std::string>& gesture_kinds() {
  static const std::vector<std::string> kinds = {"0", "1", "2", "3",    "4",     "5",    "6",
                                                 "7", "8", "9", "wave", "point", "raise"};
  return kinds;
}

Motion generate_gestures(const GestureSpec& spec, const Skeleton& skeleton, double fps) {
  if (!(fps > 0) || !std::isfinite(fps)) {
    throw Error("gestures: frame rate must be positive, got " + std::to_string(fps));
  }
  return Corpus(spec, skeleton).build(fps);
}

}  // namespace simcap
