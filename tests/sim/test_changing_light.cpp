// `simcap render` under changing light: a light's keyed intensity scales each room pixel's
// direct light exactly as the keyframes interpolate, and automatic exposure brings every image
// back to its camera's plate brightness.
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/core.hpp>

#include "core/image_io.h"
#include "sim/srgb.h"
#include "tests/sim/dataset_checks.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {
namespace fs = std::filesystem;
using namespace simcap::testing;

// At 30 frames/s frames 0..3 are at 0, 1/30, 2/30 and 3/30 s: intensity 0.8, 0.6, 0.4, 0.2.
const std::string kDimming =
    "--set 'lights[0].keyframes=[{time: 0, intensity: "
    "0.8}, "
    "{time: 0.1, intensity: 0.2}]'";

cv::Mat linear(const cv::Mat& rgb) {
  cv::Mat out(rgb.size(), CV_32FC3);
  for (int y = 0; y < rgb.rows; ++y) {
    for (int x = 0; x < rgb.cols; ++x) {
      const cv::Vec3b c = rgb.at<cv::Vec3b>(y, x);
      out.at<cv::Vec3f>(y, x) = {srgb_to_linear(c[0] / 255.f), srgb_to_linear(c[1] / 255.f),
                                 srgb_to_linear(c[2] / 255.f)};
    }
  }
  return out;
}

double mean_luma(const cv::Mat& lin) {
  const cv::Scalar m = cv::mean(lin);
  return 0.2126 * m[0] + 0.7152 * m[1] + 0.0722 * m[2];
}

TEST(ChangingLight, KeyedIntensityScalesTheDirectLightLinearly) {
  TempDir dir;
  ASSERT_EQ(render(scene_path("studio4"), dir / "d", kDimming), 0);
  for (const char* cam : {"cam00", "cam02"}) {
    SCOPED_TRACE(cam);
    std::vector<cv::Mat> l;
    for (int f = 0; f < 4; ++f)
      l.push_back(linear(read_image(image_file(dir / "d", cam, "rgb", f))));
    // Every pixel is ambient + intensity * direct: linear in the intensity, so frame 1 lies a
    // third and frame 2 two thirds of the way from frame 0 to frame 3.
    const cv::Mat step = (l[3] - l[0]) / 3.0;
    cv::Mat actor = cv::Mat::zeros(l[0].size(), CV_8UC1);
    for (int f = 0; f < 4; ++f) actor |= read_image(image_file(dir / "d", cam, "mask", f));
    const cv::Mat err1 = cv::abs(l[1] - (l[0] + step)), err2 = cv::abs(l[2] - (l[0] + 2 * step));
    // 8-bit quantisation of the two ends and the middle: a few thousandths in linear light.
    // Only the actor's moving shadow may break linearity, on a few pixels.
    int room = 0, off = 0;
    for (int y = 0; y < actor.rows; ++y) {
      for (int x = 0; x < actor.cols; ++x) {
        if (actor.at<std::uint8_t>(y, x)) continue;
        ++room;
        for (const cv::Mat* e : {&err1, &err2}) {
          const cv::Vec3f v = e->at<cv::Vec3f>(y, x);
          off += std::max({v[0], v[1], v[2]}) > 0.006f;
        }
      }
    }
    EXPECT_GT(room, kWidth * kHeight / 2);
    EXPECT_LT(off, room / 200);
    // And the light really dims: the lit floor loses three quarters of its direct light.
    EXPECT_LT(mean_luma(l[3]), 0.8 * mean_luma(l[0]));
  }
}

TEST(ChangingLight, AutoExposureKeepsEachCameraAtItsPlateBrightness) {
  TempDir dir;
  ASSERT_EQ(render(scene_path("studio4"), dir / "d", kDimming + " --set rig.auto_exposure=true"),
            0);
  for (const char* cam : {"cam00", "cam01", "cam02", "cam03"}) {
    SCOPED_TRACE(cam);
    const double plate =
        mean_luma(linear(read_image(dir / "d" / "background" / (std::string(cam) + ".png"))));
    // Frame 0 as bright as the plate; the later frames, dimmer by up to 3/4, too.
    for (int f = 0; f < 4; ++f) {
      const double m = mean_luma(linear(read_image(image_file(dir / "d", cam, "rgb", f))));
      EXPECT_NEAR(m / plate, 1.0, 0.01) << "frame " << f;
    }
  }
}

}  // namespace
}  // namespace simcap
