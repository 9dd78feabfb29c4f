// `simcap track --method triangulate` end to end on a small rendered dataset (studio4, 4 cameras,
// 30 frames): the ground truth's COCO keypoints with 2 px of noise give the issue's MPJPE, a
// camera whose detections are all wrong, a second person and left/right swaps do not disturb it,
// and missing detections are refused before anything is written.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "models/detections.h"
#include "tests/support/rendered_dataset.h"
#include "tracker/common/dataset.h"

namespace simcap {
namespace {
namespace fs = std::filesystem;
using Json = nlohmann::json;
using testing::RenderedDataset;
using testing::run_simcap;

constexpr int kFrames = 30;

class TriangulateJob : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    data_ = new RenderedDataset(SIMCAP_SOURCE_DIR "/scenes/studio4.yaml",
                                "--frames " + std::to_string(kFrames));
    ASSERT_TRUE(data_->ok()) << data_->log();
  }
  static void TearDownTestSuite() {
    delete data_;
    data_ = nullptr;
  }
  static fs::path dataset() { return data_->path(); }
  static fs::path path(const std::string& name) { return data_->file(name); }

  // `simcap detections`: the true COCO-17 keypoints with Gaussian noise of `sigma_px`.
  static Detections truth(double sigma_px, unsigned seed) {
    const fs::path file =
        path("truth_" + std::to_string(sigma_px) + "_" + std::to_string(seed) + ".json");
    std::string log;
    EXPECT_EQ(
        run_simcap("detections " + dataset().string() + " -q -o " + file.string() + " --noise-px " +
                       std::to_string(sigma_px) + " --seed " + std::to_string(seed),
                   &log),
        0)
        << log;
    std::vector<std::string> cameras;
    const tracker::Dataset ds(dataset());
    for (const Camera& c : ds.cameras()) cameras.push_back(c.name);
    return read_detections(file, cameras, kFrames);
  }

  // Tracks `detections` with `options` and returns the MPJPE validate measures, mm.
  static double mpjpe(const Detections& detections, const std::string& name,
                      const std::string& options = "") {
    const fs::path file = path(name + ".json"), track = path(name), report = path(name + "_v");
    write_coco_results(detections, file);
    std::string log;
    EXPECT_EQ(
        run_simcap("track " + dataset().string() + " -o " + track.string() +
                       " --method triangulate -q --detections " + file.string() + " " + options,
                   &log),
        0)
        << log;
    EXPECT_EQ(run_simcap("validate " + dataset().string() + " " + track.string() + " -o " +
                             report.string() + " --no-media -q",
                         &log),
              0)
        << log;
    return Json::parse(read_text(report / "metrics.json"))["mpjpe_mm"].get<double>();
  }
  static RenderedDataset* data_;
};
RenderedDataset* TriangulateJob::data_ = nullptr;

TEST_F(TriangulateJob, TruthWithTwoPixelsOfNoiseGivesTheIssuesMpjpe) {
  EXPECT_LT(mpjpe(truth(0.0, 1), "exact"), 2.0);
  // Per frame the noise leaves ~16 mm (1 px ~ 1 cm at these cameras' 3-5 m); Pose2Sim's
  // zero-phase low-pass takes it under the issue's 10 mm.
  EXPECT_LE(mpjpe(truth(2.0, 1), "noisy", "--smooth butterworth"), 10.0);
}

TEST_F(TriangulateJob, AWrongCameraASecondPersonAndSwapsDoNotMatter) {
  const Detections clean = truth(2.0, 2);
  const double reference = mpjpe(clean, "clean");
  // Camera 2's detections all 70 px off: its views are excluded, as if it had seen nobody.
  Detections shifted = clean, without = clean;
  for (int f = 0; f < kFrames; ++f) {
    for (DetectedPerson& p : shifted.at(f, 2)) {
      for (DetectedKeypoint& k : p.keypoints) k.x += 60, k.y -= 35;
    }
    without.at(f, 2).clear();
  }
  EXPECT_NEAR(mpjpe(shifted, "shifted"), mpjpe(without, "without"), 0.5);
  // A second, larger person (the actor's detections moved and scaled) listed first in every
  // image, and the knees swapped in camera 1 on every other frame.
  Detections crowded = clean;
  for (int f = 0; f < kFrames; ++f) {
    for (int c = 0; c < 4; ++c) {
      auto& people = crowded.at(f, c);
      if (people.empty()) continue;
      DetectedPerson other = people[0];
      for (DetectedKeypoint& k : other.keypoints) k.x = 1.2 * k.x - 150, k.y = 1.2 * k.y - 40;
      people.insert(people.begin(), other);
      if (c == 1 && f % 2 == 0) std::swap(people[1].keypoints[13], people[1].keypoints[14]);
    }
  }
  EXPECT_LT(mpjpe(crowded, "crowded"), reference + 1.0);
  const std::string people = read_text(path("crowded") / "diagnostics" / "people.csv");
  EXPECT_NE(people.find("0,cam00,2,1,"), std::string::npos) << people;
  const std::string swaps = read_text(path("crowded") / "diagnostics" / "swaps.csv");
  EXPECT_NE(swaps.find("0,cam01,left_knee,right_knee"), std::string::npos) << swaps;
}

TEST_F(TriangulateJob, AWristOneCameraAloneSeesIsPlacedFromTheBodyAndScored) {
  // The right wrist (COCO 10) behind a pillar for three cameras of four through the whole take:
  // no pair of views, nothing to interpolate. The track still has every joint, and the guess is
  // scored like the rest.
  Detections hidden = truth(2.0, 3);
  for (int f = 0; f < kFrames; ++f) {
    for (int c = 1; c < 4; ++c) {
      for (DetectedPerson& p : hidden.at(f, c)) p.keypoints[10] = DetectedKeypoint{};
    }
  }
  const fs::path track = path("hidden_wrist"), report = path("hidden_wrist_v");
  write_coco_results(hidden, path("hidden_wrist.json"));
  std::string log;
  ASSERT_EQ(
      run_simcap("track " + dataset().string() + " -o " + track.string() +
                     " --method triangulate --detections " + path("hidden_wrist.json").string(),
                 &log),
      0)
      << log;
  EXPECT_NE(log.find("placed from the reference body: right_wrist"), std::string::npos) << log;
  ASSERT_EQ(run_simcap("validate " + dataset().string() + " " + track.string() + " -o " +
                           report.string() + " --no-media -q",
                       &log),
            0)
      << log;
  const Json m = Json::parse(read_text(report / "metrics.json"));
  EXPECT_LT(m["mpjpe_mm"].get<double>(), 60.0);
}

TEST_F(TriangulateJob, MissingDetectionsAreRefusedBeforeAnythingIsWritten) {
  std::string log;
  const fs::path track = path("refused");
  EXPECT_EQ(run_simcap("track " + dataset().string() + " -o " + track.string() +
                           " --method triangulate -q",
                       &log),
            1);
  EXPECT_NE(log.find("--detections"), std::string::npos) << log;
  EXPECT_EQ(run_simcap("track " + dataset().string() + " -o " + track.string() +
                           " --method triangulate -q --detections " + path("none.json").string(),
                       &log),
            1);
  EXPECT_NE(log.find("none.json"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(track));
}

}  // namespace
}  // namespace simcap
