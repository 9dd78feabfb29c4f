#include "validate/video.h"

#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "core/error.h"

namespace simcap {

Mp4Writer::Mp4Writer(const std::filesystem::path& path, double fps, cv::Size size)
    : file_(path), writer_(std::make_unique<cv::VideoWriter>()), size_(size) {
  // avc1 first: browsers play H.264 in an HTML <video>; they do not play MPEG-4 part 2.
  for (const char* fourcc : {"avc1", "mp4v"}) {
    const int code = cv::VideoWriter::fourcc(fourcc[0], fourcc[1], fourcc[2], fourcc[3]);
    if (writer_->open(file_.temp_path().string(), cv::CAP_FFMPEG, code, fps, size)) {
      codec_ = fourcc;
      return;
    }
  }
  problem_ = "OpenCV could not open an MP4 encoder (avc1 or mp4v) through FFmpeg on this platform";
}

Mp4Writer::~Mp4Writer() = default;

bool Mp4Writer::is_open() const {
  return writer_->isOpened();
}

void Mp4Writer::write(const cv::Mat& rgb) {
  if (rgb.type() != CV_8UC3 || rgb.size() != size_) {
    throw Error(file_.target().string() + ": video frames must be 8-bit RGB of the first size");
  }
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  writer_->write(bgr);
}

void Mp4Writer::commit() {
  writer_->release();
  std::error_code ec;
  if (std::filesystem::file_size(file_.temp_path(), ec) == 0 || ec) {
    throw Error(file_.target().string() + ": the encoder wrote no data");
  }
  file_.commit();
}

}  // namespace simcap
