// Unzueta's gesture chapter against independent references: spotting on synthetic pseudo-energy
// with known intervals (Alg. 14 worked by hand), the clamped spline against a hand computation
// and linear data, normalisation invariances, K-NN against brute force on a tiny set, the pelvis
// frame's invariance to the body's heading, and a whole leave-one-subject-out run on two
// synthetic subjects.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <numeric>
#include <random>

#include "models/humanoid.h"
#include "tests/support/error_of.h"
#include "tests/support/key_values.h"
#include "tests/support/temp_dir.h"
#include "tracker/unzueta/gesture_classifier.h"
#include "tracker/unzueta/gesture_evaluation.h"
#include "tracker/unzueta/gesture_normalization.h"
#include "tracker/unzueta/gesture_signals.h"
#include "tracker/unzueta/gesture_spotting.h"

namespace simcap::tracker {
namespace {

std::vector<double> pulses(int n, const std::vector<std::pair<int, int>>& on, double height) {
  std::vector<double> e(static_cast<size_t>(n), 0.0);
  for (auto [a, b] : on) {
    for (int i = a; i <= b; ++i) e[static_cast<size_t>(i)] = height;
  }
  return e;
}

void expect_segments(const std::vector<SpottedStretch>& got,
                     const std::vector<std::pair<int, int>>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (size_t i = 0; i < want.size(); ++i) {
    EXPECT_EQ(got[i].first, want[i].first) << i;
    EXPECT_EQ(got[i].last, want[i].second) << i;
  }
}

TEST(GestureSpotting, PseudoEnergyIsHalfTheSquaredSpeed) {
  const std::vector<Eigen::Vector3d> x = {{0, 0, 0}, {0.1, 0, 0}, {0.1, 0.2, 0}};
  const auto e = kinetic_pseudo_energy(x, 30.0);
  EXPECT_DOUBLE_EQ(e[0], 0.0);
  EXPECT_NEAR(e[1], 0.5 * 3.0 * 3.0, 1e-12);
  EXPECT_NEAR(e[2], 0.5 * 6.0 * 6.0, 1e-12);
}

TEST(GestureSpotting, HistoryMeanByHand) {
  // History of 3: the first two frames average what there is.
  const std::vector<double> mean = history_mean({3, 0, 6, 3, 0}, 3);
  EXPECT_EQ(mean, (std::vector<double>{3, 1.5, 3, 3, 3}));
}

TEST(GestureSpotting, Algorithm14DelayByHand) {
  // History [t-9, t] = [41, 50]; psE < threshold last at 47.
  const auto e = pulses(60, {{48, 59}}, 1.0);
  EXPECT_EQ(spotting_delay(e, 50, 10, 0.5), 3);
  EXPECT_EQ(spotting_delay(e, 59, 10, 0.5), 0);  // nothing below in [50, 59]
}

TEST(GestureSpotting, KnownIntervalsWithADirectionChange) {
  // Two gestures at [50, 79] and [150, 169], the first with a two-frame stop (a wave turning):
  // the mean over 10 frames with psE = 2 x threshold crosses after 5 moving frames (t = 54), so
  // Alg. 14 finds the last still frame 49 (delay 5); it falls below at t = 85, minus 5: 80.
  auto e = pulses(200, {{50, 79}, {150, 169}}, 0.36);
  e[64] = e[65] = 0.0;
  SpottingParams p;
  p.threshold = 0.18;
  p.drop_largest = 0;  // the thesis' mean
  p.delay_at_end = false;
  expect_segments(spot_gestures(e, p), {{49, 80}, {149, 170}});
  // Measured where the history falls below (t = 85, 175): the last moving frames, 79 and 169.
  p.delay_at_end = true;
  expect_segments(spot_gestures(e, p), {{49, 79}, {149, 169}});
  // A short twitch is not a gesture; one still open at the end closes there (its history is
  // above the threshold from t = 34 to the last frame 39: 6 frames).
  p.min_frames = 6;
  expect_segments(spot_gestures(pulses(40, {{5, 7}, {30, 39}}, 0.36), p), {{29, 39}});
  p.min_frames = 7;
  EXPECT_TRUE(spot_gestures(pulses(40, {{5, 7}, {30, 39}}, 0.36), p).empty());
}

TEST(GestureSpotting, TheEndsDelayIsMeasuredAtTheEnd) {
  // A 10-frame stroke [40, 49] at psE 2: the history crosses at t = 40 (2 / 10), Alg. 14's
  // delay is 1 (start 39); the history holds the stroke until it has left the window, below at
  // t = 59. The start's delay puts the end at 58, nine frames late; measured at the end, the
  // last frame at or above the threshold is 49.
  const auto e = pulses(100, {{40, 49}}, 2.0);
  SpottingParams p;
  p.threshold = 0.18;
  p.delay_at_end = false;
  expect_segments(spot_gestures(e, p), {{39, 58}});
  p.delay_at_end = true;
  expect_segments(spot_gestures(e, p), {{39, 49}});
  // Six moving frames [40, 45] keep the history above the threshold for 15 frames (t = 40 to
  // 54): the stretch [39, 45] is kept although it is shorter than `min_frames`, which counts the
  // history; a history above for fewer frames is dropped.
  expect_segments(spot_gestures(pulses(100, {{40, 45}}, 2.0), p), {{39, 45}});
  p.min_frames = 16;
  EXPECT_TRUE(spot_gestures(pulses(100, {{40, 45}}, 2.0), p).empty());
}

TEST(GestureSpotting, PathWidensToTheMotionsOnsetAndOffset) {
  // psE 4 (speed 2.83) on [40, 49], 0.04 (speed 0.28, 10 % of it) on [34, 39] and [50, 52],
  // 0.005 (2.5 %) on [30, 33]: at 5 % of the peak speed the path runs from 34 to 52, at 20 %
  // it is the stretch; it never passes the neighbours' bounds.
  std::vector<double> e = pulses(80, {{40, 49}}, 4.0);
  for (int i = 34; i <= 52; ++i) {
    if (i < 40 || i > 49) e[i] = 0.04;
  }
  for (int i = 30; i <= 33; ++i) e[i] = 0.005;
  auto expect = [](SpottedStretch got, int first, int last) {
    EXPECT_EQ(got.first, first);
    EXPECT_EQ(got.last, last);
  };
  expect(widen_to_motion(e, {40, 49}, 0, 79, 0.05), 34, 52);
  expect(widen_to_motion(e, {40, 49}, 0, 79, 0.2), 40, 49);
  expect(widen_to_motion(e, {40, 49}, 0, 79, 0.0), 40, 49);
  expect(widen_to_motion(e, {40, 49}, 0, 79, 0.02), 30, 52);
  expect(widen_to_motion(e, {40, 49}, 37, 50, 0.05), 37, 50);
}

TEST(GestureSpotting, OneFrameJumpIsNotAGestureWithoutItsLargestValue) {
  // A still hand whose tracked position jumps once (psE 6 at frame 40: a 0.12 m step at 30
  // frames/s) besides a gesture at [100, 129]. The thesis' mean reads the jump as an 11-frame
  // stretch (6 / 10 >= 0.18 from t = 40 to 49, moved back by Alg. 14's delay of 1); without each
  // history's largest value it never reaches the threshold, so the stretch is dropped. The
  // gesture (mean crossing at t = 104, Alg. 14's delay 5, below again at t = 135) is confirmed
  // at t = 105 (5 x 0.36 / 9) and keeps the thesis' ends [99, 130].
  auto e = pulses(200, {{100, 129}}, 0.36);
  e[40] = 6.0;
  SpottingParams p;
  p.threshold = 0.18;
  p.drop_largest = 0;
  p.delay_at_end = false;  // the thesis' ends
  expect_segments(spot_gestures(e, p), {{39, 49}, {99, 130}});
  p.drop_largest = 1;
  expect_segments(spot_gestures(e, p), {{99, 130}});
  // Brute force: the mean of the 9 smallest of each 10-frame history.
  auto trimmed = [&](int t) {
    std::vector<double> w(e.begin() + t - 9, e.begin() + t + 1);
    std::sort(w.begin(), w.end());
    return std::accumulate(w.begin(), w.end() - 1, 0.0) / 9.0;
  };
  for (int t = 40; t <= 49; ++t) EXPECT_LT(trimmed(t), p.threshold) << t;
  EXPECT_LT(trimmed(104), p.threshold);
  EXPECT_GE(trimmed(105), p.threshold);
  // Two jumps in one history are two largest values: dropping two discards them as well.
  e[44] = 6.0;
  EXPECT_EQ(spot_gestures(e, p).size(), 2u);
  p.drop_largest = 2;
  EXPECT_EQ(spot_gestures(e, p).size(), 1u);
}

// A hand moving at 0.3 m/s along X (30 frames/s) whose track jumps: frame 1 lies 0.1 m off
// frame 0 (the calibration posture against the first tracked frame); frames 40, 43-44, 47 and
// 50-51 read a surface 0.12 m behind the hand (a depth flickering between two surfaces); frame
// 80 spikes 0.2 m for one frame.
std::vector<Eigen::Vector3d> jumpy_path() {
  std::vector<Eigen::Vector3d> x;
  for (int i = 0; i < 120; ++i) {
    Eigen::Vector3d p(0.01 * i, 0, 0);
    if (i >= 1) p.z() += 0.1;
    if (i == 40 || i == 43 || i == 44 || i == 47 || i == 50 || i == 51) p.z() += 0.12;
    if (i == 80) p.z() += 0.2;
    x.push_back(p);
  }
  return x;
}

TEST(GestureSpotting, MedianVelocityPathDropsJumpsAndKeepsMotion) {
  const auto x = jumpy_path();
  const auto r = median_velocity_path(x, 5);
  ASSERT_EQ(r.size(), x.size());
  // The steady motion is all that is left: 0.01 m a frame along X from x[0].
  for (size_t i = 0; i < r.size(); ++i) {
    EXPECT_LT((r[i] - Eigen::Vector3d(0.01 * static_cast<double>(i), 0, 0)).norm(), 1e-12) << i;
  }
  const auto e = kinetic_pseudo_energy(r, 30.0);
  for (size_t i = 1; i < e.size(); ++i) EXPECT_NEAR(e[i], 0.5 * 0.3 * 0.3, 1e-9) << i;
  // 1 frame: the path itself.
  EXPECT_EQ(median_velocity_path(x, 1), x);
  // A stroke that lasts (0.05 m a frame for 10 frames) keeps its speed inside.
  std::vector<Eigen::Vector3d> stroke(40, Eigen::Vector3d::Zero());
  for (int i = 15; i < 40; ++i) stroke[i].y() = 0.05 * std::min(i - 14, 10);
  const auto s = median_velocity_path(stroke, 5);
  for (int i = 18; i <= 22; ++i) EXPECT_NEAR(s[i].y() - s[i - 1].y(), 0.05, 1e-12) << i;
}

TEST(GestureSpotting, TrackJumpsAreNoGesture) {
  // From the path's own velocities (the thesis) the flicker is a gesture, even without each
  // history's largest value; from its median velocities nothing is.
  GestureOptions o;
  o.spotting.velocity_median = 1;
  const auto x = jumpy_path();
  expect_segments(spot_gestures(spotting_energy(x, 30.0, o), o.spotting), {{44, 53}});
  o.spotting.velocity_median = 5;
  EXPECT_TRUE(spot_gestures(spotting_energy(x, 30.0, o), o.spotting).empty());
  // A 1 m/s stroke over frames 60-74 of the same track is spotted there.
  auto with_stroke = x;
  for (int i = 60; i < 120; ++i) with_stroke[i].y() += 0.033 * std::min(i - 59, 15);
  expect_segments(spot_gestures(spotting_energy(with_stroke, 30.0, o), o.spotting), {{59, 74}});
}

TEST(GestureNormalization, ClampedSplineByHand) {
  // y = (0, 1, 0), end slopes 1 and -1: the second derivatives solve 2 M0 + M1 = 0,
  // M0 + 4 M1 + M2 = -12, M1 + 2 M2 = 0, so M = (2, -4, 2) and
  // S(0.5) = 2/48 - 4/48 + (0 - 2/6) / 2 + (1 + 4/6) / 2 = 5/8.
  Eigen::MatrixXd y(3, 1);
  y << 0, 1, 0;
  const Eigen::MatrixXd r = resample_clamped_spline(y, 5);
  EXPECT_NEAR(r(0, 0), 0.0, 1e-12);
  EXPECT_NEAR(r(1, 0), 0.625, 1e-12);
  EXPECT_NEAR(r(2, 0), 1.0, 1e-12);
  EXPECT_NEAR(r(3, 0), 0.625, 1e-12);
  EXPECT_NEAR(r(4, 0), 0.0, 1e-12);
  // Linear data is reproduced exactly (its slopes are its first differences).
  Eigen::MatrixXd line(7, 2);
  for (int i = 0; i < 7; ++i) line.row(i) << 2.0 + 0.5 * i, -1.0 * i;
  const Eigen::MatrixXd l = resample_clamped_spline(line, 13);
  for (int s = 0; s < 13; ++s) {
    const double t = 0.5 * s;
    EXPECT_NEAR(l(s, 0), 2.0 + 0.5 * t, 1e-12);
    EXPECT_NEAR(l(s, 1), -t, 1e-12);
  }
}

TEST(GestureNormalization, IgnoresPlaceAndSize) {
  std::vector<Eigen::Vector3d> path, moved;
  for (int i = 0; i < 23; ++i) {
    const double a = 0.3 * i;
    path.emplace_back(0.2 * std::cos(a), 0.1 * std::sin(a), 0.01 * i);
    moved.push_back(2.5 * path.back() + Eigen::Vector3d(1, -3, 0.5));
  }
  const Eigen::VectorXd n = normalize_gesture(path);
  ASSERT_EQ(n.size(), 90);
  EXPECT_NEAR(n.minCoeff(), 0.0, 1e-12);
  EXPECT_NEAR(n.maxCoeff(), 50.0, 1e-12);
  EXPECT_LT((normalize_gesture(moved) - n).norm(), 1e-9);
}

TEST(GestureClassifier, KnnAgreesWithBruteForceAndSvmSeparatesClusters) {
  std::mt19937 rng(5);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<Eigen::VectorXd> x;
  std::vector<std::string> y;
  const std::vector<std::string> names = {"a", "b", "c"};
  for (int i = 0; i < 30; ++i) {
    Eigen::VectorXd v(2);
    v << g(rng) + 6.0 * (i % 3), g(rng);
    x.push_back(v);
    y.push_back(names[static_cast<size_t>(i % 3)]);
  }
  GestureClassifier knn(GestureClassifierKind::knn);
  knn.train(x, y);
  GestureClassifier svm(GestureClassifierKind::svm);
  svm.train(x, y);
  for (int q = 0; q < 50; ++q) {
    Eigen::VectorXd v(2);
    v << 14.0 * (g(rng) * 0.3 + 0.5) - 1.0, 2.0 * g(rng);
    size_t best = 0;
    for (size_t i = 1; i < x.size(); ++i) {
      if ((x[i] - v).squaredNorm() < (x[best] - v).squaredNorm()) best = i;
    }
    EXPECT_EQ(knn.predict(v), y[best]);
  }
  for (int c = 0; c < 3; ++c) {
    Eigen::VectorXd v(2);
    v << 6.0 * c, 0.0;
    EXPECT_EQ(svm.predict(v), names[static_cast<size_t>(c)]);
  }
  EXPECT_NE(testing::error_of([] {
              GestureClassifier(GestureClassifierKind::knn).train({}, {});
            }).find("at least one"),
            std::string::npos);
}

// A neutral humanoid's HE15 joints, turned by `yaw` and moved by `at`, the right wrist put at
// `hand` (pelvis frame).
std::vector<Eigen::Vector3d> body_at(const Skeleton& s, double yaw, const Eigen::Vector3d& at,
                                     const Eigen::Vector3d& hand, const Eigen::Vector3d& left) {
  const Eigen::Matrix3d r = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const Eigen::Vector3d root = s[s.require("humanoid_root")].center;
  std::vector<Eigen::Vector3d> out;
  for (const auto& name : he15_joints()) {
    Eigen::Vector3d p = s[s.require(name)].center - root;
    if (name == "r_radiocarpal") p = hand;
    if (name == "l_radiocarpal") p = left;
    out.push_back(r * p + at);
  }
  return out;
}

TEST(GestureSignals, PelvisFrameIgnoresHeading) {
  const Skeleton s = build_humanoid(BodyParameters{});
  JointTrack t;
  t.joints = he15_joints();
  const Eigen::Vector3d hand(-0.3, 0.4, 0.2), left(0.25, -0.1, 0.05);
  t.add_frame(0, body_at(s, 0.0, {0, 1, 0}, hand, left));
  t.add_frame(1, body_at(s, 2.0, {1, 1, -2}, hand, left));
  const BodySignals b = body_signals(t, "test");
  for (int f = 0; f < 2; ++f) {
    EXPECT_LT((b.hand[1][f] - hand).norm(), 1e-9);
    EXPECT_LT((b.hand[0][f] - left).norm(), 1e-9);
  }
  EXPECT_LT((b.pose[0] - b.pose[1]).norm(), 1e-9);
  JointTrack missing;
  missing.joints = {"humanoid_root"};
  EXPECT_NE(testing::error_of([&] { body_signals(missing, "x.csv"); }).find("x.csv: no joint"),
            std::string::npos);
}

// A synthetic subject's corpus, written frame by frame into its track; the hands' rest places.
struct Recording {
  explicit Recording(std::string name) {
    c.name = std::move(name);
    c.fps = 30;
    t.joints = he15_joints();
  }
  GestureCorpus c;
  JointTrack t;
  int frame = 0;
  GestureCorpus finish() {
    c.signals = body_signals(t, c.name);
    return std::move(c);
  }
};
const Eigen::Vector3d rest(-0.25, -0.1, 0.1), left(0.25, -0.1, 0.05);

// One subject: the right hand draws circles upright ("O") and level ("C") at 1.2 m/s, held still
// ("down") in between; `scale` and `yaw` make the subject differ.
GestureCorpus synthetic_subject(const Skeleton& s, double scale, double yaw, std::string name) {
  Recording r(std::move(name));
  auto& [c, t, frame] = r;
  auto hold = [&](int n) {
    c.truth.push_back({"subject", "r_hand", "static", "down", frame, frame + n - 1});
    for (int i = 0; i < n; ++i) t.add_frame(frame++, body_at(s, yaw, {0, 1, 0}, rest, left));
  };
  auto gesture = [&](const std::string& label) {
    const int n = 40;
    c.truth.push_back({"subject", "r_hand", "dynamic", label, frame, frame + n - 1});
    for (int i = 0; i < n; ++i) {
      const double u = static_cast<double>(i + 1) / n;
      Eigen::Vector3d p = rest;
      if (label == "O") {
        p += scale *
             Eigen::Vector3d(0.25 * std::sin(2 * M_PI * u), 0.25 * (1 - std::cos(2 * M_PI * u)), 0);
      } else {
        p += scale *
             Eigen::Vector3d(0.25 * std::sin(2 * M_PI * u), 0, 0.25 * (1 - std::cos(2 * M_PI * u)));
      }
      t.add_frame(frame++, body_at(s, yaw, {0, 1, 0}, p, left));
    }
  };
  hold(30);
  for (const char* label : {"O", "C", "O", "C", "C", "O"}) {
    gesture(label);
    hold(30);
  }
  return r.finish();
}

TEST(GestureEvaluation, TwoSyntheticSubjectsAreSpottedAndRecognised) {
  const Skeleton s = build_humanoid(BodyParameters{});
  const std::vector<GestureCorpus> corpora = {synthetic_subject(s, 1.0, 0.0, "one"),
                                              synthetic_subject(s, 0.8, 0.7, "two")};
  const GestureResults r = evaluate_gestures(corpora, {});
  EXPECT_EQ(r.truth_count, 12);
  EXPECT_EQ(r.matched, 12);
  EXPECT_DOUBLE_EQ(r.f1, 1.0);
  for (const auto& [kind, conf] : r.recognition) {
    EXPECT_EQ(conf.total, 12) << name_of(kGestureClassifiers, kind);
    EXPECT_DOUBLE_EQ(conf.accuracy, 1.0) << name_of(kGestureClassifiers, kind);
  }
  EXPECT_GT(r.poses.total, 0);
  EXPECT_DOUBLE_EQ(r.poses.accuracy, 1.0);
  EXPECT_NE(testing::error_of([&] { evaluate_gestures({corpora[0]}, {}); }).find("two corpora"),
            std::string::npos);
}

// One subject: the right hand moves slowly (0.4 m/s, under the spotting threshold) up and back
// ("hook") or down and back ("bar"), 5 frames each way, then slowly to its left for 5 frames and
// fast (1.2 m/s) down for 20. Both gestures end alike, and the frames the spotting keeps (the
// fast stroke and the last slow ones, with the smoothing's reach) are alike too: they differ only
// in the slow strokes the spotting cuts off. Held still between, the hand goes back slowly.
GestureCorpus slow_stroke_subject(const Skeleton& s, double scale, std::string name) {
  Recording r(std::move(name));
  auto& [c, t, frame] = r;
  Eigen::Vector3d hand = rest;
  auto go = [&](const Eigen::Vector3d& to, int n) {
    const Eigen::Vector3d from = hand;
    for (int i = 1; i <= n; ++i) {
      hand = from + (to - from) * static_cast<double>(i) / n;
      t.add_frame(frame++, body_at(s, 0, {0, 1, 0}, hand, left));
    }
  };
  auto hold = [&](int n) {
    c.truth.push_back({"subject", "r_hand", "static", "down", frame, frame + n - 1});
    go(rest, n);
  };
  for (const char* label : {"hook", "bar", "bar", "hook"}) {
    hold(30);
    c.truth.push_back({"subject", "r_hand", "dynamic", label, frame, frame + 34});
    const double up = std::string(label) == "hook" ? 1 : -1;
    const double slow = 0.4 / 30 * 5;
    go(rest + scale * Eigen::Vector3d(0, up * slow, 0), 5);
    go(rest, 5);
    go(rest + scale * Eigen::Vector3d(slow, 0, 0), 5);
    go(hand + scale * Eigen::Vector3d(0, -1.2 / 30 * 20, 0), 20);
    go(rest, 60);
  }
  hold(30);
  return r.finish();
}

TEST(GestureEvaluation, TheSlowStrokesTheSpottingCutsAreRecognised) {
  const Skeleton s = build_humanoid(BodyParameters{});
  const std::vector<GestureCorpus> corpora = {slow_stroke_subject(s, 1.0, "one"),
                                              slow_stroke_subject(s, 0.9, "two")};
  GestureOptions o;
  const GestureResults r = evaluate_gestures(corpora, o);
  ASSERT_EQ(r.matched, 8);
  for (const auto& [kind, conf] : r.recognition) {
    EXPECT_DOUBLE_EQ(conf.accuracy, 1.0) << name_of(kGestureClassifiers, kind);
  }
  for (const auto& g : r.corpora[0].spotted) {
    EXPECT_LT(g.path_first, g.first_frame);
  }
  // The thesis' path, the spotted stretch alone: the fast strokes are alike.
  o.path_speed_fraction = 0;
  const GestureResults thesis = evaluate_gestures(corpora, o);
  EXPECT_EQ(thesis.matched, 8);
  EXPECT_LT(thesis.recognition.at(GestureClassifierKind::knn).accuracy, 1.0);
}

TEST(GestureEvaluation, ALimbNoOtherSubjectUsedIsUnknown) {
  const Skeleton s = build_humanoid(BodyParameters{});
  GestureCorpus left = synthetic_subject(s, 1.0, 0.0, "left");
  std::swap(left.signals.hand[0], left.signals.hand[1]);
  for (auto& g : left.truth) g.limb = "l_hand";
  const GestureResults r = evaluate_gestures({synthetic_subject(s, 1.0, 0.0, "right"), left}, {});
  EXPECT_EQ(r.matched, 12);
  const Confusion& c = r.recognition.at(GestureClassifierKind::knn);
  EXPECT_EQ(c.total, 12);
  EXPECT_EQ(c.correct, 0);
  for (const auto& g : r.corpora[0].spotted) {
    EXPECT_EQ(g.predicted.at(GestureClassifierKind::knn), "unknown");
  }
}

// The command on two short renders of scenes/gestures.yaml scored on their truth: the last
// line agrees with gestures.json; bad inputs are named.
TEST(GesturesCommand, ScoresRenderedCorporaAndNamesBadInput) {
  testing::TempDir tmp;
  const std::string scene = std::string(SIMCAP_SOURCE_DIR) + "/scenes/gestures.yaml";
  for (int seed : {1, 2}) {
    const std::string ds = (tmp / ("g" + std::to_string(seed))).string();
    ASSERT_EQ(testing::run_simcap("render " + scene + " -o " + ds + " --frames 450 --seed " +
                                  std::to_string(seed) + " --set rig.resolution=[160,120] -q"),
              0);
  }
  const std::string g1 = (tmp / "g1").string(), g2 = (tmp / "g2").string();
  const std::string out = (tmp / "out").string();
  std::string text;
  ASSERT_EQ(testing::run_simcap(
                "gestures " + g1 + " " + g1 + "/gt " + g2 + " " + g2 + "/gt -o " + out, &text),
            0)
      << text;
  const auto fields = testing::key_values(testing::last_line(text));
  ASSERT_TRUE(fields.contains("spotting_f1") && fields.contains("recognition_accuracy")) << text;
  std::ifstream in(out + "/gestures.json");
  const auto j = nlohmann::json::parse(in);
  EXPECT_NEAR(j["spotting"]["f1"].get<double>(), std::stod(fields.at("spotting_f1")), 1e-4);
  EXPECT_EQ(j["spotting"]["truth_gestures"].get<int>(), 2);
  EXPECT_TRUE(std::filesystem::exists(out + "/spotted.csv"));
  // The page: the scores, and a plot per subject and hand with the threshold drawn.
  std::ifstream page(out + "/report.html");
  const std::string html((std::istreambuf_iterator<char>(page)), std::istreambuf_iterator<char>());
  EXPECT_NE(html.find("Spotting: precision / recall / F1"), std::string::npos);
  size_t plots = 0;
  for (size_t at = html.find("<svg"); at != std::string::npos; at = html.find("<svg", at + 1)) {
    ++plots;
  }
  EXPECT_EQ(plots, 4u);
  EXPECT_NE(html.find("r_hand: mean pseudo-energy"), std::string::npos);

  EXPECT_EQ(testing::run_simcap("gestures " + g1 + " " + g1 + "/gt " + g2 + " -o " + out, &text),
            1);
  EXPECT_NE(text.find("DATASET TRACK pairs"), std::string::npos) << text;
  EXPECT_EQ(testing::run_simcap("gestures " + g1 + " " + g1 + " " + g2 + " " + g2 + "/gt -o " + out,
                                &text),
            1);
  EXPECT_NE(text.find("joints3d.csv"), std::string::npos) << text;
  EXPECT_EQ(testing::run_simcap(
                "gestures " + g1 + "/gt " + g1 + "/gt " + g2 + " " + g2 + "/gt -o " + out, &text),
            1);
  EXPECT_NE(text.find("gestures.csv"), std::string::npos) << text;
  // A corpus cut short holds no whole gesture and no table: the error names that cause too.
  EXPECT_NE(text.find("render --frames or render.first_frame may leave them all out"),
            std::string::npos)
      << text;
}

// `simcap loop --subjects`: render, track and validate each subject, then the gestures of all;
// a scene without gestures is refused after its first subject, with no gesture scores written.
TEST(GesturesCommand, LoopOverSubjectsEndsInGestureScores) {
  testing::TempDir tmp;
  const std::string scenes = std::string(SIMCAP_SOURCE_DIR) + "/scenes/";
  const std::string out = (tmp / "loop").string();
  std::string text;
  ASSERT_EQ(testing::run_simcap("loop " + scenes + "gestures.yaml -o " + out +
                                    " --subjects 2 --seed 3 --frames 450 --set "
                                    "rig.resolution=[160,120] --method sik --effectors gt "
                                    "--no-media -q",
                                &text),
            0)
      << text;
  for (const char* subject : {"/subject3", "/subject4"}) {
    EXPECT_TRUE(std::filesystem::exists(out + subject + "/report/metrics.json")) << subject;
  }
  const auto fields = testing::key_values(testing::last_line(text));
  ASSERT_TRUE(fields.contains("spotting_f1")) << text;
  std::ifstream in(out + "/gestures/gestures.json");
  EXPECT_NEAR(nlohmann::json::parse(in)["spotting"]["f1"].get<double>(),
              std::stod(fields.at("spotting_f1")), 1e-4);

  const std::string walk = (tmp / "walk").string();
  EXPECT_EQ(testing::run_simcap("loop " + scenes + "studio4.yaml -o " + walk +
                                    " --subjects 2 --frames 3 --no-media -q",
                                &text),
            1);
  EXPECT_NE(text.find("no gesture motion"), std::string::npos) << text;
  EXPECT_FALSE(std::filesystem::exists(walk + "/gestures"));
  EXPECT_FALSE(std::filesystem::exists(walk + "/subject2"));
}

}  // namespace
}  // namespace simcap::tracker
