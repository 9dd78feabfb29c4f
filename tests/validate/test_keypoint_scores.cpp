// 2D keypoint scoring: OKS and COCO AP against hand computations, every metric of a planted
// detection set with known errors, truth against itself, and `simcap validate --detections`.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "tests/support/occluders_dataset.h"
#include "tests/support/temp_dir.h"
#include "validate/keypoint_scores.h"
#include "validate/noisy_detections.h"

namespace simcap {
namespace {
namespace fs = std::filesystem;
using testing::run_simcap;
using testing::TempDir;

constexpr int kK = 17;

// COCO-17 truth of one actor: left points at x = 100, right ones at x = 140, the nose at 120,
// keypoint k at y = 50 + 10 k; all visible.
ActorView planted_view(double area = 10000) {
  ActorView v{true, area, 200.0, std::vector<TruthKeypoint>(kK)};
  for (int k = 0; k < kK; ++k) {
    const double x = k == 0 ? 120 : k % 2 == 1 ? 100 : 140;
    v.keypoints[k] = {true, {x, 50.0 + 10 * k}, VisibilityLabel::visible};
  }
  return v;
}

DetectedPerson exact(const ActorView& v, double score) {
  DetectedPerson p{std::vector<DetectedKeypoint>(kK), score};
  for (int k = 0; k < kK; ++k)
    p.keypoints[k] = {v.keypoints[k].pixel.x(), v.keypoints[k].pixel.y(), 1};
  return p;
}

TEST(KeypointAp, OksByHand) {
  const ActorView v = planted_view();
  DetectedPerson d = exact(v, 1);
  const KeypointLayout& coco = keypoint_layout(KeypointLayoutId::coco17);
  EXPECT_DOUBLE_EQ(*keypoint_oks(v, d, coco), 1.0);
  // left_hip (sigma 0.107) 10 px off, area 10000: e = 100 / (2 * 10000 * 0.214^2).
  d.keypoints[11].x += 6;
  d.keypoints[11].y += 8;
  EXPECT_NEAR(*keypoint_oks(v, d, coco), (16 + std::exp(-100.0 / (2 * 10000 * 0.214 * 0.214))) / 17,
              1e-12);
  // Only labelled keypoints count: with left_hip out of frame the others are exact.
  ActorView out = v;
  out.keypoints[11].visibility = VisibilityLabel::out_of_frame;
  EXPECT_DOUBLE_EQ(*keypoint_oks(out, d, coco), 1.0);
  for (auto& t : out.keypoints) t.visibility = VisibilityLabel::out_of_frame;
  EXPECT_FALSE(keypoint_oks(out, d, coco).has_value());
}

TEST(KeypointAp, AveragePrecisionByHand) {
  // Two images of one actor. Image 0: a (score 0.9) with five keypoints 1000 px off, so OKS =
  // 12/17 = 0.706 (the five terms underflow to 0). Image 1: b (0.8) exact, c (0.95) far off.
  KeypointTruth truth(KeypointLayoutId::coco17, {"cam00"}, {"a"}, 2);
  truth.at(0, 0, 0) = planted_view();
  truth.at(1, 0, 0) = planted_view();
  Detections det(KeypointLayoutId::coco17, {"cam00"}, 2);
  DetectedPerson a = exact(planted_view(), 0.9);
  for (const int k : {0, 3, 7, 11, 15}) a.keypoints[k].x += 1000;
  DetectedPerson c = exact(planted_view(), 0.95);
  for (auto& kp : c.keypoints) kp.x += 1000;
  det.at(0, 0).push_back(a);
  det.at(1, 0).push_back(exact(planted_view(), 0.8));
  det.at(1, 0).push_back(c);
  const CocoKeypointAp ap = coco_keypoint_ap(truth, det);
  // In score order c, a, b. OKS thresholds 0.50..0.70 (a matches): precision 0, 1/2, 2/3 at
  // recall 0, 1/2, 1, made non-increasing: 2/3 at every recall level. 0.75..0.95 (a does not):
  // precision 1/3 up to recall 1/2 (51 of the 101 levels), 0 above.
  for (int t = 0; t < 5; ++t) EXPECT_NEAR(ap.ap_at[t], 2.0 / 3, 1e-12) << t;
  for (int t = 5; t < 10; ++t) EXPECT_NEAR(ap.ap_at[t], 51.0 / 101 / 3, 1e-12) << t;
  EXPECT_NEAR(ap.ap, 0.5 * (2.0 / 3 + 51.0 / 303), 1e-12);
  EXPECT_NEAR(ap.ap50, 2.0 / 3, 1e-12);
  EXPECT_NEAR(ap.ap75, 51.0 / 303, 1e-12);
  EXPECT_NEAR(ap.ar, 0.75, 1e-12);
  EXPECT_EQ(ap.truths, 2);
  EXPECT_EQ(ap.detections, 3);
}

TEST(KeypointScores, PlantedErrorsGiveTheirScores) {
  // Actor a in two frames; b, another actor, elsewhere. Frame 0: a's detection (score 0.6) and a
  // decoy on b (0.9); frame 1: only the decoy, so a is unmatched and missed.
  KeypointTruth truth(KeypointLayoutId::coco17, {"cam00"}, {"a", "b"}, 2);
  ActorView a = planted_view();
  for (const int k : {5, 6}) a.keypoints[k].visibility = VisibilityLabel::self_occluded;
  for (const int k : {7, 8}) a.keypoints[k].visibility = VisibilityLabel::scene_occluded;
  a.keypoints[16].visibility = VisibilityLabel::out_of_frame;
  ActorView b = planted_view();
  for (auto& t : b.keypoints) t.pixel.x() += 400;
  for (int f = 0; f < 2; ++f) {
    truth.at(f, 0, 0) = a;
    truth.at(f, 0, 1) = b;
  }
  DetectedPerson d = exact(a, 0.6);
  const double dy[kK] = {0, 4, 6, 12, 30, 0, 8, 0, 3, 0, 0, 0, 0, 0, 0, 0, 0};
  for (int k = 0; k < kK; ++k) d.keypoints[k].y += dy[k];
  d.keypoints[7] = {0, 0, 0};                   // not detected
  std::swap(d.keypoints[13], d.keypoints[14]);  // knees swapped: 41.23 px each
  Detections det(KeypointLayoutId::coco17, {"cam00"}, 2);
  det.at(0, 0) = {exact(b, 0.9), d};
  det.at(1, 0) = {exact(b, 0.9)};
  const KeypointScores s = score_keypoints(truth, det, {0, 0.0});
  EXPECT_EQ(s.images, 2);
  EXPECT_EQ(s.several_people, 1);
  EXPECT_EQ(s.several_chosen_top, 0);  // a's detection is not the top-scored one
  EXPECT_EQ(s.one_person, 1);
  EXPECT_EQ(s.unmatched, 1);
  EXPECT_EQ(s.no_person, 0);
  // In frame: 16 keypoints x 2 frames, 15 detected (all of frame 0 but the left elbow).
  const double knee = std::hypot(40.0, 10.0);
  EXPECT_EQ(s.all.keypoints, 32);
  EXPECT_EQ(s.all.detected, 15);
  EXPECT_DOUBLE_EQ(s.all.miss_rate(), 17.0 / 32);
  EXPECT_DOUBLE_EQ(s.all.median_px(), 3);  // 0 x7, 3, 4, 6, 8, 12, 30, 41.2, 41.2
  EXPECT_NEAR(s.all.mean_px(), (3 + 4 + 6 + 8 + 12 + 30 + 2 * knee) / 15, 1e-12);
  // Torso = mean(|l_shoulder - r_hip|, |r_shoulder - l_hip|) = (|(40, 70)| + |(40, 50)|) / 2.
  const double torso = 0.5 * (std::hypot(40.0, 70.0) + std::hypot(40.0, 50.0));
  ASSERT_LT(6, 0.1 * torso);
  ASSERT_GT(8, 0.1 * torso);
  ASSERT_GT(30, 0.2 * torso);
  ASSERT_LT(30, 0.5 * torso);
  EXPECT_DOUBLE_EQ(s.all.pck_torso(0), 10.0 / 32);
  EXPECT_DOUBLE_EQ(s.all.pck_torso(1), 12.0 / 32);
  EXPECT_DOUBLE_EQ(s.all.pck_torso(2), 13.0 / 32);
  // Body height 200 px: 5, 10, 20 px.
  EXPECT_DOUBLE_EQ(s.all.pck_height(0), 9.0 / 32);
  EXPECT_DOUBLE_EQ(s.all.pck_height(1), 11.0 / 32);
  EXPECT_DOUBLE_EQ(s.all.pck_height(2), 12.0 / 32);
  // Pairs checked in frame 0: eyes, ears, shoulders, wrists, hips, knees (not the elbows: one
  // missed; not the ankles: one out of frame); the knees swapped.
  EXPECT_EQ(s.swap_pairs, 6);
  EXPECT_EQ(s.swapped_pairs, 1);
  EXPECT_DOUBLE_EQ(s.all.swap_rate(), 2.0 / 12);
  const auto& visible = s.by_visibility[static_cast<int>(VisibilityLabel::visible)];
  EXPECT_EQ(visible.keypoints, 24);
  EXPECT_DOUBLE_EQ(visible.miss_rate(), 0.5);
  EXPECT_DOUBLE_EQ(visible.median_px(), 2);  // 0 x6, 4, 6, 12, 30, 41.2, 41.2
  const auto& self = s.by_visibility[static_cast<int>(VisibilityLabel::self_occluded)];
  EXPECT_EQ(self.keypoints, 4);
  EXPECT_DOUBLE_EQ(self.median_px(), 4);
  EXPECT_EQ(self.pairs, 2);
  EXPECT_EQ(self.swapped, 0);
  const auto& scene = s.by_visibility[static_cast<int>(VisibilityLabel::scene_occluded)];
  EXPECT_DOUBLE_EQ(scene.miss_rate(), 0.75);
  EXPECT_DOUBLE_EQ(scene.median_px(), 3);
  const auto& out = s.by_visibility[static_cast<int>(VisibilityLabel::out_of_frame)];
  EXPECT_EQ(out.keypoints, 2);
  EXPECT_EQ(out.detected, 1);
  EXPECT_EQ(s.per_keypoint[13][0].swapped, 1);
  EXPECT_DOUBLE_EQ(s.per_keypoint[4][0].median_px(), 30);
  // Scored as b, the decoys are exact.
  const KeypointScores sb = score_keypoints(truth, det, {1, 0.0});
  EXPECT_EQ(sb.all.detected, 34);
  EXPECT_EQ(sb.all.median_px(), 0);
}

class KeypointScoresDataset : public ::testing::Test {
 protected:
  static fs::path dataset() { return testing::occluders_dataset(); }
};

TEST_F(KeypointScoresDataset, TruthAgainstItselfIsPerfect) {
  for (const auto& [name, id] : kKeypointLayouts) {
    SCOPED_TRACE(std::string(name));
    const KeypointTruth truth = read_keypoint_truth(dataset(), id);
    const KeypointScores s = score_keypoints(truth, detections_from_truth(truth, {0.0, 1}), {});
    EXPECT_EQ(s.all.miss_rate(), 0.0);
    EXPECT_EQ(s.all.median_px(), 0.0);
    EXPECT_EQ(s.all.pck_torso(0), 1.0);
    EXPECT_EQ(s.all.pck_height(0), 1.0);
    EXPECT_EQ(s.swapped_pairs, 0);
    EXPECT_GT(s.swap_pairs, 0);
    EXPECT_EQ(s.coco.ap, 1.0);
    EXPECT_EQ(s.coco.ar, 1.0);
    EXPECT_GT(s.by_visibility[static_cast<int>(VisibilityLabel::self_occluded)].keypoints, 0);
  }
}

TEST_F(KeypointScoresDataset, ValidateDetectionsWritesTheReport) {
  TempDir dir;
  ASSERT_EQ(
      run_simcap("detections " + dataset().string() + " -o " + (dir / "det.json").string() + " -q"),
      0);
  std::string out;
  ASSERT_EQ(run_simcap("validate " + dataset().string() + " --detections " +
                           (dir / "det.json").string() + " -o " + (dir / "r").string(),
                       &out),
            0)
      << out;
  const auto j = nlohmann::json::parse(read_text(dir / "r" / "keypoints2d.json"));
  EXPECT_EQ(j["schema"], "simcap-keypoints2d/1");
  EXPECT_EQ(j["layout"], "coco17");
  EXPECT_EQ(j["coco"]["ap"], 1.0);
  EXPECT_EQ(j["all"]["pck_torso_0.1"], 1.0);
  EXPECT_EQ(j["all"]["miss_rate"], 0.0);
  EXPECT_LE(j["all"]["median_px"].get<double>(), 1e-3);  // the file's pixels are rounded to 1e-3
  EXPECT_EQ(j["swapped_pairs"], 0);
  EXPECT_EQ(j["matching"]["images"], 16);
  EXPECT_EQ(j["per_keypoint"].size(), 17u);
  const std::string csv = read_text(dir / "r" / "keypoints2d.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "keypoint,visibility,keypoints,detected,miss_rate,median_px,mean_px,pck_torso_0.1,"
            "pck_torso_0.2,pck_torso_0.5,pck_height_0.025,pck_height_0.05,pck_height_0.1,"
            "swap_checked,swap_rate");
  const std::string html = read_text(dir / "r" / "report.html");
  EXPECT_NE(html.find("<svg"), std::string::npos);
  EXPECT_NE(html.find("self_occluded"), std::string::npos);
}

TEST_F(KeypointScoresDataset, BadDetectionsWriteNothing) {
  TempDir dir;
  write_text_atomic(dir / "det.json", "[{\"image_id\": 1, \"keypoints\": [1, 2, 3]}]");
  std::string out;
  EXPECT_NE(run_simcap("validate " + dataset().string() + " --detections " +
                           (dir / "det.json").string() + " -o " + (dir / "r").string(),
                       &out),
            0);
  EXPECT_NE(out.find((dir / "det.json").string() + ": [0].keypoints: 3 numbers"), std::string::npos)
      << out;
  EXPECT_FALSE(fs::exists(dir / "r"));
  // A user's mistake, not an internal error: status 1 and the message says which.
  EXPECT_EQ(run_simcap("validate " + dataset().string() + " -o " + (dir / "r").string(), &out), 1);
  EXPECT_NE(
      out.find("simcap: error: validate: give either TRACK or --detections FILE (got neither)"),
      std::string::npos)
      << out;
  EXPECT_EQ(
      run_simcap("validate " + dataset().string() + " " + (dir / "t").string() + " --detections " +
                     (dir / "det.json").string() + " -o " + (dir / "r").string(),
                 &out),
      1);
  EXPECT_NE(out.find("(got both)"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(dir / "r"));
}

}  // namespace
}  // namespace simcap
