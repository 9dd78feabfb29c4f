// The render-and-compare pieces against independent computations: the capsule rasterizer against
// the analytic disc a sphere projects to, its face/crown split against ray-sphere normals, the
// region cost against hand-counted pixels, and the chamfer cost against a brute-force nearest-edge
// search, the feet and top priors against hand-computed offsets and the silhouette's rasterized
// extent.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>

#include "tracker/gomez/frame_cues.h"
#include "tracker/gomez/pose_scorer.h"

namespace simcap::tracker::gomez {
namespace {

Camera test_camera() {
  return Camera::look_at("cam", 320, 240, std::numbers::pi / 3, Eigen::Vector3d(0, 1, 3),
                         Eigen::Vector3d(0, 1, 0));
}

// One capsule carried by joint 0 (identity frame) from `a` to `b`.
BodyShape one_capsule(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double ra, double rb) {
  BodyShape s;
  Capsule c;
  c.a = a;
  c.b = b;
  c.ra = ra;
  c.rb = rb;
  s.capsules.push_back(c);
  return s;
}

const std::vector<Eigen::Isometry3d> kIdentity{Eigen::Isometry3d::Identity()};

TEST(LabelRenderer, ASphereCoversTheDiscItProjectsTo) {
  const Camera cam = test_camera();
  // A sphere of radius r at distance z on the optical axis covers a disc of radius ~ f r / z
  // (exactly f r / sqrt(z^2 - r^2), the cone's tangent; the renderer uses f r / z).
  const double r = 0.12, z = 3.0;
  const BodyShape shape = one_capsule(Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 1, 0), r, r);
  for (const int factor : {1, 2, 4}) {
    const View view{&cam, 0, 0, factor, cam.width / factor, cam.height / factor};
    LabelImage labels;
    render_labels(shape, kIdentity, view, labels);
    int drawn = 0;
    for (const std::uint8_t c : labels.cell) drawn += c != kNoCell;
    const double radius = cam.K(0, 0) * r / z / factor;
    const double area = std::numbers::pi * radius * radius;
    EXPECT_NEAR(drawn, area, 2 * std::numbers::pi * radius + 4) << "factor " << factor;
    // The pixel nearest the centre sees the sphere's front: z - r sqrt(1 - (d / radius)^2) at
    // its distance d from the centre.
    const Eigen::Vector2d centre = view.to_working(*cam.project(Eigen::Vector3d(0, 1, 0)));
    const Eigen::Vector2d pixel(std::round(centre.x()), std::round(centre.y()));
    const double d = (pixel - centre).norm() / radius;
    const size_t i = static_cast<size_t>(pixel.y()) * labels.width + static_cast<size_t>(pixel.x());
    EXPECT_NEAR(labels.depth[i], z - r * std::sqrt(1 - d * d), 1e-5);
  }
}

TEST(LabelRenderer, TheNearerCapsuleHidesTheFartherAndCellsRunAlongTheAxis) {
  const Camera cam = test_camera();
  BodyShape shape =
      one_capsule(Eigen::Vector3d(-0.3, 1, 0), Eigen::Vector3d(0.3, 1, 0), 0.05, 0.05);
  shape.capsules.push_back(shape.capsules[0]);
  shape.capsules[1].a = Eigen::Vector3d(0, 0.7, 0.5);
  shape.capsules[1].b = Eigen::Vector3d(0, 1.3, 0.5);
  const View view{&cam, 0, 0, 1, cam.width, cam.height};
  LabelImage labels;
  render_labels(shape, kIdentity, view, labels);
  const auto cell_at = [&](const Eigen::Vector3d& p) {
    const Eigen::Vector2d q = *cam.project(p);
    return labels.at(static_cast<int>(std::lround(q.x())), static_cast<int>(std::lround(q.y())));
  };
  // The crossing point belongs to the vertical capsule (0.5 m nearer the camera).
  EXPECT_EQ(cell_at(Eigen::Vector3d(0, 1, 0)) / kCellsPerCapsule, 1);
  // Along the horizontal capsule the cells count from a (x = -0.3) to b.
  EXPECT_EQ(cell_at(Eigen::Vector3d(-0.28, 1, 0)), 0);
  EXPECT_EQ(cell_at(Eigen::Vector3d(0.28, 1, 0)), kCellsPerCapsule - 1);
}

TEST(LabelRenderer, AHeadTurnedAwayShowsItsCrownsCell) {
  const Camera cam = test_camera();
  const Eigen::Vector3d centre(0, 1, 0);
  const double r = 0.12;
  for (const Eigen::Vector3d& front : {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0, 0, -1),
                                       Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(-0.6, 0, 0.8)}) {
    BodyShape shape = one_capsule(centre, centre, r, r);
    shape.capsules[0].front = front;
    const View view{&cam, 0, 0, 1, cam.width, cam.height};
    LabelImage labels;
    render_labels(shape, kIdentity, view, labels);
    // Each drawn pixel against the sphere point its sight line meets first (ray-sphere in the
    // world): it shows the crown's cell exactly when that point's normal faces away from the
    // face, away from the terminator where the renderer's approximate normal may differ.
    int checked = 0, back = 0;
    for (int v = labels.v0; v < labels.v1; ++v) {
      for (int u = labels.u0; u < labels.u1; ++u) {
        if (labels.at(u, v) == kNoCell) continue;
        const Eigen::Vector3d o = cam.centre(), d = cam.unproject(Eigen::Vector2d(u, v));
        const double b = d.dot(centre - o), disc = b * b - ((centre - o).squaredNorm() - r * r);
        if (disc < 0) continue;
        const Eigen::Vector3d normal = (o + (b - std::sqrt(disc)) * d - centre) / r;
        const double facing = normal.dot(front);
        if (std::abs(facing) < 0.2) continue;
        ++checked;
        back += facing < 0;
        EXPECT_EQ(labels.at(u, v), facing < 0 ? kCellsPerCapsule - 1 : 0)
            << "pixel " << u << "," << v << " facing " << facing;
      }
    }
    EXPECT_GT(checked, 250);
    // Facing the camera: no crown; turned away: all crown; sideways: about half.
    if (front.z() > 0.99) {
      EXPECT_EQ(back, 0);
    } else if (front.z() < -0.99) {
      EXPECT_EQ(back, checked);
    } else if (std::abs(front.x()) > 0.99) {
      EXPECT_NEAR(back, checked / 2.0, 0.1 * checked);
    }
  }
}

