// The building blocks of Unzueta's tracking from pixels against independent references: DLT
// triangulation against OpenCV's cv::triangulatePoints and cv::projectPoints, the point Kalman
// filter against the filter equations computed by hand, CFOF following a textured patch
// (also while hidden, carried with the body's motion) and depth quantiles against a sort.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <limits>
#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>
#include <opencv2/imgproc.hpp>
#include <random>

#include "core/error.h"
#include "tracker/common/triangulation.h"
#include "tracker/unzueta/cfof.h"
#include "tracker/unzueta/depth_lookup.h"
#include "tracker/unzueta/point_kalman.h"

namespace simcap::tracker {
namespace {

std::vector<Camera> ring() {
  std::vector<Camera> cams;
  for (int i = 0; i < 3; ++i) {
    const double a = 0.9 * i;
    cams.push_back(Camera::look_at("cam0" + std::to_string(i), 640, 480, 1.0,
                                   {4 * std::sin(a), 1.6, 4 * std::cos(a)}, {0, 1, 0}));
  }
  return cams;
}

cv::Mat projection(const Camera& c) {
  Eigen::Matrix<double, 3, 4> rt;
  rt << c.R, c.t;
  cv::Mat p;
  cv::eigen2cv(Eigen::Matrix<double, 3, 4>(c.K * rt), p);
  return p;
}

TEST(Triangulation, AgreesWithOpenCvTriangulatePoints) {
  const auto cams = ring();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.8, 0.8);
  std::normal_distribution<double> noise(0.0, 0.5);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Vector3d x(u(rng), 1.0 + u(rng), u(rng));
    // Pixels from cv::projectPoints, with half a pixel of noise so that the solutions differ
    // from the truth and the two algorithms are compared, not merely the exact point.
    std::vector<PixelObservation> views;
    std::vector<cv::Point2d> px;
    for (const Camera& c : cams) {
      cv::Mat rvec, tvec, k;
      cv::Mat r;
      cv::eigen2cv(c.R, r);
      cv::Rodrigues(r, rvec);
      cv::eigen2cv(c.t, tvec);
      cv::eigen2cv(c.K, k);
      std::vector<cv::Point2d> out;
      cv::projectPoints(std::vector<cv::Point3d>{{x.x(), x.y(), x.z()}}, rvec, tvec, k,
                        cv::noArray(), out);
      px.push_back(out[0] + cv::Point2d(noise(rng), noise(rng)));
      views.push_back({&c, {px.back().x, px.back().y}});
    }
    // Exact pixels give the point back (the cv::projectPoints round trip).
    std::vector<PixelObservation> exact = views;
    for (size_t i = 0; i < cams.size(); ++i) exact[i].pixel = *cams[i].project(x);
    const auto back = triangulate(exact);
    ASSERT_TRUE(back);
    EXPECT_LT((*back - x).norm(), 1e-9);
    // Two views: cv::triangulatePoints solves the same DLT.
    const std::vector<PixelObservation> two = {views[0], views[1]};
    const auto mine = triangulate(two);
    ASSERT_TRUE(mine);
    cv::Mat h;
    cv::triangulatePoints(projection(cams[0]), projection(cams[1]), cv::Mat(cv::Point2d(px[0])),
                          cv::Mat(cv::Point2d(px[1])), h);
    const Eigen::Vector3d theirs(h.at<double>(0) / h.at<double>(3),
                                 h.at<double>(1) / h.at<double>(3),
                                 h.at<double>(2) / h.at<double>(3));
    EXPECT_LT((*mine - theirs).norm(), 1e-3) << "trial " << trial;
    EXPECT_LT(reprojection_rms(*mine, two), 1.0);
  }
  const auto cam = ring();
  EXPECT_FALSE(triangulate({{&cam[0], Eigen::Vector2d(320, 240)}}));
}

TEST(DepthLookup, QuantileAgainstASortSkippingEmptyAndOutsidePixels) {
  // A hand end-on over its forearm: 40 px at 2.0-2.39 m, 4 background pixels (+inf), one
  // point outside the image.
  cv::Mat depth(10, 10, CV_32FC1, cv::Scalar(std::numeric_limits<float>::infinity()));
  std::vector<cv::Point> at;
  std::vector<float> z;
  for (int i = 0; i < 40; ++i) {
    const cv::Point p(i % 10, i / 10);
    depth.at<float>(p) = 2.0f + 0.01f * static_cast<float>((i * 7) % 40);
    at.push_back(p);
    z.push_back(depth.at<float>(p));
  }
  for (int x = 0; x < 4; ++x) at.emplace_back(x, 9);
  at.emplace_back(12, 3);
  std::sort(z.begin(), z.end());
  EXPECT_FLOAT_EQ(*depth_quantile(depth, at, 0.0), z.front());
  EXPECT_FLOAT_EQ(*depth_quantile(depth, at, 0.1), z[4]);
  EXPECT_FLOAT_EQ(*depth_quantile(depth, at, 0.5), z[20]);
  EXPECT_FLOAT_EQ(*depth_quantile(depth, at, 1.0), z.back());
  EXPECT_FALSE(depth_quantile(depth, {{0, 9}, {-1, 0}}, 0.5));
}

