// The metric functions and evaluate() against values computed by hand or by an independent
// formula (explicit loops, the trace formula for rotation angles).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "core/error.h"
#include "models/humanoid.h"
#include "models/pose.h"
#include "validate/evaluation.h"
#include "validate/metrics.h"
#include "validate/report_html.h"

namespace simcap {
namespace {

// HE15 joints of the neutral humanoid, 3 x 15.
Eigen::Matrix3Xd he15_points() {
  const Skeleton s = build_humanoid();
  const auto p = joint_positions(s, Pose::neutral(s));
  Eigen::Matrix3Xd m(3, he15_joints().size());
  for (size_t j = 0; j < he15_joints().size(); ++j) {
    m.col(static_cast<Eigen::Index>(j)) = p[s.require(he15_joints()[j])];
  }
  return m;
}

EvaluationInput input_of(const std::vector<Eigen::Matrix3Xd>& truth,
                         const std::vector<Eigen::Matrix3Xd>& estimate) {
  EvaluationInput in;
  in.joints = he15_joints();
  for (size_t f = 0; f < truth.size(); ++f) in.frames.push_back(static_cast<int>(f));
  in.truth = truth;
  in.estimate = estimate;
  return in;
}

TEST(Metrics, JointDistances) {
  Eigen::Matrix3Xd a(3, 2), b(3, 2);
  a << 0, 1, 0, 1, 0, 1;
  b << 3, 1, 4, 1, 0, 3;
  const Eigen::VectorXd d = joint_distances(a, b);
  EXPECT_DOUBLE_EQ(d[0], 5.0);
  EXPECT_DOUBLE_EQ(d[1], 2.0);
}

TEST(Metrics, ProcrustesRemovesASimilarityTransform) {
  const Eigen::Matrix3Xd truth = he15_points();
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const double s = 1.3;
  const Eigen::Vector3d t(0.4, -0.2, 1.1);
  const Eigen::Matrix3Xd est = ((s * R) * truth).colwise() + t;
  const Eigen::Matrix3Xd aligned = procrustes_aligned(truth, est);
  EXPECT_LT(joint_distances(truth, aligned).maxCoeff(), 1e-9);

  // Evaluate over two frames: PA-MPJPE ~ 0, MPJPE the plain mean distance, computed by loop.
  const Evaluation ev = evaluate(input_of({truth, truth}, {est, est}));
  double sum = 0;
  for (Eigen::Index j = 0; j < truth.cols(); ++j) {
    const Eigen::Vector3d x = truth.col(j), y = s * R * x + t;
    sum += std::sqrt((y - x).dot(y - x));
  }
  EXPECT_NEAR(ev.mpjpe_mm, 1000.0 * sum / truth.cols(), 1e-9);
  EXPECT_NEAR(ev.pa_mpjpe_mm, 0.0, 1e-6);
  EXPECT_GT(ev.mpjpe_mm, 100.0);
}

TEST(Metrics, TranslationGivesItsLengthAsMpjpe) {
  const Eigen::Matrix3Xd truth = he15_points();
  const Eigen::Matrix3Xd est = truth.colwise() + Eigen::Vector3d(0.03, 0.0, 0.04);
  const Evaluation ev = evaluate(input_of({truth}, {est}));
  EXPECT_NEAR(ev.mpjpe_mm, 50.0, 1e-9);
  EXPECT_NEAR(ev.pa_mpjpe_mm, 0.0, 1e-6);
  EXPECT_NEAR(ev.rmse_mean_mm, 50.0, 1e-9);
  EXPECT_NEAR(ev.wrists_elbows_mm, 50.0, 1e-9);
  ASSERT_EQ(ev.pck.size(), 3u);
  EXPECT_DOUBLE_EQ(ev.pck[0].fraction, 1.0);  // 50 mm is "at or below" 50 mm
}

TEST(Metrics, OneCameraSplitsTheErrorAlongAndAcrossItsRays) {
  const Eigen::Matrix3Xd truth = he15_points();
  // Every joint moved 30 mm towards a far camera and 40 mm sideways of its ray.
  const Eigen::Vector3d centre(0.2, 1.1, 1000.0);
  Eigen::Matrix3Xd est = truth;
  for (int j = 0; j < truth.cols(); ++j) {
    const Eigen::Vector3d ray = (truth.col(j) - centre).normalized();
    const Eigen::Vector3d side = ray.cross(Eigen::Vector3d::UnitY()).normalized();
    est.col(j) += -0.03 * ray + 0.04 * side;
  }
  EvaluationInput in = input_of({truth}, {est});
  EXPECT_FALSE(evaluate(in).ray);
  in.camera_centre = centre;
  const Evaluation ev = evaluate(in);
  ASSERT_TRUE(ev.ray);
  EXPECT_NEAR(ev.ray->along_mm, 30.0, 1e-9);
  EXPECT_NEAR(ev.ray->across_mm, 40.0, 1e-9);
  EXPECT_NEAR(ev.mpjpe_mm, 50.0, 1e-9);
  ASSERT_TRUE(ev.per_joint[3].ray);
  EXPECT_NEAR(ev.per_joint[3].ray->along_mm, 30.0, 1e-9);

  // Per frame: a second frame tracked exactly halves the means over the take.
  in = input_of({truth, truth}, {est, truth});
  in.camera_centre = centre;
  const Evaluation two = evaluate(in);
  ASSERT_TRUE(two.per_frame[0].ray && two.per_frame[1].ray);
  EXPECT_NEAR(two.per_frame[0].ray->along_mm, 30.0, 1e-9);
  EXPECT_NEAR(two.per_frame[0].ray->across_mm, 40.0, 1e-9);
  EXPECT_NEAR(two.per_frame[1].ray->along_mm, 0.0, 1e-12);
  EXPECT_NEAR(two.ray->across_mm, 20.0, 1e-9);
  const std::string html = report_html(two, {});
  EXPECT_NE(html.find("<h2>Depth ambiguity</h2>"), std::string::npos);
  EXPECT_NE(html.find("along 15.0 mm, across 20.0 mm"), std::string::npos);
  EXPECT_EQ(report_html(evaluate(input_of({truth}, {est})), {}).find("Depth ambiguity"),
            std::string::npos);
}

TEST(Metrics, PckCountsErrorsAtOrBelowTheThreshold) {
  const std::vector<double> e = {10, 50, 60, 100, 149, 151, 200};
  EXPECT_DOUBLE_EQ(pck(e, 50), 2.0 / 7);
  EXPECT_DOUBLE_EQ(pck(e, 100), 4.0 / 7);
  EXPECT_DOUBLE_EQ(pck(e, 150), 5.0 / 7);
  EXPECT_DOUBLE_EQ(pck({}, 50), 0.0);
}

TEST(Metrics, PckOverJointFrames) {
  // Frame 0: every joint 20 mm off; frame 1: the 4 wrists/elbows 120 mm off, the rest exact.
  const Eigen::Matrix3Xd truth = he15_points();
  Eigen::Matrix3Xd f0 = truth.colwise() + Eigen::Vector3d(0.02, 0, 0), f1 = truth;
  for (int j : {5, 6, 7, 8}) f1.col(j).y() += 0.12;
  const Evaluation ev = evaluate(input_of({truth, truth}, {f0, f1}));
  EXPECT_DOUBLE_EQ(ev.pck[0].fraction, 26.0 / 30);  // 15 + 11 within 50 mm
  EXPECT_DOUBLE_EQ(ev.pck[1].fraction, 26.0 / 30);
  EXPECT_DOUBLE_EQ(ev.pck[2].fraction, 1.0);
  EXPECT_NEAR(ev.wrists_elbows_mm, (4 * 20.0 + 4 * 120.0) / 8, 1e-9);
  EXPECT_NEAR(ev.mpjpe_mm, (15 * 20.0 + 4 * 120.0) / 30, 1e-9);
}

TEST(Metrics, PerPointRmseIsTheRootMeanSquareOverFrames) {
  // l_elbow (column 5) is 30 mm off in frame 0 and 40 mm off in frame 1, others exact.
  const Eigen::Matrix3Xd truth = he15_points();
  Eigen::Matrix3Xd a = truth, b = truth;
  a.col(5).z() += 0.03;
  b.col(5).x() -= 0.04;
  const Evaluation ev = evaluate(input_of({truth, truth}, {a, b}));
  const JointScore& elbow = ev.per_joint[5];
  ASSERT_EQ(elbow.joint, "l_elbow");
  EXPECT_NEAR(elbow.mpjpe_mm, 35.0, 1e-9);
  EXPECT_NEAR(elbow.rmse_mm, std::sqrt((30.0 * 30 + 40.0 * 40) / 2), 1e-9);
  EXPECT_NEAR(elbow.max_mm, 40.0, 1e-9);
  EXPECT_NEAR(ev.per_joint[0].rmse_mm, 0.0, 1e-9);
  EXPECT_NEAR(ev.rmse_mean_mm, elbow.rmse_mm / 15, 1e-9);
  EXPECT_DOUBLE_EQ(root_mean_square({3, 4}), std::sqrt(12.5));
}

TEST(Metrics, RotationAngleMatchesTheTraceFormula) {
  const Eigen::Quaterniond a(Eigen::AngleAxisd(0.4, Eigen::Vector3d(0, 1, 1).normalized()));
  const Eigen::Quaterniond b(Eigen::AngleAxisd(-1.1, Eigen::Vector3d(1, 0.2, 0).normalized()));
  const Eigen::Matrix3d Ra = a.toRotationMatrix(), Rb = b.toRotationMatrix();
  const double expected = std::acos(((Ra * Rb.transpose()).trace() - 1) / 2);
  EXPECT_NEAR(rotation_angle(a, b), expected, 1e-12);
  const Eigen::Quaterniond c =
      a * Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()));
  EXPECT_NEAR(rotation_angle(a, c), 0.3, 1e-12);
  EXPECT_NEAR(rotation_angle(a, Eigen::Quaterniond(-a.coeffs())), 0.0, 1e-12);
}

