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

double GaussianBackground::frame_sigma(const cv::Mat& frame) const {
  // Every 7th pixel of every 7th row and all three channels: enough for a median, and the step
  // is prime to the usual image widths so that columns do not repeat.
  std::vector<float> e;
  e.reserve(static_cast<size_t>(frame.rows / 7 + 1) * (frame.cols / 7 + 1) * 3);
  for (int r = 0; r < frame.rows; r += 7) {
    const cv::Vec3b* x = frame.ptr<cv::Vec3b>(r);
    const cv::Vec3f* mu = mean_.ptr<cv::Vec3f>(r);
    for (int c = (r / 7) % 7; c < frame.cols; c += 7) {
      for (int k = 0; k < 3; ++k) e.push_back(std::abs(x[c][k] - mu[c][k]));
    }
  }
  if (e.empty()) return 0;
  const auto mid = e.begin() + static_cast<std::ptrdiff_t>(e.size() / 2);
  std::nth_element(e.begin(), mid, e.end());
  return 1.4826 * *mid;
}

cv::Mat GaussianBackground::foreground(const cv::Mat& frame) const {
  if (frame.type() != CV_8UC3 || frame.size() != mean_.size()) {
    throw Error("background model: frame must be an 8-bit colour image of the plate's size");
  }
  cv::Mat out(frame.size(), CV_8UC1);
  const float noise = options_.frame_noise ? static_cast<float>(frame_sigma(frame)) : 0.0f;
  const float inverse_noise2 = 1.0f / (noise * noise);  // +inf without noise: no floor
  const float t2 = static_cast<float>(options_.threshold * options_.threshold);
  const float c2 = static_cast<float>(options_.shadow_chroma * options_.shadow_chroma);
  const float lo = static_cast<float>(options_.shadow_min_ratio);
  const float hi = static_cast<float>(options_.shadow_max_ratio);
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
        float d2 = 0, xm = 0, mm = 0;
        for (int k = 0; k < 3; ++k) {
          const float e = x[c][k] - mu[c][k];
          d2 += e * e * iv[k];
          xm += x[c][k] * mu[c][k];
          mm += mu[c][k] * mu[c][k];
        }
        bool fg = d2 > t2;
        if (fg && options_.suppress_shadows && mm > 0) {
          const float alpha = xm / mm;
          if (alpha >= lo && alpha <= hi) {
            float cd2 = 0;
            for (int k = 0; k < 3; ++k) {
              const float e = x[c][k] - alpha * mu[c][k];
              cd2 += e * e * iv[k];
            }
            fg = cd2 > c2;
          }
        }
        o[c] = fg ? 255 : 0;
      }
    }
  });
  return out;
}

}  // namespace simcap::tracker
