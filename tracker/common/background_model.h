// Per-pixel Gaussian background model (Moschini §6.3, eqs. 6.1-6.3) with the thesis's inverted
// test fixed: a pixel is foreground when it is unlikely under the background's distribution.
#pragma once

#include <algorithm>
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
  // Changing light (not in the thesis): after the plates were taken a cloud, a lamp, the sun
  // moving or the camera's automatic exposure scale each background pixel's brightness by a
  // factor of its own (a surface turned towards the light more than one in shade) and keep its
  // chromaticity. Two things follow. The frame's noise (frame_noise) is measured on what is left
  // once each pixel's brightness is scaled to the frame's whenever the plain difference exceeds
  // `relit_ratio` times that: most pixels then differ by the light, not by noise. And where the
  // light grew (at least 1 % of the sampled pixels are the background's colour brightened by
  // more than 3 sigma), a pixel brighter than the background by a factor up to the 95th
  // percentile of theirs times `highlight_margin`, with the background's chromaticity (within
  // shadow_chroma), is background too: Horprasert et al.'s highlighted background, its bound
  // measured on the frame.
  bool relight = true;
  double relit_ratio = 2.0;
  double highlight_margin = 1.25;
};

// How a frame's light differs from the plates', measured on a sample of its pixels.
struct FrameLight {
  double sigma = 0;        // noise of the plain difference, 8-bit levels (frame_sigma())
  double relit_sigma = 0;  // noise left once each pixel's brightness is scaled to the frame's
  bool relit = false;      // the plain difference is the light's (BackgroundOptions::relit_ratio)
  double highlight = 0;    // > 0: the frame is brighter, its background by up to this factor
  // The noise the test uses (BackgroundOptions::frame_noise).
  double noise(double floor) const { return relit ? std::max(relit_sigma, floor) : sigma; }
};

class GaussianBackground {
 public:
  // plates: one or more empty-room frames of one camera, CV_8UC3, equal sizes.
  GaussianBackground(const std::vector<cv::Mat>& plates, const BackgroundOptions& options = {});
  // CV_8UC1, 255 = foreground. Thread-safe.
  cv::Mat foreground(const cv::Mat& frame) const;
  // The frame's noise in 8-bit levels (see BackgroundOptions::frame_noise).
  double frame_sigma(const cv::Mat& frame) const;
  // The frame's light against the plates' (see BackgroundOptions::relight).
  FrameLight frame_light(const cv::Mat& frame) const;

 private:
  BackgroundOptions options_;
  cv::Mat mean_;         // CV_32FC3
  cv::Mat inverse_var_;  // CV_32FC3, 1 / the variance floored at sigma_floor², in float
};

}  // namespace simcap::tracker