// A hand pointing at the camera: 20 px of hand at 2.0 m over 60 px of forearm at 2.3 m. Its
// 3D point is read on the hand, its place in the occlusion order on the whole blob.
TEST(DepthLookup, PartDepthReadsTheSurfaceAndTheOrderAtTheirOwnQuantiles) {
  cv::Mat depth(8, 10, CV_32FC1, cv::Scalar(2.3f));
  depth(cv::Rect(0, 0, 10, 2)).setTo(2.0f);
  std::vector<cv::Point> at;
  for (int y = 0; y < depth.rows; ++y) {
    for (int x = 0; x < depth.cols; ++x) at.emplace_back(x, y);
  }
  const auto z = part_depth(depth, at, 0.1, 0.5);
  ASSERT_TRUE(z);
  EXPECT_FLOAT_EQ(z->surface, 2.0f);
  EXPECT_FLOAT_EQ(z->order, 2.3f);
  EXPECT_FALSE(part_depth(depth, {{-1, 0}}, 0.1, 0.5));
  // With a thickness the median is kept only within it of the nearest tenth: 2.0 + 0.05 m.
  const auto thick = part_depth(depth, at, 0.5, 0.5, 0.05);
  EXPECT_FLOAT_EQ(thick->surface, 2.05f);
  EXPECT_FLOAT_EQ(thick->order, 2.3f);
  // A part as deep as its pixels spread (a hand seen flat, 2.30-2.33 m) keeps its median.
  depth(cv::Rect(0, 0, 10, 2)).setTo(2.33f);
  EXPECT_FLOAT_EQ(part_depth(depth, at, 0.5, 0.5, 0.05)->surface, 2.3f);
}

TEST(PointKalman, MatchesTheFilterEquationsByHand) {
  const PointKalmanNoise noise{2.0, 1.0};
  PointKalman k({10, 20}, noise, 100.0, {1, -2});
  Eigen::Matrix4d a = Eigen::Matrix4d::Identity();
  a(0, 2) = a(1, 3) = 1;
  Eigen::Matrix<double, 2, 4> h = Eigen::Matrix<double, 2, 4>::Zero();
  h(0, 0) = h(1, 1) = 1;
  Eigen::Vector4d x(10, 20, 1, -2);
  Eigen::Matrix4d p = Eigen::Vector4d(1, 1, 100, 100).asDiagonal();
  const std::vector<Eigen::Vector2d> z = {{11.5, 17.0}, {12.0, 16.5}, {14.0, 13.0}, {15.5, 12.0}};
  for (const auto& m : z) {
    x = a * x;
    p = a * p * a.transpose() + 2.0 * Eigen::Matrix4d::Identity();
    const cv::Point2d pred = k.predict();
    EXPECT_NEAR(pred.x, x[0], 1e-9);
    EXPECT_NEAR(pred.y, x[1], 1e-9);
    const Eigen::Matrix2d s = h * p * h.transpose() + Eigen::Matrix2d::Identity();
    const Eigen::Vector2d innovation = m - h * x;
    EXPECT_NEAR(k.mahalanobis2({m.x(), m.y()}), innovation.dot(s.inverse() * innovation), 1e-9);
    const Eigen::Matrix<double, 4, 2> gain = p * h.transpose() * s.inverse();
    x += gain * innovation;
    p = (Eigen::Matrix4d::Identity() - gain * h) * p;
    const cv::Point2d post = k.correct({m.x(), m.y()});
    EXPECT_NEAR(post.x, x[0], 1e-9);
    EXPECT_NEAR(post.y, x[1], 1e-9);
    EXPECT_NEAR(k.velocity().x, x[2], 1e-9);
    EXPECT_NEAR(k.velocity().y, x[3], 1e-9);
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j < 4; ++j) EXPECT_NEAR(k.covariance().at<double>(i, j), p(i, j), 1e-9);
    }
  }
}

// A red, textured disc moving 4 px right and 2 px down per frame over a grey textured floor.
cv::Mat frame_with_disc(cv::Point2d centre, const cv::Mat& floor, const cv::Mat& skin) {
  cv::Mat img = floor.clone();
  cv::Mat disc(img.size(), CV_8UC1, cv::Scalar(0));
  cv::circle(disc, cv::Point(cvRound(centre.x), cvRound(centre.y)), 18, cv::Scalar(255), -1);
  // The disc's texture moves with it: shift the skin by the integer centre.
  const cv::Mat shift = (cv::Mat_<double>(2, 3) << 1, 0, std::round(centre.x) - 100, 0, 1,
                         std::round(centre.y) - 100);
  cv::Mat moved;
  cv::warpAffine(skin, moved, shift, img.size());
  moved.copyTo(img, disc);
  return img;
}

