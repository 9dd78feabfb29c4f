#include "tracker/unzueta/pelvis_tracker.h"

#include <algorithm>
#include <vector>

namespace simcap::tracker {

PelvisParams PelvisParams::scaled_for(double person_px) const {
  PelvisParams p = *this;
  const double k = person_px / 170.0;
  p.grid = std::max(1, static_cast<int>(std::lround(grid * k)));
  p.max_dist *= k;
  return p;
}

std::optional<cv::Point2d> PelvisTracker::measure(const cv::Mat& mask) const {
  std::vector<cv::Point> pixels;
  const int g = params_.grid;
  for (int y = g / 2; y < mask.rows; y += g) {
    const unsigned char* row = mask.ptr<unsigned char>(y);
    for (int x = g / 2; x < mask.cols; x += g) {
      if (row[x]) pixels.emplace_back(x, y);
    }
  }
  if (pixels.empty()) return std::nullopt;
  std::vector<int> xs;
  for (const cv::Point& p : pixels) xs.push_back(p.x);
  std::nth_element(xs.begin(), xs.begin() + xs.size() / 2, xs.end());
  const double median = xs[xs.size() / 2];
  // The band always holds the median pixel itself.
  cv::Point2d sum;
  int n = 0;
  for (const cv::Point& p : pixels) {
    if (p.x >= median - params_.max_dist && p.x <= median + params_.max_dist) {
      sum += cv::Point2d(p);
      ++n;
    }
  }
  return sum / n;
}

std::optional<cv::Point2d> PelvisTracker::track(const cv::Mat& mask) {
  const std::optional<cv::Point2d> m = measure(mask);
  measured_ = m.has_value();
  if (!filter_) {
    if (m) filter_.emplace(*m, params_.kalman);
    return m;
  }
  filter_->predict();
  if (m) return filter_->correct(*m);
  filter_->coast();
  return filter_->position();
}

}  // namespace simcap::tracker
