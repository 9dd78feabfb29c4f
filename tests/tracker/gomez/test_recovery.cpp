// The tracker on images of its own body: a pose rendered flat-shaded by colour class (skin, shirt,
// trousers) is recovered by the chapter-3 registration and by the particle filter when they
// start near it, so that what the dataset runs measure is the gap between the bodies and the
// search, not a bug in the costs.
#include <gtest/gtest.h>

#include <numbers>

#include "models/humanoid.h"
#include "tracker/gomez/monocular_tracker.h"
#include "tracker/gomez/root_depth.h"

namespace simcap::tracker::gomez {
namespace {

struct Rendered {
  cv::Mat image, silhouette;
};

// The body at `x` drawn at full resolution: the head and hands skin-coloured, the legs in
// trousers, the rest in a shirt, over a grey background.
Rendered draw(const Body& body, const State& x, const Camera& cam) {
  const View view{&cam, 0, 0, 1, cam.width, cam.height};
  LabelImage labels;
  render_labels(body.shape, forward_kinematics(body.skeleton, body.dofs.pose(x)), view, labels);
  Rendered r{cv::Mat(cam.height, cam.width, CV_8UC3, cv::Scalar(128, 128, 128)),
             cv::Mat(cam.height, cam.width, CV_8UC1, cv::Scalar(0))};
  for (int v = 0; v < cam.height; ++v) {
    for (int u = 0; u < cam.width; ++u) {
      const std::uint8_t cell = labels.at(u, v);
      if (cell == kNoCell) continue;
      const Capsule& c = body.shape.capsules[cell / kCellsPerCapsule];
      const std::string& joint = body.skeleton[c.joint].name;
      cv::Vec3b colour(160, 60, 40);  // shirt (BGR)
      if (c.part == Part::head || joint.ends_with("radiocarpal")) colour = cv::Vec3b(120, 150, 210);
      if (c.part == Part::left_leg || c.part == Part::right_leg || joint == "humanoid_root") {
        colour = cv::Vec3b(40, 40, 40);
      }
      r.image.at<cv::Vec3b>(v, u) = colour;
      r.silhouette.at<std::uint8_t>(v, u) = 255;
    }
  }
  return r;
}

// Mean distance between the elbows and wrists of two poses of `body`, metres.
double arm_error(const Body& body, const State& x, const State& y) {
  const auto a = joint_positions(body.skeleton, body.dofs.pose(x));
  const auto b = joint_positions(body.skeleton, body.dofs.pose(y));
  double sum = 0;
  for (const char* n : {"l_elbow", "r_elbow", "l_radiocarpal", "r_radiocarpal"}) {
    sum += (a[body.skeleton.require(n)] - b[body.skeleton.require(n)]).norm();
  }
  return sum / 4;
}

struct Setup {
  Skeleton skeleton = build_humanoid();
  Camera camera = Camera::look_at("cam", 480, 360, std::numbers::pi / 3,
                                  Eigen::Vector3d(0.4, 1.5, 3.2), Eigen::Vector3d(0, 1.0, 0));
  std::unique_ptr<Body> body =
      std::make_unique<Body>(skeleton, BodyKind::full, Pose::neutral(skeleton));
  State truth;
  Setup() {
    truth = body->dofs.clamp(State::Zero(body->dofs.size()));
    const auto set = [&](const char* name, double v) { truth[body->dofs.require(name)] = v; };
    set("l_shoulder_abduction", 1.0);
    set("l_elbow_flexion", -0.8);
    set("r_shoulder_flexion", -0.6);
    set("r_shoulder_abduction", -0.5);
    set("r_elbow_flexion", -1.2);
    truth = body->dofs.clamp(truth);
  }
  State perturbed() const {
    State x = truth;
    const auto add = [&](const char* name, double v) { x[body->dofs.require(name)] += v; };
    add("l_shoulder_abduction", -0.15);
    add("l_elbow_flexion", 0.2);
    add("r_shoulder_flexion", 0.15);
    add("r_elbow_flexion", -0.15);
    return body->dofs.clamp(x);
  }
};

// The tracker started at a perturbed pose on frame 1 of a still image, then run to frame 5.
struct StillRun {
  double before = 0, after = 0;  // elbow and wrist error, metres
  Score start, end;
};

StillRun run_from_perturbed(Search search) {
  Setup s;
  const Rendered r = draw(*s.body, s.truth, s.camera);
  MonocularSettings settings;
  settings.search = search;
  settings.smoothing = 0;
  // H2 diffuses only the parts the image shows moving: a still image moves none.
  settings.filter.h2_partitioned = false;
  settings.registration.evaluations = 1500;
  // The thesis's costs alone: the feet and top priors (tested below) change the 40-DOF simplex's
  // path on this still image (it ends at 3.9 cm instead of below 3).
  settings.score.sigma_top_px = 0;
  settings.score.sigma_feet_px = 0;
  const State start = s.perturbed();
  StillRun run;
  run.before = arm_error(*s.body, start, s.truth);
  MonocularTracker tracker(std::move(s.body), s.truth, s.camera, r.image, r.silhouette, settings);
  EXPECT_EQ(tracker.classes().count(), 3);
  tracker.track(r.image, r.silhouette, 0);
  TrackedFrame t = tracker.track(r.image, r.silhouette, 1, &start);
  run.start = t.start_score;
  for (int frame = 2; frame < 6; ++frame) t = tracker.track(r.image, r.silhouette, frame);
  run.after = arm_error(tracker.body(), t.estimate, s.truth);
  run.end = t.score;
  return run;
}

TEST(Recovery, TheSimplexRegistrationRecoversARenderedPose) {
  const StillRun run = run_from_perturbed(Search::simplex);
  ASSERT_GT(run.before, 0.05);
  EXPECT_LT(run.after, 0.03) << "from " << run.before;
  EXPECT_LT(run.end.region, 0.1);
}

// The filter's elitism: on a still image its best pose never explains the image worse than the
// pose it started from. (It does not reach the simplex's 3 cm here: its random children rarely
// improve all of the body's 40 DOFs at once, see GOMEZ.md.)
TEST(Recovery, TheParticleFilterNeverLosesItsStartOnAStillImage) {
  const StillRun run = run_from_perturbed(Search::particles);
  EXPECT_LE(run.end.region, run.start.region + 1e-9);
}

// H5 from the image: the left arm started hanging while the image shows it raised sideways. The
// hand's skin region lies far from where any child of the hanging arm reaches; the proposals
// that put the hand on that region's far end bring the arm back, which diffusion alone does not.
TEST(Recovery, HandProposalsBringBackALostArm) {
  const State truth = [] {
    const struct Setup s;
    return s.truth;
  }();
  const auto run = [&](int hand_depths) {
    struct Setup s;
    const Rendered r = draw(*s.body, s.truth, s.camera);
    MonocularSettings settings;
    settings.smoothing = 0;
    settings.filter.particles = 60;
    settings.filter.h2_partitioned = false;
    settings.filter.hand_depths = hand_depths;
    State start = s.truth;
    start[s.body->dofs.require("l_shoulder_abduction")] = 0;
    start[s.body->dofs.require("l_elbow_flexion")] = 0;
    start = s.body->dofs.clamp(start);
    MonocularTracker tracker(std::move(s.body), s.truth, s.camera, r.image, r.silhouette, settings);
    tracker.track(r.image, r.silhouette, 0);
    TrackedFrame t = tracker.track(r.image, r.silhouette, 1, &start);
    int proposals = t.filter.hand_proposals;
    for (int frame = 2; frame < 4; ++frame) {
      t = tracker.track(r.image, r.silhouette, frame);
      proposals += t.filter.hand_proposals;
    }
    const Body& body = tracker.body();
    const auto a = joint_positions(body.skeleton, body.dofs.pose(t.estimate));
    const auto b = joint_positions(body.skeleton, body.dofs.pose(truth));
    const int w = body.skeleton.require("l_radiocarpal");
    return std::make_pair((a[w] - b[w]).norm(), proposals);
  };
  const auto [without, none] = run(0);
  const auto [with, proposed] = run(4);
  EXPECT_EQ(none, 0);
  EXPECT_GT(proposed, 0);
  EXPECT_GT(without, 0.2);
  EXPECT_LT(with, 0.1) << "without proposals " << without;
}

// The feet prior on the body itself: at the drawn pose the body's lowest and highest extents
// meet the silhouette's; moved half a metre further from the camera along the floor, the body's
// feet rise in the image (the floor keeps them on it) and the prior's energy grows.
TEST(Recovery, TheFeetPriorPlacesTheBodyOnTheFloorAtItsDepth) {
  const struct Setup s;
  const Rendered r = draw(*s.body, s.truth, s.camera);
  const ColourClasses classes =
      learn_colours(*s.body, s.truth, s.camera, r.image, r.silhouette, {});
  ScoreOptions o;
  const PoseScorer scorer(s.body->dofs, s.body->shape, classes.cell_class(), o);
  const FrameCues cues = make_cues(s.camera, r.image, r.silhouette, classes, {}, {});
  ASSERT_TRUE(std::isfinite(cues.feet_row));
  const Score at = scorer.score(s.truth, cues);
  EXPECT_LT(std::abs(at.feet), 0.5);
  EXPECT_LT(std::abs(at.top), 0.5);
  State away = s.truth;
  away[s.body->dofs.require("root_tz")] -= 0.5;
  const Score moved = scorer.score(away, cues);
  EXPECT_LT(moved.feet, -2.0);
  EXPECT_GT(moved.top, 1.0);
  EXPECT_GT(energy(moved, o).feet, energy(at, o).feet + 0.5);
}

// The depth proposal: the body slid 0.6 m along the floor under its camera ray (its image column
// kept, its size and feet row changed) comes back to the drawn depth from the silhouette's feet
// and top rows, and from the top row alone when the feet are cut off; at the drawn depth there
// is nothing to propose.
TEST(RootDepth, SlidesTheBodyBackToTheSilhouettesFeetAndTopRows) {
  const struct Setup s;
  const BodyDofs& dofs = s.body->dofs;
  const Rendered r = draw(*s.body, s.truth, s.camera);
  const ColourClasses classes =
      learn_colours(*s.body, s.truth, s.camera, r.image, r.silhouette, {});
  FrameCues cues = make_cues(s.camera, r.image, r.silhouette, classes, {}, {});
  ASSERT_TRUE(std::isfinite(cues.feet_row) && std::isfinite(cues.top_row));
  EXPECT_FALSE(root_depth_proposal(dofs, s.body->shape, s.truth, cues));
  const int tx = dofs.require("root_tx"), tz = dofs.require("root_tz");
  const Eigen::Vector2d truth(s.truth[tx], s.truth[tz]);
  Eigen::Vector3d along = dofs.pose(s.truth).root_position - s.camera.centre();
  along.y() = 0;
  along.normalize();
  for (const double slide : {0.6, -0.6}) {
    State x = s.truth;
    x[tx] += slide * along.x();
    x[tz] += slide * along.z();
    for (const bool feet : {true, false}) {
      FrameCues c = cues;
      if (!feet) c.feet_row = NAN;
      // The head's row alone moves little with depth here (the camera is near its height).
      RootDepthOptions o;
      o.least_px = 1.0;
      const auto y = root_depth_proposal(dofs, s.body->shape, x, c, o);
      ASSERT_TRUE(y) << slide << " " << feet;
      EXPECT_LT((Eigen::Vector2d((*y)[tx], (*y)[tz]) - truth).norm(), feet ? 0.02 : 0.05)
          << slide << " " << feet;
    }
  }
  FrameCues none = cues;
  none.feet_row = none.top_row = NAN;
  State x = s.truth;
  x[tz] += 0.5;
  EXPECT_FALSE(root_depth_proposal(dofs, s.body->shape, x, none));
}

}  // namespace
}  // namespace simcap::tracker::gomez
