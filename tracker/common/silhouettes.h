// The tracker's silhouettes, one per camera and frame: the dataset's ground-truth masks, the
// Gaussian background model of §6.3, or OpenCV's MOG2 background subtractor.
#pragma once

#include <memory>
#include <mutex>
#include <opencv2/core/mat.hpp>
#include <opencv2/video/background_segm.hpp>
#include <string>
#include <vector>

#include "core/name_table.h"
#include "tracker/common/background_model.h"
#include "tracker/common/dataset.h"

namespace simcap::tracker {

enum class SilhouetteMethod { gt, bgsub, mog2 };
inline constexpr NameTable<SilhouetteMethod, 3> kSilhouetteMethods{
    {{"gt", SilhouetteMethod::gt},
     {"bgsub", SilhouetteMethod::bgsub},
     {"mog2", SilhouetteMethod::mog2}}};

struct SilhouetteOptions {
  BackgroundOptions background;
  // Clean-up of subtracted masks: opening removes speckles, closing fills small holes (a hole
  // in one view would carve a tunnel through the hull).
  int open_px = 3;
  int close_px = 5;
  double mog2_var_threshold = 16.0;  // OpenCV's default squared Mahalanobis distance
};

class SilhouetteExtractor {
 public:
  SilhouetteExtractor(const Dataset& dataset, SilhouetteMethod method,
                      const SilhouetteOptions& options = {});
  SilhouetteMethod method() const { return method_; }
  // Which images of the dataset this method reads ("mask" or "rgb").
  std::string image_kind() const { return method_ == SilhouetteMethod::gt ? "mask" : "rgb"; }
  // CV_8UC1, nonzero = actor. Thread-safe. With `colour`, the frame's colour image goes there
  // too (read once when the method subtracts it from the background); with `colour_in_silhouette`
  // only down to the silhouette's lowest row, for a caller that reads colours inside it alone.
  cv::Mat extract(int camera, int frame, cv::Mat* colour = nullptr,
                  bool colour_in_silhouette = false) const;

 private:
  cv::Mat clean(const cv::Mat& mask) const;
  const Dataset* dataset_;
  SilhouetteMethod method_;
  SilhouetteOptions options_;
  std::vector<GaussianBackground> gaussian_;
  std::vector<cv::Ptr<cv::BackgroundSubtractorMOG2>> mog2_;
  std::unique_ptr<std::mutex[]> mog2_mutex_;  // apply() writes into the subtractor
};

// Intersection over union of two masks (nonzero = inside); 1 when both are empty.
double silhouette_iou(const cv::Mat& a, const cv::Mat& b);

}  // namespace simcap::tracker
