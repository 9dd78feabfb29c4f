// Per-pixel Gaussian background model (Moschini §6.3, eqs. 6.1-6.3) with the thesis's inverted
// test fixed: a pixel is foreground when it is unlikely under the background's distribution.
#pragma once

#include <opencv2/core/mat.hpp>
#include <vector>

namespace simcap::tracker {

struct BackgroundOptions {
  // Variance floor in 8-bit levels: one empty plate gives zero variance, and a rendered or
  // real camera still has a few levels of noise and compression error.
  double sigma_floor = 4.0;
  // Each frame's own noise also floors the variance: 1.4826 times the median absolute
  // difference from the background mean over a sample of its pixels (most of which are
  // background), so that a noisier sensor than the plates show is not all foreground.
  bool frame_noise = true;
  // "Risk value" of §6.3 as a Mahalanobis distance: foreground when the colour lies more than
  // this many standard deviations (summed over channels) from the background mean. A fixed
  // pdf value would make noisy pixels foreground more easily; the distance does not.
  double threshold = 5.0;
  // Cast shadows (not in the thesis): a pixel darker than the background by a ratio in
  // [min, max] with the background's chromaticity (residual after scaling within
  // shadow_chroma standard deviations) is background (Horprasert et al., ICCV FRAME-RATE 1999).
  bool suppress_shadows = true;
  double shadow_min_ratio = 0.4;
  double shadow_max_ratio = 0.95;
  double shadow_chroma = 2.0;
};

class GaussianBackground {
 public:
  // plates: one or more empty-room frames of one camera, CV_8UC3, equal sizes.
  GaussianBackground(const std::vector<cv::Mat>& plates, const BackgroundOptions& options = {});
  // CV_8UC1, 255 = foreground. Thread-safe.
  cv::Mat foreground(const cv::Mat& frame) const;
  // The frame's noise in 8-bit levels (see BackgroundOptions::frame_noise).
  double frame_sigma(const cv::Mat& frame) const;

 private:
  BackgroundOptions options_;
  cv::Mat mean_;         // CV_32FC3
  cv::Mat inverse_var_;  // CV_32FC3, 1 / the variance floored at sigma_floor², in float
};

}  // namespace simcap::tracker
