// Image files through OpenImageIO: exact round trips, atomic writes, clear errors.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/image_claims.h"
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

// Damaged files are refused from what their structure claims, before a decoder allocates for it;
// good files pass. cv::imencode writes the PNGs (an independent encoder).
TEST(ImageIO, DamagedPngAndExrHeadersAreRefusedBeforeDecoding) {
  TempDir dir;
  std::vector<unsigned char> encoded;
  cv::imencode(".png", cv::Mat(48, 64, CV_8UC3, cv::Scalar(1, 2, 3)), encoded);
  const std::string png(encoded.begin(), encoded.end());
  EXPECT_EQ(png_claims(png).damage, "");
  EXPECT_EQ(png_claims(png).width, 64);
  EXPECT_EQ(png_claims(png).channels, 3);
  EXPECT_NE(png_claims(png.substr(0, png.size() - 12)).damage.find("without an IEND"),
            std::string::npos);
  std::string overlong = png;
  overlong[33] = 0x7f;  // the length of the chunk after IHDR: 2 GB
  EXPECT_NE(png_claims(overlong).damage.find("more than the file holds"), std::string::npos);
  std::string wide = png;  // 64 -> 8192 pixels wide: far more than the image data could hold
  wide[18] = 0x20;
  wide[19] = 0x00;
  EXPECT_NE(png_claims(wide).damage.find("cannot hold the 8192x48 pixels"), std::string::npos)
      << png_claims(wide).damage;
  write_text_atomic(dir / "wide.png", wide);
  try {
    read_image(dir / "wide.png");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("wide.png: damaged PNG"), std::string::npos) << e.what();
  }

  write_image(dir / "depth.exr", cv::Mat(6, 8, CV_32FC1, cv::Scalar(2.5f)));
  std::string exr = read_text(dir / "depth.exr");
  EXPECT_EQ(exr_header_damage(exr), "");
  EXPECT_EQ(exr_header_damage(png), "");  // not OpenEXR: the reader says so
  // The first attribute's size field (after the 8-byte preamble, its name and type) claims 2 GB.
  const std::size_t name_end = exr.find('\0', 8), type_end = exr.find('\0', name_end + 1);
  exr[type_end + 4] = 0x7f;
  const std::string damage = exr_header_damage(exr);
  EXPECT_NE(damage.find("claims"), std::string::npos) << damage;
  write_text_atomic(dir / "bad.exr", exr);
  try {
    read_image(dir / "bad.exr");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.exr: damaged OpenEXR header: attribute"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace simcap
