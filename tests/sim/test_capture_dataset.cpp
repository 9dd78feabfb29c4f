// `simcap render` with the capture nuisances on: a perturbed calibration differs from the true
// one in gt/ by exactly the recorded perturbation while the images stay those of the true
// cameras; a camera out of sync by whole frame periods sees what a synchronised one sees those
// frames later; motion blur alone leaves depth, mask and parts as they are without it; and with
// offsets, a rolling shutter and motion blur together every table still agrees with the images
// and with OpenCV's projection at each row's capture time.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>

#include "core/atomic_file.h"
#include "core/image_io.h"
#include "tests/sim/dataset_checks.h"
#include "tests/support/file_tree.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {
namespace fs = std::filesystem;
using namespace simcap::testing;

cv::Mat centre(const CameraCalibration& c) {
  return -c.R.t() * c.t;
}

TEST(CaptureDataset, CalibrationErrorIsExactlyTheRecordedPerturbation) {
  TempDir dir;
  const std::string error =
      "--set 'rig.calibration_error={rotation_deg: 0.75, translation_m: 0.02, focal_rel: 0.01, "
      "principal_px: 3, seed: 5}'";
  ASSERT_EQ(render(scene_path("studio4"), dir / "wrong", error), 0);
  ASSERT_EQ(render(scene_path("studio4"), dir / "right"), 0);
  const fs::path wrong = dir / "wrong", right = dir / "right";
  check_consistency(wrong);

  const auto written = read_calibration(wrong / "calibration" / "opencv.yaml");
  const auto truth = read_calibration(wrong / "gt" / "calibration.yaml");
  const auto exact = read_calibration(right / "calibration" / "opencv.yaml");
  const auto meta = nlohmann::json::parse(read_text(wrong / "meta.json"));
  ASSERT_EQ(written.size(), 4u);
  for (const auto& [name, w] : written) {
    SCOPED_TRACE(name);
    const CameraCalibration& t = truth.at(name);
    // The truth is the calibration of the unperturbed render.
    EXPECT_LT(cv::norm(t.R, exact.at(name).R), 1e-12);
    EXPECT_LT(cv::norm(t.K, exact.at(name).K), 1e-9);
    const auto& p = meta.at("calibration_error").at("cameras").at(name);
    // Rotation: R_written R_true^T is the recorded rotation, by exactly rotation_deg.
    const cv::Mat dR = w.R * t.R.t();
    cv::Mat rvec;
    cv::Rodrigues(dR, rvec);
    EXPECT_NEAR(cv::norm(rvec) * 180 / CV_PI, 0.75, 1e-9);
    const auto axis = p.at("rotation_axis_camera");
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(rvec.at<double>(k) / cv::norm(rvec), axis[k].get<double>(), 1e-7);
    }
    // Centre moved by exactly translation_m along the recorded shift.
    const cv::Mat shift = centre(w) - centre(t);
    EXPECT_NEAR(cv::norm(shift), 0.02, 1e-9);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(shift.at<double>(k), p.at("centre_shift_m")[k].get<double>(), 1e-9);
    }
    const double scale = w.K.at<double>(0, 0) / t.K.at<double>(0, 0);
    EXPECT_NEAR(std::abs(scale - 1), 0.01, 1e-12);
    EXPECT_NEAR(w.K.at<double>(1, 1) / t.K.at<double>(1, 1), scale, 1e-12);
    const double du = w.K.at<double>(0, 2) - t.K.at<double>(0, 2);
    const double dv = w.K.at<double>(1, 2) - t.K.at<double>(1, 2);
    EXPECT_NEAR(std::hypot(du, dv), 3, 1e-9);
    EXPECT_NEAR(du, p.at("principal_shift_px")[0].get<double>(), 1e-9);
  }
  // The images and tables are those of the true cameras.
  auto a = read_tree(wrong), b = read_tree(right);
  for (const auto& [file, content] : b) {
    if (file.starts_with("cam") || file.starts_with("background") || file.starts_with("gt/")) {
      EXPECT_TRUE(a.count(file) && a.at(file) == content) << file;
    }
  }
  EXPECT_NE(a.at("calibration/opencv.yaml"), b.at("calibration/opencv.yaml"));
  EXPECT_NE(a.at("calibration/calibration.toml"), b.at("calibration/calibration.toml"));
  // Off, the nuisances leave no trace.
  EXPECT_EQ(b.count("gt/calibration.yaml"), 0u);
  const auto plain = nlohmann::json::parse(b.at("meta.json"));
  EXPECT_FALSE(plain.contains("capture"));
  EXPECT_FALSE(plain.contains("calibration_error"));
  EXPECT_FALSE(plain.contains("auto_exposure"));
}

// Rows of joints2d.csv by (frame, camera, joint).
std::map<std::tuple<int, std::string, std::string>, Joint2d> by_key(const fs::path& d) {
  std::map<std::tuple<int, std::string, std::string>, Joint2d> out;
  for (const Joint2d& r : read_joints2d(d / "gt" / "joints2d.csv")) {
    out[{r.frame, r.camera, r.joint}] = r;
  }
  return out;
}

