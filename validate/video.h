// An MP4 file written frame by frame through OpenCV's VideoWriter (H.264 when the platform's
// FFmpeg has an encoder for it, else MPEG-4 part 2), published atomically on commit().
#pragma once

#include <filesystem>
#include <memory>
#include <opencv2/core/mat.hpp>
#include <string>

#include "core/atomic_file.h"

namespace cv {
class VideoWriter;
}

namespace simcap {

class Mp4Writer {
 public:
  Mp4Writer(const std::filesystem::path& path, double fps, cv::Size size);
  ~Mp4Writer();
  Mp4Writer(const Mp4Writer&) = delete;
  Mp4Writer& operator=(const Mp4Writer&) = delete;

  // False when no codec could be opened; `problem()` then says why.
  bool is_open() const;
  const std::string& problem() const { return problem_; }
  const std::string& codec() const { return codec_; }  // "avc1" or "mp4v"
  // Appends a CV_8UC3 RGB frame of the size given to the constructor.
  void write(const cv::Mat& rgb);
  // Finishes the file and renames it into place; throws Error when that fails.
  void commit();

 private:
  AtomicFile file_;
  std::unique_ptr<cv::VideoWriter> writer_;
  std::string codec_, problem_;
  cv::Size size_;
};

}  // namespace simcap
