#include "tracker/common/silhouettes.h"

#include <opencv2/imgproc.hpp>

#include "core/error.h"

namespace simcap::tracker {

SilhouetteExtractor::SilhouetteExtractor(const Dataset& dataset, SilhouetteMethod method,
                                         const SilhouetteOptions& options)
    : dataset_(&dataset), method_(method), options_(options) {
  const int nc = dataset.camera_count();
  if (method == SilhouetteMethod::bgsub) {
    for (int c = 0; c < nc; ++c)
      gaussian_.emplace_back(std::vector{dataset.background(c)}, options.background);
  } else if (method == SilhouetteMethod::mog2) {
    mog2_mutex_ = std::make_unique<std::mutex[]>(nc);
    for (int c = 0; c < nc; ++c) {
      auto mog = cv::createBackgroundSubtractorMOG2(500, options.mog2_var_threshold, true);
      const cv::Mat plate = dataset.background(c);
      cv::Mat ignored;
      // The first frame (rate 1) initialises every Gaussian; the repeats let the mixture's
      // weights settle on the single background mode.
      mog->apply(plate, ignored, 1.0);
      for (int i = 0; i < 20; ++i) mog->apply(plate, ignored, -1);
      mog2_.push_back(mog);
    }
  }
}

cv::Mat SilhouetteExtractor::clean(const cv::Mat& mask) const {
  cv::Mat out = mask;
  if (options_.open_px > 1) {
    cv::morphologyEx(
        out, out, cv::MORPH_OPEN,
        cv::getStructuringElement(cv::MORPH_ELLIPSE, {options_.open_px, options_.open_px}));
  }
  if (options_.close_px > 1) {
    cv::morphologyEx(
        out, out, cv::MORPH_CLOSE,
        cv::getStructuringElement(cv::MORPH_ELLIPSE, {options_.close_px, options_.close_px}));
  }
  return out;
}

cv::Mat SilhouetteExtractor::extract(int camera, int frame, cv::Mat* colour,
                                     bool colour_in_silhouette) const {
  if (method_ == SilhouetteMethod::gt) {
    cv::Mat mask = dataset_->mask(camera, frame);
    if (colour) {
      int rows = mask.rows;
      while (colour_in_silhouette && rows > 0 && cv::countNonZero(mask.row(rows - 1)) == 0) --rows;
      *colour = dataset_->rgb(camera, frame, rows);
    }
    return mask;
  }
  const cv::Mat image = dataset_->rgb(camera, frame);
  if (colour) *colour = image;
  switch (method_) {
    case SilhouetteMethod::gt:
      break;
    case SilhouetteMethod::bgsub:
      return clean(gaussian_.at(camera).foreground(image));
    case SilhouetteMethod::mog2: {
      cv::Mat fg;
      {
        std::lock_guard lock(mog2_mutex_[camera]);
        mog2_.at(camera)->apply(image, fg, 0.0);  // rate 0: the model stays the empty room's
      }
      cv::threshold(fg, fg, 200, 255, cv::THRESH_BINARY);  // shadows are marked 127: background
      return clean(fg);
    }
  }
  throw Error("silhouettes: unknown method");
}

double silhouette_iou(const cv::Mat& a, const cv::Mat& b) {
  if (a.size() != b.size()) throw Error("silhouette IoU: masks differ in size");
  const cv::Mat ma = a != 0, mb = b != 0;
  const double inter = cv::countNonZero(ma & mb);
  const double uni = cv::countNonZero(ma | mb);
  return uni > 0 ? inter / uni : 1.0;
}

}  // namespace simcap::tracker