TEST(CaptureDataset, OffsetsOfWholeFramesShowLaterFrames) {
  TempDir dir;
  // At 25 frames/s a frame period is 40 ms.
  ASSERT_EQ(render(scene_path("studio4"), dir / "sync", "--set render.fps=25"), 0);
  ASSERT_EQ(render(scene_path("studio4"), dir / "off",
                   "--set render.fps=25 --set 'rig.sync={offset_ms: [0, 40, 80, 0]}'"),
            0);
  check_consistency(dir / "off");
  const auto meta = nlohmann::json::parse(read_text(dir / "off" / "meta.json"));
  EXPECT_EQ(meta.at("capture").at("offset_ms").at("cam02").get<double>(), 80);
  const auto sync = by_key(dir / "sync"), off = by_key(dir / "off");
  int compared = 0;
  for (const auto& [key, r] : off) {
    const auto& [frame, camera, joint] = key;
    const int ahead = camera == "cam01" ? 1 : camera == "cam02" ? 2 : 0;
    if (frame + ahead >= kFrames) continue;
    const Joint2d& s = sync.at({frame + ahead, camera, joint});
    if (std::isnan(s.u)) continue;
    EXPECT_NEAR(r.u, s.u, 1e-6) << frame << " " << camera << " " << joint;
    EXPECT_NEAR(r.v, s.v, 1e-6) << frame << " " << camera << " " << joint;
    EXPECT_NEAR(r.depth, s.depth, 1e-6);
    ++compared;
  }
  EXPECT_GT(compared, 100);
  // The mask of the camera 40 ms late at frame 0 is the synchronised mask of frame 1 (up to
  // rounding in the interpolated pose), not of frame 0.
  const cv::Mat late = read_image(image_file(dir / "off", "cam01", "mask", 0));
  const cv::Mat next = read_image(image_file(dir / "sync", "cam01", "mask", 1));
  const cv::Mat now = read_image(image_file(dir / "sync", "cam01", "mask", 0));
  EXPECT_LE(cv::countNonZero(late != next), 5);
  EXPECT_GT(cv::countNonZero(late != now), 50);
  // A camera without offset is unchanged.
  EXPECT_EQ(read_text(image_file(dir / "off", "cam00", "rgb", 2)),
            read_text(image_file(dir / "sync", "cam00", "rgb", 2)));
}

// Without a rolling shutter the labels' rays meet the bodies at the exposure's middle time
// step: blur changes the colour and nothing else, at a short shutter as at a full one.
TEST(CaptureDataset, MotionBlurChangesTheColourOnly) {
  TempDir dir;
  const std::string samples = "--set render.samples_per_pixel=2";
  ASSERT_EQ(render(scene_path("studio4"), dir / "sharp", samples), 0);
  for (const std::string shutter : {"0.25", "1"}) {
    SCOPED_TRACE(shutter);
    const fs::path blurred = dir / ("shutter" + shutter);
    ASSERT_EQ(render(scene_path("studio4"), blurred, samples + " --set render.shutter=" + shutter),
              0);
    int colour_changed = 0;
    for (const std::string cam : {"cam00", "cam01", "cam02", "cam03"}) {
      for (int frame = 0; frame < kFrames; ++frame) {
        for (const std::string kind : {"depth", "mask", "parts"}) {
          EXPECT_EQ(read_text(image_file(dir / "sharp", cam, kind, frame)),
                    read_text(image_file(blurred, cam, kind, frame)))
              << cam << " " << kind << " " << frame;
        }
        colour_changed += read_text(image_file(dir / "sharp", cam, "rgb", frame)) !=
                          read_text(image_file(blurred, cam, "rgb", frame));
      }
    }
    EXPECT_GT(colour_changed, 0);
  }
}

TEST(CaptureDataset, OffsetsRollingShutterAndBlurKeepTheTruthExact) {
  TempDir dir;
  ASSERT_EQ(render(scene_path("studio4"), dir / "d",
                   "--set 'rig.sync={offset_ms_sigma: 15, seed: 2}' --set rig.readout_ms=25 "
                   "--set render.shutter=0.5 --set render.samples_per_pixel=4"),
            0);
  check_consistency(dir / "d");
  const auto meta = nlohmann::json::parse(read_text(dir / "d" / "meta.json"));
  const auto& capture = meta.at("capture");
  EXPECT_EQ(capture.at("readout_ms").get<double>(), 25);
  EXPECT_NEAR(capture.at("exposure_ms").get<double>(), 0.5 * 1000 / 30, 1e-9);
  int differing = 0;
  for (const auto& [name, ms] : capture.at("offset_ms").items()) {
    differing += ms.get<double>() != 0;
  }
  EXPECT_EQ(differing, 4);
}

}  // namespace
}  // namespace simcap
