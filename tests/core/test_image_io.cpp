// Image files through OpenImageIO: exact round trips, atomic writes, clear errors.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/image_io.h"
#include "tests/support/huge_png.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {

using simcap::testing::TempDir;

TEST(ImageIO, PngRoundTripsRgbMaskAndLabels) {
  TempDir dir;
  cv::Mat rgb(48, 64, CV_8UC3), mask(48, 64, CV_8UC1), labels(48, 64, CV_16UC1);
  cv::randu(rgb, 0, 256);
  cv::randu(mask, 0, 256);
  cv::randu(labels, 0, 65535);
  for (const auto& [name, img] :
       {std::pair{"rgb.png", rgb}, {"mask.png", mask}, {"l.png", labels}}) {
    write_image(dir / name, img);
    const cv::Mat back = read_image(dir / name);
    ASSERT_EQ(back.type(), img.type()) << name;
    EXPECT_EQ(cv::norm(back, img, cv::NORM_INF), 0.0) << name;
  }
}

TEST(ImageIO, ExrKeepsFloatDepthExactly) {
  TempDir dir;
  cv::Mat depth(30, 40, CV_32FC1);
  cv::randu(depth, 0.5f, 8.0f);
  depth.at<float>(3, 4) = std::numeric_limits<float>::infinity();
  write_image(dir / "d.exr", depth);
  cv::Mat back = read_image(dir / "d.exr");
  ASSERT_EQ(back.type(), CV_32FC1);
  EXPECT_TRUE(std::isinf(back.at<float>(3, 4)));
  back.at<float>(3, 4) = depth.at<float>(3, 4) = 0;
  EXPECT_EQ(cv::norm(back, depth, cv::NORM_INF), 0.0);
}

TEST(ImageIO, WritesAreAtomicAndLeaveNoTemporaries) {
  TempDir dir;
  write_image(dir / "sub" / "a.png", cv::Mat(4, 4, CV_8UC1, cv::Scalar(9)));
  int files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir / "sub")) ++files;
  EXPECT_EQ(files, 1);
}

TEST(ImageIO, ErrorsNameTheFile) {
  TempDir dir;
  try {
    read_image(dir / "missing.png");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("missing.png"), std::string::npos);
  }
  write_text_atomic(dir / "junk.png", "not a png at all");
  EXPECT_THROW(read_image(dir / "junk.png"), Error);
  EXPECT_THROW(write_image(dir / "f.png", cv::Mat(4, 4, CV_32FC1)), Error);
  EXPECT_THROW(write_image(dir / "f.exr", cv::Mat(4, 4, CV_8UC1)), Error);
  EXPECT_FALSE(std::filesystem::exists(dir / "f.png"));
}

TEST(ImageIO, RefusesAHeaderClaimingTooManyPixelsBeforeAllocating) {
  TempDir dir;
  write_text_atomic(dir / "huge.png", simcap::testing::kHugeHeaderPng);
  try {
    read_image(dir / "huge.png");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("huge.png: the image is 65536x32768 pixels, more than the "
                                         "67108864 (8192x8192) simcap allows an image"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace simcap