TEST(Metrics, AngleRmseOverFrames) {
  const Eigen::Matrix3Xd truth = he15_points();
  EvaluationInput in = input_of({truth, truth}, {truth, truth});
  in.angle_joints = {"l_elbow"};
  const Eigen::Quaterniond id = Eigen::Quaterniond::Identity();
  in.truth_rotations = {{id}, {id}};
  in.estimate_rotations = {{Eigen::Quaterniond(Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()))},
                           {Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()))}};
  const Evaluation ev = evaluate(in);
  ASSERT_EQ(ev.angles.size(), 1u);
  EXPECT_NEAR(ev.angles[0].rmse_rad, std::sqrt((0.01 + 0.09) / 2), 1e-12);
  EXPECT_NEAR(ev.angles[0].mean_rad, 0.2, 1e-12);
  EXPECT_NEAR(ev.angles[0].max_rad, 0.3, 1e-12);
}

TEST(Metrics, FailureEpisodesAndRecovery) {
  const std::vector<int> frames = {10, 11, 12, 13, 14, 15, 16};
  const auto e = failure_episodes(frames, {50, 150, 160, 80, 120, 90, 200}, 100);
  ASSERT_EQ(e.size(), 3u);
  EXPECT_EQ(e[0].first_frame, 11);
  EXPECT_EQ(e[0].frames, 2);
  EXPECT_TRUE(e[0].recovered);
  EXPECT_EQ(e[1].first_frame, 14);
  EXPECT_EQ(e[1].frames, 1);
  EXPECT_TRUE(e[1].recovered);
  EXPECT_EQ(e[2].first_frame, 16);
  EXPECT_FALSE(e[2].recovered);
  EXPECT_TRUE(failure_episodes(frames, {1, 2, 3, 4, 5, 6, 100}, 100).empty());
}