// A grey textured floor and a red skin texture, 320x240.
std::pair<cv::Mat, cv::Mat> textures(int seed) {
  cv::RNG rng(seed);
  cv::Mat floor(240, 320, CV_8UC3), skin(240, 320, CV_8UC3);
  rng.fill(floor, cv::RNG::UNIFORM, cv::Scalar(90, 90, 90), cv::Scalar(130, 130, 130));
  rng.fill(skin, cv::RNG::UNIFORM, cv::Scalar(10, 20, 150), cv::Scalar(50, 60, 230));
  cv::GaussianBlur(skin, skin, {5, 5}, 1.2);
  cv::GaussianBlur(floor, floor, {5, 5}, 1.2);
  return {floor, skin};
}

TEST(Cfof, FollowsAMovingTexturedPatchToUnderAPixel) {
  const auto [floor, skin] = textures(3);
  const CfofParams params;
  cv::Point2d truth(100, 100);
  CfofFrame previous = CfofFrame::from_bgr(frame_with_disc(truth, floor, skin), cv::Mat(), params);
  CfofTracker t(params);
  t.initialize(previous, cv::Rect2d(truth.x - 20, truth.y - 20, 40, 40));
  // The ROI is centred on CMDF's selection, a few pixels off the disc's centre; a restart
  // (Alg. 2 line 3) re-centres it. Each frame's step follows the disc's to under a pixel (by
  // the median), and the ROI never leaves the disc's middle.
  std::vector<double> step_error;
  cv::Point2d last = t.centre();
  for (int f = 1; f <= 20; ++f) {
    truth += cv::Point2d(4, 2);
    CfofFrame current = CfofFrame::from_bgr(frame_with_disc(truth, floor, skin), cv::Mat(), params);
    t.track(previous, current);
    EXPECT_EQ(t.state(), CfofState::tracking) << "frame " << f;
    const cv::Point2d err = t.centre() - truth;
    EXPECT_LT(std::hypot(err.x, err.y), 4.0) << "frame " << f;
    const cv::Point2d step = t.centre() - last - cv::Point2d(4, 2);
    step_error.push_back(std::hypot(step.x, step.y));
    last = t.centre();
    previous = std::move(current);
  }
  std::nth_element(step_error.begin(), step_error.begin() + 10, step_error.end());
  EXPECT_LT(step_error[10], 1.0);
}

// A part hidden while its body moves (CfofTracker::track's `carry`): carried with the body's
// motion it stays on the disc and resumes when it shows again; coasting on its decaying
// velocity alone (no carry) it falls behind and cannot find its colour again.
TEST(Cfof, HiddenPartCarriedWithTheBodyResumesOnIt) {
  const auto [floor, skin] = textures(5);
  const CfofParams params;
  const cv::Point2d step(4, 2);
  for (const bool carried : {true, false}) {
    cv::Point2d truth(60, 60);
    CfofFrame previous =
        CfofFrame::from_bgr(frame_with_disc(truth, floor, skin), cv::Mat(), params);
    CfofTracker t(params);
    t.initialize(previous, cv::Rect2d(truth.x - 20, truth.y - 20, 40, 40));
    for (int f = 1; f <= 30; ++f) {
      truth += step;
      CfofFrame current =
          CfofFrame::from_bgr(frame_with_disc(truth, floor, skin), cv::Mat(), params);
      const bool hidden = f > 5 && f <= 20;
      t.track(previous, current, hidden, carried ? step : cv::Point2d());
      if (hidden) {
        EXPECT_EQ(t.state(), CfofState::occluded) << "frame " << f;
      }
      previous = std::move(current);
    }
    const cv::Point2d err = t.centre() - truth;
    // On the disc (radius 18 px) or far off it.
    if (carried) {
      EXPECT_EQ(t.state(), CfofState::tracking);
      EXPECT_LT(std::hypot(err.x, err.y), 18.0);
    } else {
      EXPECT_GT(std::hypot(err.x, err.y), 40.0);
    }
  }
}

// A part whose first region holds none of the person's silhouette (another person's head, where
// the part labels of two actors met) learns no colours: it fails to start, then stays lost
// while the person moves through its region, without asking the colour model anything.
TEST(Cfof, APartThatNeverShowedItsColoursStaysLost) {
  const auto [floor, skin] = textures(7);
  const CfofParams params;
  cv::Point2d truth(100, 100);
  auto frame = [&](cv::Point2d centre) {
    const cv::Mat bgr = frame_with_disc(centre, floor, skin);
    cv::Mat mask(bgr.size(), CV_8UC1, cv::Scalar(0));
    cv::circle(mask, cv::Point(cvRound(centre.x), cvRound(centre.y)), 18, cv::Scalar(255), -1);
    return CfofFrame::from_bgr(bgr, mask, params);
  };
  CfofFrame previous = frame(truth);
  CfofTracker t(params);
  EXPECT_THROW(t.initialize(previous, cv::Rect2d(200, 150, 40, 40)), Error);
  EXPECT_EQ(t.state(), CfofState::lost);
  for (int f = 1; f <= 10; ++f) {
    truth += cv::Point2d(10, 5);
    CfofFrame current = frame(truth);
    EXPECT_NO_THROW(t.track(previous, current));
    EXPECT_EQ(t.state(), CfofState::lost) << "frame " << f;
    EXPECT_FALSE(t.restart(current, truth));
    previous = std::move(current);
  }
}

}  // namespace
}  // namespace simcap::tracker
