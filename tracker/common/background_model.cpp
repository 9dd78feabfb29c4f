#include "tracker/common/background_model.h"

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>
#include <vector>

#include "core/error.h"

namespace simcap::tracker {

GaussianBackground::GaussianBackground(const std::vector<cv::Mat>& plates,
                                       const BackgroundOptions& options)
    : options_(options) {
  if (plates.empty()) throw Error("background model: no background frames");
  const cv::Size size = plates.front().size();
  cv::Mat sum = cv::Mat::zeros(size, CV_64FC3), sum2 = cv::Mat::zeros(size, CV_64FC3);
  for (const cv::Mat& p : plates) {
    if (p.type() != CV_8UC3 || p.size() != size) {
      throw Error("background model: background frames must be 8-bit colour images of one size");
    }
    cv::Mat f;
    p.convertTo(f, CV_64FC3);
    sum += f;
    sum2 += f.mul(f);
  }
  const double n = static_cast<double>(plates.size());
  cv::Mat mean = sum / n;
  cv::Mat var = sum2 / n - mean.mul(mean);  // eq. 6.2
  const double floor = options.sigma_floor * options.sigma_floor;
  cv::max(var, floor, var);
  mean.convertTo(mean_, CV_32FC3);
  // Inverted in float, so that min(1/var, 1/noise²) per frame equals 1/max(var, noise²).
  cv::Mat var32;
  var.convertTo(var32, CV_32FC3);
  cv::divide(1.0f, var32, inverse_var_, 1, CV_32FC3);
}

namespace {

// Median of `v` (reordered); 0 when empty.
float median(std::vector<float>& v) {
  if (v.empty()) return 0;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// The brightness factor that brings the background colour `mu` nearest to `x` over the channels
// `x` does not saturate, and its squared residual weighted by `iv`.
struct Scaled {
  float alpha = 0, residual2 = 0;
  float norm = 0;    // of the background's colour over those channels
  int channels = 0;  // unsaturated
};
Scaled scale_to(const cv::Vec3b& x, const cv::Vec3f& mu, const cv::Vec3f& iv) {
  Scaled s;
  float xm = 0, mm = 0;
  for (int k = 0; k < 3; ++k) {
    if (x[k] == 255) continue;
    xm += x[k] * mu[k];
    mm += mu[k] * mu[k];
    ++s.channels;
  }
  if (mm <= 0) return s;
  s.alpha = xm / mm;
  s.norm = std::sqrt(mm);
  for (int k = 0; k < 3; ++k) {
    if (x[k] == 255) continue;
    const float e = x[k] - s.alpha * mu[k];
    s.residual2 += e * e * iv[k];
  }
  return s;
}

}  // namespace

double GaussianBackground::frame_sigma(const cv::Mat& frame) const {
  return frame_light(frame).sigma;
}

FrameLight GaussianBackground::frame_light(const cv::Mat& frame) const {
  // Every 7th pixel of every 7th row and all three channels: enough for a median, and the step
  // is prime to the usual image widths so that columns do not repeat.
  std::vector<float> plain, residual;
  std::vector<Scaled> scaled;
  plain.reserve(static_cast<size_t>(frame.rows / 7 + 1) * (frame.cols / 7 + 1) * 3);
  const cv::Vec3f unit(1, 1, 1);
  for (int r = 0; r < frame.rows; r += 7) {
    const cv::Vec3b* x = frame.ptr<cv::Vec3b>(r);
    const cv::Vec3f* mu = mean_.ptr<cv::Vec3f>(r);
    for (int c = (r / 7) % 7; c < frame.cols; c += 7) {
      for (int k = 0; k < 3; ++k) plain.push_back(std::abs(x[c][k] - mu[c][k]));
      if (!options_.relight) continue;
      const Scaled s = scale_to(x[c], mu[c], unit);
      if (s.channels < 2) continue;
      scaled.push_back(s);
      residual.push_back(std::sqrt(s.residual2 / static_cast<float>(s.channels)));
    }
  }
  FrameLight light;
  light.sigma = 1.4826 * median(plain);
  if (!options_.relight) return light;
  // Scaling by the fitted factor leaves about 2 of 3 channels' worth of noise.
  light.relit_sigma = 1.4826 * std::sqrt(1.5) * median(residual);
  light.relit =
      light.sigma > options_.relit_ratio * std::max(light.relit_sigma, options_.sigma_floor);
  // The pixels a factor explains that are brighter by more than the noise: the background
  // where the light grew (a person's colours rarely are the background's, brightened).
  const double noise = std::max(light.noise(options_.sigma_floor), options_.sigma_floor);
  const auto t2 = static_cast<float>(options_.threshold * options_.threshold * noise * noise);
  std::vector<float> brighter;
  for (const Scaled& s : scaled) {
    if (s.residual2 <= t2 && (s.alpha - 1) * s.norm > 3 * noise) brighter.push_back(s.alpha);
  }
  if (brighter.size() >= std::max<size_t>(20, scaled.size() / 100)) {
    const auto p95 = brighter.begin() + static_cast<std::ptrdiff_t>(brighter.size() * 95 / 100);
    std::nth_element(brighter.begin(), p95, brighter.end());
    light.highlight = *p95 * options_.highlight_margin;
  }
  return light;
}

cv::Mat GaussianBackground::foreground(const cv::Mat& frame) const {
  if (frame.type() != CV_8UC3 || frame.size() != mean_.size()) {
    throw Error("background model: frame must be an 8-bit colour image of the plate's size");
  }
  cv::Mat out(frame.size(), CV_8UC1);
  const FrameLight light =
      options_.frame_noise || options_.relight ? frame_light(frame) : FrameLight{};
  const float noise =
      options_.frame_noise ? static_cast<float>(light.noise(options_.sigma_floor)) : 0.0f;
  const float inverse_noise2 = 1.0f / (noise * noise);  // +inf without noise: no floor
  const float t2 = static_cast<float>(options_.threshold * options_.threshold);
  const float c2 = static_cast<float>(options_.shadow_chroma * options_.shadow_chroma);
  const float lo = options_.suppress_shadows ? static_cast<float>(options_.shadow_min_ratio) : 1;
  const float hi = options_.suppress_shadows ? static_cast<float>(options_.shadow_max_ratio) : 1;
  const auto highlight = static_cast<float>(light.highlight);
  // A channel the frame saturates is background only where the scaled background saturates too.
  const float saturated = 255.0f - 3.0f * std::max(noise, static_cast<float>(options_.sigma_floor));
  cv::parallel_for_(cv::Range(0, frame.rows), [&](const cv::Range& rows) {
    for (int r = rows.start; r < rows.end; ++r) {
      const cv::Vec3b* x = frame.ptr<cv::Vec3b>(r);
      const cv::Vec3f* mu = mean_.ptr<cv::Vec3f>(r);
      const cv::Vec3f* inverse_var = inverse_var_.ptr<cv::Vec3f>(r);
      std::uint8_t* o = out.ptr<std::uint8_t>(r);
      for (int c = 0; c < frame.cols; ++c) {
        const cv::Vec3f iv(std::min(inverse_var[c][0], inverse_noise2),
                           std::min(inverse_var[c][1], inverse_noise2),
                           std::min(inverse_var[c][2], inverse_noise2));
        float d2 = 0;
        for (int k = 0; k < 3; ++k) {
          const float e = x[c][k] - mu[c][k];
          d2 += e * e * iv[k];
        }
        bool fg = d2 > t2;
        if (fg) {
          // Shaded or highlighted background: the background's chromaticity, scaled.
          const Scaled s = scale_to(x[c], mu[c], iv);
          if (s.channels == 0) {
            // White: background if the brightest the background gets saturates it too.
            fg = highlight * std::min({mu[c][0], mu[c][1], mu[c][2]}) < saturated;
          } else if ((s.alpha >= lo && s.alpha <= hi) || (s.alpha > hi && s.alpha <= highlight)) {
            fg = s.residual2 > c2;
            for (int k = 0; k < 3; ++k) {
              if (x[c][k] == 255 && s.alpha * mu[c][k] < saturated) fg = true;
            }
          }
        }
        o[c] = fg ? 255 : 0;
      }
    }
  });
  return out;
}

}  // namespace simcap::tracker
