// Image files through OpenImageIO: 8/16-bit PNG (RGB, masks, label maps) and float32 EXR
// (depth). Images live in cv::Mat; colour images are kept in RGB channel order, not OpenCV's BGR.
#pragma once

#include <filesystem>
#include <opencv2/core/mat.hpp>

namespace simcap {

// Writes atomically (temporary name, then rename). Supported: CV_8UC1, CV_8UC3, CV_16UC1 as
// PNG; CV_32FC1 and CV_32FC3 as EXR (zip-compressed). Throws Error naming the file and reason.
void write_image(const std::filesystem::path& path, const cv::Mat& image);

// Reads PNG as CV_8U/CV_16U with the file's channel count, EXR as CV_32F.
cv::Mat read_image(const std::filesystem::path& path);

}  // namespace simcap
