// The dataset's PNG decoder against OpenCV's: the same pixels for every kind of file, and the
// same refusal of damaged ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <random>

#include "core/error.h"
#include "tests/support/huge_png.h"
#include "tests/support/temp_dir.h"
#include "tracker/common/png_decoder.h"

namespace simcap::tracker {
namespace {

namespace fs = std::filesystem;

cv::Mat noise(int type) {
  cv::Mat m(37, 53, type);
  cv::randu(m, 0, CV_MAT_DEPTH(type) == CV_16U ? 65536 : 256);
  return m;
}

bool same(const cv::Mat& a, const cv::Mat& b) {
  if (a.empty() || b.empty()) return a.empty() && b.empty();
  return a.size() == b.size() && a.type() == b.type() && cv::norm(a, b, cv::NORM_INF) == 0;
}

TEST(PngDecoder, DecodesEveryKindOfFileAsOpenCvDoes) {
  testing::TempDir dir;
  cv::theRNG().state = 7;
  const std::vector<std::pair<std::string, cv::Mat>> files = {{"grey.png", noise(CV_8UC1)},
                                                              {"colour.png", noise(CV_8UC3)},
                                                              {"alpha.png", noise(CV_8UC4)},
                                                              {"grey16.png", noise(CV_16UC1)},
                                                              {"colour16.png", noise(CV_16UC3)}};
  for (const auto& [name, image] : files) {
    const fs::path path = dir / name;
    ASSERT_TRUE(cv::imwrite(path.string(), image));
    for (const int flags : {cv::IMREAD_UNCHANGED, cv::IMREAD_COLOR, cv::IMREAD_GRAYSCALE}) {
      EXPECT_TRUE(same(decode_png(path, flags), cv::imread(path.string(), flags)))
          << name << " flags " << flags;
    }
  }
}

TEST(PngDecoder, DecodesTheFirstRowsOnlyWhenAsked) {
  testing::TempDir dir;
  cv::theRNG().state = 5;
  for (const int type : {CV_8UC1, CV_8UC3}) {
    const fs::path path = dir / "image.png";
    ASSERT_TRUE(cv::imwrite(path.string(), noise(type)));
    const int flags = type == CV_8UC1 ? cv::IMREAD_UNCHANGED : cv::IMREAD_COLOR;
    const cv::Mat whole = decode_png(path, flags);
    for (const int rows : {0, 1, 20, 36, 37, 100}) {
      const cv::Mat top = decode_png(path, flags, rows);
      ASSERT_EQ(top.size(), whole.size()) << rows;
      const int kept = std::min(rows, whole.rows);
      EXPECT_TRUE(same(top.rowRange(0, kept), whole.rowRange(0, kept))) << rows;
      EXPECT_EQ(cv::countNonZero(top.rowRange(kept, top.rows).reshape(1)), 0) << rows;
    }
  }
}

TEST(PngDecoder, RefusesDamagedFilesAsOpenCvDoes) {
  testing::TempDir dir;
  cv::theRNG().state = 11;
  const fs::path good = dir / "good.png";
  ASSERT_TRUE(cv::imwrite(good.string(), noise(CV_8UC3)));
  std::ifstream in(good, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto write = [&](const std::string& name, const std::string& content) {
    std::ofstream(dir / name, std::ios::binary) << content;
    return dir / name;
  };
  std::string flipped = bytes;
  flipped[flipped.size() / 2] ^= 0x5a;  // inside the image data: its chunk CRC no longer matches
  for (const fs::path& path :
       {write("truncated.png", bytes.substr(0, bytes.size() / 2)), write("flipped.png", flipped),
        write("empty.png", ""), write("text.png", "not a picture"), dir / "missing.png"}) {
    const cv::Mat decoded = decode_png(path, cv::IMREAD_COLOR);
    EXPECT_TRUE(decoded.empty()) << path;
    EXPECT_TRUE(same(decoded, cv::imread(path.string(), cv::IMREAD_COLOR))) << path;
  }
}

TEST(PngDecoder, RefusesAHeaderClaimingTooManyPixelsBeforeAllocating) {
  testing::TempDir dir;
  std::ofstream(dir / "huge.png", std::ios::binary) << testing::kHugeHeaderPng;
  for (const int flags : {cv::IMREAD_UNCHANGED, cv::IMREAD_COLOR}) {
    try {
      decode_png(dir / "huge.png", flags);
      FAIL() << flags;
    } catch (const Error& e) {
      EXPECT_NE(
          std::string(e.what()).find("65536x32768 pixels, more than the 67108864 (8192x8192)"),
          std::string::npos)
          << e.what();
    }
  }
}

// A frame that is not a PNG is unreadable, whatever else it may be: cv::imread would hand it to
// every decoder OpenCV has (a DICOM reader aborts on some bytes), and a chunk claiming more
// than the file holds is damage, refused before anything allocates what it claims.
TEST(PngDecoder, NotAPngAndOverlongChunksAreUnreadable) {
  testing::TempDir dir;
  const cv::Mat grey(4, 6, CV_8UC1, cv::Scalar(90));
  cv::imwrite((dir / "frame.bmp").string(), grey);
  std::filesystem::copy_file(dir / "frame.bmp", dir / "bmp.png");
  ASSERT_FALSE(cv::imread((dir / "bmp.png").string(), cv::IMREAD_UNCHANGED).empty());
  std::vector<std::uint8_t> png;
  cv::imencode(".png", grey, png);
  png[33] = 0x7f;  // the length of the chunk after IHDR: 2 GB, beyond the file's end
  std::ofstream(dir / "overlong.png", std::ios::binary)
      .write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
  for (const int flags : {cv::IMREAD_UNCHANGED, cv::IMREAD_COLOR, cv::IMREAD_GRAYSCALE}) {
    EXPECT_TRUE(decode_png(dir / "bmp.png", flags).empty()) << flags;
    EXPECT_TRUE(decode_png(dir / "overlong.png", flags).empty()) << flags;
  }
}

}  // namespace
}  // namespace simcap::tracker