TEST(Metrics, FailureSummaryInEvaluation) {
  const Eigen::Matrix3Xd truth = he15_points();
  const Eigen::Matrix3Xd off = truth.colwise() + Eigen::Vector3d(0, 0.15, 0);
  const Evaluation ev = evaluate(input_of({truth, truth, truth, truth}, {truth, off, off, truth}));
  EXPECT_EQ(ev.failures.failed_frames, 2);
  EXPECT_DOUBLE_EQ(ev.failures.failed_fraction, 0.5);
  ASSERT_EQ(ev.failures.episodes.size(), 1u);
  EXPECT_DOUBLE_EQ(ev.failures.mean_recovery_frames, 2.0);
  EXPECT_EQ(ev.failures.max_recovery_frames, 2);
  EXPECT_NEAR(ev.per_frame[1].mpjpe_mm, 150.0, 1e-9);
}

TEST(Metrics, ErrorsGroupedByVisibility) {
  const Eigen::Matrix3Xd truth = he15_points();
  Eigen::Matrix3Xd est = truth;
  est.col(0).x() += 0.1;  // humanoid_root: 100 mm, seen by 1 camera, scene-occluded elsewhere
  est.col(1).x() += 0.3;  // vc7: 300 mm, seen by 2 cameras, self-occluded in the third
  EvaluationInput in = input_of({truth}, {est});
  in.camera_count = 3;
  in.views = {std::vector<JointSight>(15, JointSight{3, Occlusion::none})};
  in.views[0][0] = {1, Occlusion::scene};
  in.views[0][1] = {2, Occlusion::self};
  const Evaluation ev = evaluate(in);
  ASSERT_EQ(ev.by_visible_cameras.size(), 4u);
  EXPECT_EQ(ev.by_visible_cameras[0].count, 0);
  EXPECT_EQ(ev.by_visible_cameras[1].count, 1);
  EXPECT_NEAR(ev.by_visible_cameras[1].mpjpe_mm, 100.0, 1e-9);
  EXPECT_NEAR(ev.by_visible_cameras[2].mpjpe_mm, 300.0, 1e-9);
  EXPECT_EQ(ev.by_visible_cameras[3].count, 13);
  EXPECT_NEAR(ev.by_visible_cameras[3].mpjpe_mm, 0.0, 1e-9);
  ASSERT_EQ(ev.by_occlusion.size(), 3u);
  EXPECT_EQ(ev.by_occlusion[0].label, "unoccluded");
  EXPECT_EQ(ev.by_occlusion[0].count, 13);
  EXPECT_NEAR(ev.by_occlusion[1].mpjpe_mm, 300.0, 1e-9);
  EXPECT_NEAR(ev.by_occlusion[2].mpjpe_mm, 100.0, 1e-9);
}

TEST(Metrics, InconsistentInputIsAnError) {
  const Eigen::Matrix3Xd truth = he15_points();
  EXPECT_THROW(evaluate(input_of({}, {})), Error);
  EXPECT_THROW(evaluate(input_of({truth}, {truth.leftCols(14)})), Error);
  EvaluationInput in = input_of({truth}, {truth});
  in.joints.pop_back();
  EXPECT_THROW(evaluate(in), Error);
}

}  // namespace
}  // namespace simcap
