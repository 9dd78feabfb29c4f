// Image files through OpenImageIO: 8/16-bit PNG (RGB, masks, label maps) and float32 EXR
// (depth). Images live in cv::Mat; colour images are kept in RGB channel order, not OpenCV's BGR.
#pragma once

#include <filesystem>
#include <opencv2/core/mat.hpp>
#include <string>

namespace simcap {

// How hard to compress: the defaults give small files; the renderer, which writes a dozen
// images per frame, trades size for encoding speed.
struct ImageCompression {
  int png_level = 6;        // zlib level, 0 (fastest) to 9 (smallest)
  bool png_filter = true;   // libpng's adaptive row filters; false: none (~3x faster encoding)
  std::string exr = "zip";  // OpenEXR compression: zip, none, rle, piz, ...
};

// Writes atomically (temporary name, then rename). Supported: CV_8UC1, CV_8UC3, CV_16UC1 as
// PNG; CV_32FC1 and CV_32FC3 as EXR. Throws Error naming the file and reason.
void write_image(const std::filesystem::path& path, const cv::Mat& image,
                 const ImageCompression& compression = {});

// Reads PNG as CV_8U/CV_16U with the file's channel count, EXR as CV_32F. A file whose header
// claims more than limits.h allows is refused before anything is allocated for its pixels.
cv::Mat read_image(const std::filesystem::path& path);

// Throws Error naming `path` and the limit when an image of width x height pixels and `channels`
// channels is beyond limits.h's (checked on a header's claim, before allocating).
void check_image_size(const std::filesystem::path& path, long width, long height, int channels);

}  // namespace simcap