TEST(RegionModel, TellsFrontFromBackWhenTheCrownDiffersFromTheFace) {
  BodyShape shape = one_capsule(Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 1.2, 0), 0.1, 0.1);
  shape.capsules.push_back(shape.capsules[0]);
  std::vector<std::uint8_t> classes(2 * kCellsPerCapsule, 1);
  // No capsule has a face: nothing to tell by.
  classes[kCellsPerCapsule - 1] = 2;
  EXPECT_FALSE(tells_front_from_back(shape, classes));
  shape.capsules[0].front = Eigen::Vector3d::UnitZ();
  EXPECT_TRUE(tells_front_from_back(shape, classes));  // hair (2) above a face (1)
  classes[kCellsPerCapsule - 1] = 1;
  classes[kCellsPerCapsule + kCellsPerCapsule - 1] = 2;  // the other capsule's crown
  EXPECT_FALSE(tells_front_from_back(shape, classes));   // a bald head: skin all round
}

// A 6 x 4 working image with hand-made model cells and image classes.
struct SmallCase {
  LabelImage labels;
  FrameCues cues;
  RegionModel model;
};

SmallCase small_case() {
  SmallCase s;
  const int W = 6, H = 4;
  s.labels.width = W;
  s.labels.height = H;
  s.labels.cell.assign(W * H, kNoCell);
  s.labels.depth.assign(W * H, 1.0f);
  s.labels.u0 = 0;
  s.labels.u1 = W;
  s.labels.v0 = 0;
  s.labels.v1 = H;
  s.cues.view.width = W;
  s.cues.view.height = H;
  s.cues.cls.assign(W * H, 0);
  // Model: cell 0 (class 1) on columns 0-2 of rows 0-1; cell 1 (class 2) on columns 0-3 of row 3.
  for (int u = 0; u < 3; ++u) s.labels.cell[0 * W + u] = s.labels.cell[1 * W + u] = 0;
  for (int u = 0; u < 4; ++u) s.labels.cell[3 * W + u] = 1;
  // Image: class 1 on columns 1-4 of row 0; class 2 on columns 0-1 of row 3 and 2 of row 2.
  for (int u = 1; u < 5; ++u) s.cues.cls[0 * W + u] = 1;
  s.cues.cls[3 * W + 0] = s.cues.cls[3 * W + 1] = s.cues.cls[2 * W + 2] = 2;
  s.cues.class_area[1] = 4;
  s.cues.class_area[2] = 3;
  s.model.cell_class = {1, 2};
  s.model.head_cell = {0, 0};
  return s;
}

