#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <tuple>
#include <vector>

#include "core/csv.h"
#include "core/error.h"
#include "core/image_io.h"
#include "tests/support/temp_dir.h"
#include "tests/tracker/capsule_dataset.h"
#include "tracker/common/background_model.h"
#include "tracker/common/dataset.h"
#include "tracker/common/silhouettes.h"

namespace simcap::tracker {
namespace {

namespace fs = std::filesystem;

cv::Mat plate(cv::RNG& rng, int rows, int cols) {
  cv::Mat p(rows, cols, CV_8UC3);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c)
      p.at<cv::Vec3b>(r, c) = cv::Vec3b(100 + (r + 2 * c) % 60, 140 - r % 30, 90 + c % 40);
  cv::Mat noise(rows, cols, CV_8UC3);
  rng.fill(noise, cv::RNG::NORMAL, 0, 2);
  return p + noise;
}

TEST(GaussianBackground, FindsTheForegroundAndIgnoresShadows) {
  cv::RNG rng(1);
  const int rows = 120, cols = 160;
  std::vector<cv::Mat> plates;
  for (int i = 0; i < 3; ++i) plates.push_back(plate(rng, rows, cols));
  const GaussianBackground model(plates);
  cv::Mat frame = plate(rng, rows, cols);
  cv::Mat truth(rows, cols, CV_8UC1, cv::Scalar(0));
  // A person-coloured block, and beside it a cast shadow: the background at 60% brightness.
  cv::rectangle(frame, cv::Rect(40, 20, 30, 70), cv::Scalar(40, 60, 170), cv::FILLED);
  cv::rectangle(truth, cv::Rect(40, 20, 30, 70), cv::Scalar(255), cv::FILLED);
  cv::Mat shadow = frame(cv::Rect(75, 60, 50, 30));
  shadow.convertTo(shadow, -1, 0.6);
  const cv::Mat fg = model.foreground(frame);
  EXPECT_GT(silhouette_iou(fg, truth), 0.97);

  BackgroundOptions no_shadows;
  no_shadows.suppress_shadows = false;
  const cv::Mat with_shadow = GaussianBackground(plates, no_shadows).foreground(frame);
  EXPECT_LT(silhouette_iou(with_shadow, truth), 0.7);  // the shadow is taken for the person
}

// One clean plate, then a frame from a noisier sensor (12 levels): the frame's own noise floors
// the variance, so the background stays background; with the plate's floor alone it does not.
TEST(GaussianBackground, MeasuresTheFramesOwnNoise) {
  cv::RNG rng(2);
  const int rows = 120, cols = 160;
  const std::vector<cv::Mat> plates = {plate(rng, rows, cols)};
  cv::Mat frame = plate(rng, rows, cols);
  cv::rectangle(frame, cv::Rect(40, 20, 30, 70), cv::Scalar(40, 60, 170), cv::FILLED);
  cv::Mat noise(rows, cols, CV_16SC3);
  rng.fill(noise, cv::RNG::NORMAL, 0, 12);
  cv::Mat noisy;
  frame.convertTo(noisy, CV_16SC3);
  noisy += noise;
  noisy.convertTo(noisy, CV_8UC3);
  cv::Mat truth(rows, cols, CV_8UC1, cv::Scalar(0));
  cv::rectangle(truth, cv::Rect(40, 20, 30, 70), cv::Scalar(255), cv::FILLED);
  const GaussianBackground model(plates);
  EXPECT_NEAR(model.frame_sigma(noisy), 12.0, 2.0);
  EXPECT_GT(silhouette_iou(model.foreground(noisy), truth), 0.9);
  BackgroundOptions plate_floor;
  plate_floor.frame_noise = false;
  EXPECT_LT(silhouette_iou(GaussianBackground(plates, plate_floor).foreground(noisy), truth), 0.5);
}

// The light changed after the plates: a third of the image darkened (a cloud), a third
// brightened past saturation in one channel (a lamp), the person across all three. The
// brightness factors are measured on the frame, the noise on what is left once each pixel is
// scaled, so the background stays background and the person is found; the plain test takes
// the brightened third for the person and, with the frame's noise measured on the plain
// difference, loses the person's darker half in it.
TEST(GaussianBackground, FollowsTheLightWhenItChanges) {
  cv::RNG rng(3);
  const int rows = 120, cols = 180;
  const std::vector<cv::Mat> plates = {plate(rng, rows, cols), plate(rng, rows, cols)};
  cv::Mat frame = plate(rng, rows, cols);
  cv::Mat cloud = frame(cv::Rect(0, 0, 60, rows)), lamp = frame(cv::Rect(120, 0, 60, rows));
  cloud.convertTo(cloud, -1, 0.55);
  lamp.convertTo(lamp, -1, 1.7);  // 100-160 in the first channel: saturated from 150
  cv::Mat truth(rows, cols, CV_8UC1, cv::Scalar(0));
  for (const cv::Rect& person : {cv::Rect(40, 20, 100, 25), cv::Rect(75, 45, 30, 60)}) {
    cv::rectangle(frame, person, cv::Scalar(40, 60, 170), cv::FILLED);
    cv::rectangle(truth, person, cv::Scalar(255), cv::FILLED);
  }
  const GaussianBackground model(plates);
  const FrameLight light = model.frame_light(frame);
  EXPECT_GT(light.highlight, 1.7 * 1.1);
  EXPECT_GT(silhouette_iou(model.foreground(frame), truth), 0.95);

  BackgroundOptions plain;
  plain.relight = false;
  EXPECT_LT(silhouette_iou(GaussianBackground(plates, plain).foreground(frame), truth), 0.6);

  // Darkened everywhere: the plain difference is the light's, not noise.
  cv::Mat dim = plate(rng, rows, cols);
  dim.convertTo(dim, -1, 0.55);
  cv::rectangle(dim, cv::Rect(75, 45, 30, 60), cv::Scalar(40, 60, 170), cv::FILLED);
  cv::Mat dim_truth(rows, cols, CV_8UC1, cv::Scalar(0));
  cv::rectangle(dim_truth, cv::Rect(75, 45, 30, 60), cv::Scalar(255), cv::FILLED);
  EXPECT_TRUE(model.frame_light(dim).relit);
  EXPECT_GT(silhouette_iou(model.foreground(dim), dim_truth), 0.95);
  EXPECT_LT(silhouette_iou(GaussianBackground(plates, plain).foreground(dim), dim_truth), 0.5);

  // The same light on a frame that did not change: nothing is relit, nothing highlighted.
  const FrameLight steady = model.frame_light(plate(rng, rows, cols));
  EXPECT_FALSE(steady.relit);
  EXPECT_EQ(steady.highlight, 0.0);
}

// A lamp blows out the brighter half of the room (every channel at 255): white is background
// where the brightest the background gets elsewhere would saturate it too; the person is not.
TEST(GaussianBackground, AWhiteBlownOutBackgroundIsBackground) {
  cv::RNG rng(4);
  const int rows = 100, cols = 160;
  cv::Mat room(rows, cols, CV_8UC3, cv::Scalar(100, 95, 90));
  room(cv::Rect(80, 0, 80, rows)).setTo(cv::Scalar(200, 190, 180));
  cv::Mat noise(rows, cols, CV_8UC3);
  rng.fill(noise, cv::RNG::NORMAL, 0, 2);
  const GaussianBackground model(std::vector<cv::Mat>{room + noise});
  cv::Mat frame;
  room.convertTo(frame, -1, 1.5);  // the darker half 150, 142, 135; the brighter one white
  cv::Mat truth(rows, cols, CV_8UC1, cv::Scalar(0));
  cv::rectangle(frame, cv::Rect(60, 20, 40, 60), cv::Scalar(40, 60, 170), cv::FILLED);
  cv::rectangle(truth, cv::Rect(60, 20, 40, 60), cv::Scalar(255), cv::FILLED);
  EXPECT_GT(silhouette_iou(model.foreground(frame), truth), 0.95);
}

TEST(GaussianBackground, RejectsMismatchedImages) {
  EXPECT_THROW(GaussianBackground(std::vector<cv::Mat>{}), Error);
  const cv::Mat p(10, 10, CV_8UC3, cv::Scalar(1, 2, 3));
  const GaussianBackground model(std::vector<cv::Mat>{p});
  EXPECT_THROW(model.foreground(cv::Mat(5, 5, CV_8UC3, cv::Scalar(0))), Error);
  EXPECT_THROW(GaussianBackground(std::vector<cv::Mat>{p, cv::Mat(10, 10, CV_8UC1, cv::Scalar(0))}),
               Error);
}

TEST(Silhouettes, IouAndMethodNames) {
  cv::Mat a(10, 10, CV_8UC1, cv::Scalar(0)), b(10, 10, CV_8UC1, cv::Scalar(0));
  EXPECT_DOUBLE_EQ(silhouette_iou(a, b), 1.0);
  a(cv::Rect(0, 0, 4, 5)).setTo(255);
  b(cv::Rect(2, 0, 4, 5)).setTo(7);
  EXPECT_DOUBLE_EQ(silhouette_iou(a, b), 10.0 / 30.0);
  for (const auto& [name, method] : kSilhouetteMethods)
    EXPECT_EQ(name_of(kSilhouetteMethods, method), name);
}

// The capsule dataset with the renderer's Gaussian sensor noise (scene noise.rgb_sigma) on its
// frames and noise-free plates, as `simcap render` writes them. Without noise every pixel is
// either the body or the exact plate, both subtractions return the true masks, and they agree
// by construction (studio4 renders do that); the noise is what tells the two models apart.
const fs::path& noisy_capsules() {
  static testing::TempDir dir;
  static const fs::path root = [] {
    const fs::path r = dir / "capsules";
    testing::write_capsule_dataset(r, {.frames = 3, .cameras = 4});
    const Dataset ds(r);
    cv::RNG rng(7);
    for (int f : ds.frames("rgb")) {
      for (int c = 0; c < ds.camera_count(); ++c) {
        const fs::path path = ds.image_path(c, "rgb", f);
        cv::Mat noise(ds.cameras()[c].height, ds.cameras()[c].width, CV_16SC3);
        rng.fill(noise, cv::RNG::NORMAL, 0, 3.0);
        cv::Mat noisy;
        cv::add(read_image(path), noise, noisy, cv::noArray(), CV_8UC3);
        write_image(path, noisy);
      }
    }
    return r;
  }();
  return root;
}

TEST(Silhouettes, Mog2AndTheGaussianModelDisagreeOnNoiseYetBothFindTheBody) {
  const Dataset ds(noisy_capsules());
  const SilhouetteExtractor gaussian(ds, SilhouetteMethod::bgsub);
  const SilhouetteExtractor mog2(ds, SilhouetteMethod::mog2);
  int differing = 0;
  for (int f : ds.frames("rgb")) {
    for (int c = 0; c < ds.camera_count(); ++c) {
      const cv::Mat truth = ds.mask(c, f);
      const cv::Mat a = gaussian.extract(c, f), b = mog2.extract(c, f);
      // Limbs are a few pixels wide at 240 x 180; the clean-up morphology costs some IoU there.
      EXPECT_GT(silhouette_iou(a, truth), 0.9) << "frame " << f << " camera " << c;
      EXPECT_GT(silhouette_iou(b, truth), 0.9) << "frame " << f << " camera " << c;
      differing += cv::countNonZero((a != 0) != (b != 0));
    }
  }
  // MOG2 learns its variance from the plate (down to OpenCV's floor of 4 levels^2); the
  // Gaussian model floors it at 16: MOG2 takes more of the noise for the person.
  EXPECT_GT(differing, 50);
}

// silhouette_iou.csv of `simcap track` as (frame, camera) -> IoU, in file order.
std::vector<std::tuple<long, long, double>> track_iou(const std::string& method) {
  testing::TempDir out;
  std::string log;
  EXPECT_EQ(
      testing::run_simcap("track " + noisy_capsules().string() + " -o " + (out / "t").string() +
                              " --init gt --quiet --silhouettes " + method,
                          &log),
      0)
      << log;
  CsvReader csv(out / "t" / "diagnostics" / "silhouette_iou.csv", {"frame", "camera", "iou"});
  std::vector<std::tuple<long, long, double>> rows;
  while (csv.next()) rows.emplace_back(csv.integer(0), csv.integer(1), csv.number(2));
  return rows;
}

TEST(Silhouettes, TrackScoresTheMasksOfTheMethodItWasGiven) {
  const Dataset ds(noisy_capsules());
  std::vector<std::vector<std::tuple<long, long, double>>> scores;
  for (const SilhouetteMethod method : {SilhouetteMethod::bgsub, SilhouetteMethod::mog2}) {
    const std::string name(name_of(kSilhouetteMethods, method));
    const SilhouetteExtractor extractor(ds, method);
    const auto& rows = scores.emplace_back(track_iou(name));
    ASSERT_EQ(rows.size(), 3u * 4u) << name;
    for (const auto& [frame, camera, iou] : rows) {
      const int c = static_cast<int>(camera), f = static_cast<int>(frame);
      EXPECT_NEAR(iou, silhouette_iou(extractor.extract(c, f), ds.mask(c, f)), 5e-5)
          << name << " frame " << frame << " camera " << camera;
    }
  }
  EXPECT_NE(scores[0], scores[1]);
}

TEST(Silhouettes, ColourInTheSilhouetteIsTheWholeImagesDownToItsLowestRow) {
  const Dataset ds(noisy_capsules());
  const SilhouetteExtractor extractor(ds, SilhouetteMethod::gt);
  int cropped = 0;  // cameras whose image goes on below the silhouette
  for (int c = 0; c < ds.camera_count(); ++c) {
    cv::Mat whole, top;
    const cv::Mat mask = extractor.extract(c, 1, &whole);
    ASSERT_TRUE(cv::countNonZero(mask) > 0) << c;
    EXPECT_EQ(cv::norm(extractor.extract(c, 1, &top, true), mask, cv::NORM_INF), 0) << c;
    int lowest = mask.rows - 1;
    while (cv::countNonZero(mask.row(lowest)) == 0) --lowest;
    EXPECT_EQ(cv::norm(top.rowRange(0, lowest + 1), whole.rowRange(0, lowest + 1), cv::NORM_INF), 0)
        << c;
    if (lowest + 1 < mask.rows) {
      ++cropped;
      EXPECT_EQ(cv::countNonZero(top.rowRange(lowest + 1, top.rows).reshape(1)), 0) << c;
      EXPECT_GT(cv::countNonZero(whole.rowRange(lowest + 1, whole.rows).reshape(1)), 0) << c;
    }
  }
  EXPECT_GT(cropped, 0);
}

}  // namespace
}  // namespace simcap::tracker
