// Ground truth as a detector's output (`simcap detections`): without noise every keypoint sits
// on its true pixel in gt/keypoints_coco.json and gt/joints2d.csv; with noise the offsets have the
// asked spread; the same seed gives the same file; a broken dataset is named.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "models/detections.h"
#include "tests/support/error_of.h"
#include "tests/support/occluders_dataset.h"
#include "tests/support/temp_dir.h"
#include "validate/noisy_detections.h"

namespace simcap {
namespace {
namespace fs = std::filesystem;
using testing::run_simcap;
using testing::TempDir;

class NoisyDetections : public ::testing::Test {
 protected:
  static fs::path dataset() { return testing::occluders_dataset(); }
};

TEST_F(NoisyDetections, WithoutNoiseTheTruth) {
  const KeypointTruth truth = read_keypoint_truth(dataset(), KeypointLayoutId::coco17);
  const Detections d = detections_from_truth(truth, {0.0, 1});
  const auto coco = nlohmann::json::parse(read_text(dataset() / "gt" / "keypoints_coco.json"));
  ASSERT_EQ(d.frames(), 4);
  ASSERT_EQ(d.people(), static_cast<int>(coco["annotations"].size()));
  int occluded = 0;
  for (const auto& ann : coco["annotations"]) {
    const int id = ann["image_id"].get<int>() - 1;
    const auto& people = d.at(id / 4, id % 4);
    ASSERT_EQ(people.size(), 1u);
    for (int k = 0; k < 17; ++k) {
      const int v = ann["keypoints"][3 * k + 2];
      const DetectedKeypoint& p = people[0].keypoints[k];
      EXPECT_EQ(p.score, v > 0 ? 1.0 : 0.0);
      if (v == 0) continue;
      EXPECT_NEAR(p.x, ann["keypoints"][3 * k].get<double>(), 1e-3);
      EXPECT_NEAR(p.y, ann["keypoints"][3 * k + 1].get<double>(), 1e-3);
      const VisibilityLabel label = truth.at(id / 4, id % 4, 0).keypoints[k].visibility;
      EXPECT_EQ(visibility_label_name(label), ann["visibility"][k].get<std::string>());
      occluded += v == 1;
    }
  }
  EXPECT_GT(occluded, 0);  // occluded keypoints are detected too, as a learned detector does
}

TEST_F(NoisyDetections, Human36mPointsAreProjected) {
  const KeypointTruth truth = read_keypoint_truth(dataset(), KeypointLayoutId::h36m17);
  const KeypointTruth coco = read_keypoint_truth(dataset(), KeypointLayoutId::coco17);
  const ActorView& h = truth.at(1, 2, 0);
  const ActorView& c = coco.at(1, 2, 0);
  // RHip is the H-Anim joint of COCO's right_hip; Hip (their 3D midpoint, projected) lies
  // near the midpoint of the two hip pixels (perspective moves it a little).
  EXPECT_EQ(h.keypoints[1].pixel, c.keypoints[12].pixel);
  EXPECT_LT((h.keypoints[0].pixel - 0.5 * (c.keypoints[11].pixel + c.keypoints[12].pixel)).norm(),
            0.5);
  EXPECT_EQ(h.keypoints[0].visibility, VisibilityLabel::missing);
  EXPECT_EQ(h.keypoints[1].visibility, c.keypoints[12].visibility);
}

TEST_F(NoisyDetections, NoiseHasTheAskedSpreadAndFollowsTheSeed) {
  const KeypointTruth truth = read_keypoint_truth(dataset(), KeypointLayoutId::blazepose33);
  const Detections d = detections_from_truth(truth, {2.0, 7});
  double sum = 0, sum2 = 0;
  int n = 0;
  for (int f = 0; f < 4; ++f) {
    for (int c = 0; c < 4; ++c) {
      for (const DetectedPerson& p : d.at(f, c)) {
        for (size_t k = 0; k < p.keypoints.size(); ++k) {
          if (p.keypoints[k].score == 0) continue;
          const Eigen::Vector2d e = Eigen::Vector2d(p.keypoints[k].x, p.keypoints[k].y) -
                                    truth.at(f, c, 0).keypoints[k].pixel;
          sum += e.x() + e.y();
          sum2 += e.squaredNorm();
          n += 2;
        }
      }
    }
  }
  ASSERT_GT(n, 500);
  EXPECT_NEAR(sum / n, 0.0, 0.25);
  EXPECT_NEAR(std::sqrt(sum2 / n), 2.0, 0.2);
  TempDir dir;
  ASSERT_EQ(run_simcap("detections " + dataset().string() + " -o " + (dir / "a.json").string() +
                       " --noise-px 2 --seed 7 --layout blazepose33 -q"),
            0);
  ASSERT_EQ(run_simcap("detections " + dataset().string() + " -o " + (dir / "b.json").string() +
                       " --noise-px 2 --seed 7 --layout blazepose33 -q"),
            0);
  ASSERT_EQ(run_simcap("detections " + dataset().string() + " -o " + (dir / "c.json").string() +
                       " --noise-px 2 --seed 8 --layout blazepose33 -q"),
            0);
  EXPECT_EQ(read_text(dir / "a.json"), read_text(dir / "b.json"));
  EXPECT_NE(read_text(dir / "a.json"), read_text(dir / "c.json"));
  const Detections back = read_detections(dir / "a.json", truth.cameras(), 4);
  EXPECT_EQ(back.layout(), KeypointLayoutId::blazepose33);
  EXPECT_NEAR(back.at(2, 1)[0].keypoints[11].x, d.at(2, 1)[0].keypoints[11].x, 5e-4);
}

TEST(NoisyDetectionsErrors, BrokenDatasetIsNamed) {
  TempDir dir;
  std::string out;
  EXPECT_NE(
      run_simcap("detections " + dir.path().string() + " -o " + (dir / "d.json").string(), &out),
      0);
  EXPECT_NE(out.find((dir / "calibration" / "opencv.yaml").string()), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(dir / "d.json"));
}

}  // namespace
}  // namespace simcap