TEST(RegionCost, MatchesAHandCountedCase) {
  const SmallCase s = small_case();
  // Class 1: model 6 pixels, image 4, both 2 (row 0, columns 1-2): union 8, xor 6 -> 0.75.
  // Class 2: model 4, image 3, both 2 (row 3, columns 0-1): union 5, xor 3 -> 0.6.
  EXPECT_NEAR(region_cost(s.labels, s.model, s.cues, RegionCombine::mean), (0.75 + 0.6) / 2, 1e-12);
  EXPECT_NEAR(region_cost(s.labels, s.model, s.cues, RegionCombine::root_sum),
              (std::sqrt(0.75) + std::sqrt(0.6)) / 2, 1e-12);
  EXPECT_NEAR(region_cost(s.labels, s.model, s.cues, RegionCombine::pixels), 9.0 / 13.0, 1e-12);
}

TEST(RegionCost, SplitsTheHeadClassUnderTheModelsHead) {
  SmallCase s = small_case();
  // Cell 0 is the head's: class 1 under it (2 pixels of the image, 6 drawn) is compared apart
  // from class 1 elsewhere (2 image pixels, nothing drawn).
  s.model.head_cell = {1, 0};
  s.model.head_class = 1;
  // Head: union 6, xor 4; class 1 elsewhere: union 2, xor 2; class 2 as before: 0.6.
  EXPECT_NEAR(region_cost(s.labels, s.model, s.cues, RegionCombine::mean),
              (4.0 / 6.0 + 1.0 + 0.6) / 3, 1e-12);
}

TEST(ChamferCost, EqualsTheBruteForceNearestEdgeOverTheContour) {
  const Camera cam = test_camera();
  const BodyShape shape =
      one_capsule(Eigen::Vector3d(-0.25, 0.8, 0), Eigen::Vector3d(0.2, 1.2, 0), 0.06, 0.1);
  const View view{&cam, 0, 0, 2, cam.width / 2, cam.height / 2};
  LabelImage labels;
  render_labels(shape, kIdentity, view, labels);
  // Image edges: a few scattered pixels and a line.
  cv::Mat edges(view.height, view.width, CV_8UC1, cv::Scalar(0));
  cv::line(edges, {20, 30}, {130, 70}, cv::Scalar(255));
  for (const cv::Point p : {cv::Point(80, 20), cv::Point(60, 90), cv::Point(100, 50)}) {
    edges.at<std::uint8_t>(p) = 255;
  }
  cv::Mat distance;
  cv::distanceTransform(255 - edges, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  FrameCues cues;
  cues.view = view;
  cues.distance.assign(distance.begin<float>(), distance.end<float>());
  cues.far = static_cast<float>(view.width + view.height);

  std::vector<cv::Point> edge_pixels;
  cv::findNonZero(edges, edge_pixels);
  double sum = 0;
  int count = 0;
  for (int v = 0; v < labels.height; ++v) {
    for (int u = 0; u < labels.width; ++u) {
      if (labels.at(u, v) == kNoCell) continue;
      // Contour of a single capsule: a drawn pixel with an empty 4-neighbour.
      const bool contour = labels.at(u + 1, v) == kNoCell || labels.at(u - 1, v) == kNoCell ||
                           labels.at(u, v + 1) == kNoCell || labels.at(u, v - 1) == kNoCell;
      if (!contour) continue;
      double best = INFINITY;
      for (const cv::Point& e : edge_pixels) best = std::min(best, std::hypot(e.x - u, e.y - v));
      sum += best;
      ++count;
    }
  }
  ASSERT_GT(count, 50);
  EXPECT_NEAR(chamfer_cost(labels, cues, 0.04), sum / count, 1e-3);
}

TEST(BodyExtent, IsTheAnalyticDiscOfASphereAndTheRasterizedSilhouettesExtent) {
  const Camera cam = test_camera();
  const double r = 0.12, z = 3.0;
  const BodyShape sphere = one_capsule(Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 1, 0), r, r);
  const Eigen::Vector2d centre = *cam.project(Eigen::Vector3d(0, 1, 0));
  const double radius = cam.K(0, 0) * r / z;
  const Eigen::AlignedBox2d box = body_extent(sphere, kIdentity, cam);
  EXPECT_NEAR(box.min().x(), centre.x() - radius, 1e-9);
  EXPECT_NEAR(box.max().y(), centre.y() + radius, 1e-9);
  const cv::Rect rounded = body_box(sphere, kIdentity, cam);
  EXPECT_LE(rounded.y, box.min().y());
  EXPECT_GE(rounded.y + rounded.height, box.max().y());
  // A slanted, tapered capsule: its lowest and highest drawn rows at full resolution lie within
  // a pixel of the extent's.
  const BodyShape slanted =
      one_capsule(Eigen::Vector3d(-0.3, 0.5, 0.4), Eigen::Vector3d(0.2, 1.4, -0.3), 0.05, 0.11);
  const View view{&cam, 0, 0, 1, cam.width, cam.height};
  LabelImage labels;
  render_labels(slanted, kIdentity, view, labels);
  int top = cam.height, bottom = -1;
  for (int v = 0; v < labels.height; ++v) {
    for (int u = 0; u < labels.width; ++u) {
      if (labels.at(u, v) == kNoCell) continue;
      top = std::min(top, v);
      bottom = std::max(bottom, v);
    }
  }
  const Eigen::AlignedBox2d e = body_extent(slanted, kIdentity, cam);
  EXPECT_NEAR(bottom + 0.5, e.max().y(), 1.0);
  EXPECT_NEAR(top - 0.5, e.min().y(), 1.0);
}

TEST(FeetPrior, RowsComeFromTheSilhouetteUnlessItTouchesTheImagesBorder) {
  const Camera cam = test_camera();
  const ColourClasses classes = ColourClasses::uniform(1);
  cv::Mat image(cam.height, cam.width, CV_8UC3, cv::Scalar(90, 90, 90));
  cv::Mat mask(cam.height, cam.width, CV_8UC1, cv::Scalar(0));
  mask(cv::Rect(100, 40, 30, 150)).setTo(255);  // rows 40..189
  FrameCues cues = make_cues(cam, image, mask, classes, {}, {});
  EXPECT_DOUBLE_EQ(cues.feet_row, 189.5);
  EXPECT_DOUBLE_EQ(cues.top_row, 39.5);
  mask(cv::Rect(100, 0, 30, cam.height)).setTo(255);  // feet and head cut off
  cues = make_cues(cam, image, mask, classes, {}, {});
  EXPECT_TRUE(std::isnan(cues.feet_row));
  EXPECT_TRUE(std::isnan(cues.top_row));
  EXPECT_EQ(feet_offset(200.0, cues), 0.0);
  EXPECT_EQ(top_offset(10.0, cues), 0.0);
}

TEST(FeetPrior, OffsetsAndEnergyMatchAHandComputedCase) {
  FrameCues cues;
  cues.view.factor = 2;
  cues.feet_row = 200.5;
  cues.top_row = 50.5;
  // In working pixels (full-resolution rows / 2): 6 px below, 12 px above.
  EXPECT_DOUBLE_EQ(feet_offset(206.5, cues), 3.0);
  EXPECT_DOUBLE_EQ(top_offset(38.5, cues), -6.0);
  ScoreOptions o;
  o.sigma_region = 0.08;
  o.sigma_edge_px = 1.5;
  o.sigma_feet_px = 3.0;
  o.sigma_top_px = 3.0;
  const Energy e = energy({0.16, 3.0, 3.0, -6.0}, o);
  EXPECT_DOUBLE_EQ(e.region, 2.0);  // (0.16 / 0.08)^2 / 2
  EXPECT_DOUBLE_EQ(e.edge, 2.0);
  EXPECT_DOUBLE_EQ(e.feet, 0.5 * (1.0 + 4.0));
  EXPECT_DOUBLE_EQ(e.total(), 6.5);
  EXPECT_DOUBLE_EQ(e.terms().sum(), e.total());
  o.sigma_feet_px = o.sigma_top_px = 0;  // off
  EXPECT_DOUBLE_EQ(energy({0.16, 3.0, 3.0, -6.0}, o).feet, 0.0);
}

}  // namespace
}  // namespace simcap::tracker::gomez
