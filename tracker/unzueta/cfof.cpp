#include "tracker/unzueta/cfof.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>

#include "core/error.h"

namespace simcap::tracker {
namespace {

// The thesis' person height in its 320x240 images (a 1.78 m subject 3.5 m from the camera).
constexpr double kThesisPersonPx = 170.0;

double median(std::vector<double> v) {
  const size_t mid = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + mid, v.end());
  return v[mid];
}

}  // namespace

CfofParams CfofParams::scaled_for(double person_px) const {
  CfofParams p = *this;
  const double k = person_px / kThesisPersonPx;
  p.max_dist *= k;
  p.lk_window = std::max(5, static_cast<int>(std::lround(lk_window * k)));
  p.shi_tomasi_min_distance *= k;
  return p;
}

CfofFrame CfofFrame::from_bgr(const cv::Mat& bgr, const cv::Mat& mask, const CfofParams& params) {
  CfofFrame f;
  cv::cvtColor(bgr, f.grey, cv::COLOR_BGR2GRAY);
  cv::cvtColor(bgr, f.hsv, cv::COLOR_BGR2HSV);
  cv::buildOpticalFlowPyramid(f.grey, f.pyramid, cv::Size(params.lk_window, params.lk_window),
                              params.lk_levels - 1);
  f.mask = mask;
  return f;
}

const char* cfof_state_name(CfofState state) {
  switch (state) {
    case CfofState::tracking:
      return "tracking";
    case CfofState::occluded:
      return "occluded";
    case CfofState::lost:
      return "lost";
  }
  return "?";
}

cv::Rect CfofTracker::roi_at(cv::Point2d c) const {
  return {static_cast<int>(std::lround(c.x - 0.5 * size_.width)),
          static_cast<int>(std::lround(c.y - 0.5 * size_.height)),
          static_cast<int>(std::lround(size_.width)), static_cast<int>(std::lround(size_.height))};
}

cv::Rect2d CfofTracker::roi() const {
  return {centre_.x - 0.5 * size_.width, centre_.y - 0.5 * size_.height, size_.width, size_.height};
}

cv::Point2d CfofTracker::predicted_centre() const {
  switch (state_) {
    case CfofState::tracking:
      return roi_filter_.position() + roi_filter_.velocity();
    case CfofState::occluded:
      return centre_ + coast_velocity_;
    case CfofState::lost:
      break;
  }
  return centre_;
}

std::vector<cv::Point2f> CfofTracker::selection() const {
  std::vector<cv::Point2f> out;
  const size_t n = std::min<size_t>(features_.size(), params_.select);
  for (size_t i = 0; i < n; ++i) out.push_back(features_[i].point);
  return out;
}

CfofTracker::Feature CfofTracker::make_feature(cv::Point2f p) const {
  return {p, PointKalman(p, params_.kalman)};
}

int CfofTracker::coloured_pixels(const CfofFrame& frame, cv::Rect roi) const {
  const cv::Mat p = colour_.back_project(frame.hsv, roi, frame.mask);
  return p.empty() ? 0 : cv::countNonZero(p >= std::ceil(params_.min_color * 255));
}

void CfofTracker::initialize(const CfofFrame& frame, cv::Rect2d roi) {
  size_ = roi.size();
  centre_ = (roi.tl() + roi.br()) * 0.5;
  colour_.learn(frame.hsv, roi_at(centre_), frame.mask);
  initial_coloured_ = coloured_pixels(frame, roi_at(centre_));
  if (initial_coloured_ == 0) throw Error("CFOF: no pixel of the part's colour in its region");
  start(frame);
}

void CfofTracker::borrow_colours(const CfofTracker& donor, double scale) {
  if (initial_coloured_ > 0 || donor.initial_coloured_ == 0) return;
  colour_ = donor.colour_;
  size_ = donor.size_ * scale;
  initial_coloured_ =
      std::max(1, static_cast<int>(std::lround(donor.initial_coloured_ * scale * scale)));
}

bool CfofTracker::restart(const CfofFrame& frame, cv::Point2d centre) {
  if (initial_coloured_ == 0 ||
      coloured_pixels(frame, roi_at(centre)) < params_.restart_color_fraction * initial_coloured_) {
    return false;
  }
  centre_ = centre;
  start(frame);
  return state_ == CfofState::tracking;
}

void CfofTracker::start(const CfofFrame& frame) {
  features_.clear();
  search(frame);
  cmdf(frame);
  coast_velocity_ = {};
  if (features_.empty()) {
    state_ = CfofState::lost;
    return;
  }
  centre_on_selection();
  roi_filter_ = PointKalman(centre_, params_.kalman);
  state_ = CfofState::tracking;
}

void CfofTracker::search(const CfofFrame& frame) {
  const cv::Rect roi = roi_at(centre_) & cv::Rect(0, 0, frame.grey.cols, frame.grey.rows);
  if (roi.empty()) return;
  const cv::Mat coloured =
      colour_.back_project(frame.hsv, roi, frame.mask) >= std::ceil(params_.min_color * 255);
  std::vector<cv::Point2f> corners;
  cv::goodFeaturesToTrack(frame.grey(roi), corners, params_.max_detect, params_.shi_tomasi_quality,
                          params_.shi_tomasi_min_distance, coloured);
  for (const cv::Point2f& c : corners) features_.push_back(make_feature(c + cv::Point2f(roi.tl())));
}

void CfofTracker::flow(const CfofFrame& previous, const CfofFrame& current) {
  std::vector<cv::Point2f> from, to;
  for (const Feature& f : features_) from.push_back(f.point);
  std::vector<unsigned char> status;
  std::vector<float> error;
  cv::calcOpticalFlowPyrLK(previous.pyramid, current.pyramid, from, to, status, error,
                           cv::Size(params_.lk_window, params_.lk_window), params_.lk_levels - 1);
  std::vector<Feature> kept;
  const double gate2 = params_.kalman_gate * params_.kalman_gate;
  for (size_t i = 0; i < features_.size(); ++i) {
    if (!status[i]) continue;
    Feature f = std::move(features_[i]);
    f.filter.predict();
    if (f.filter.mahalanobis2(to[i]) > gate2) continue;
    f.point = f.filter.correct(to[i]);
    kept.push_back(std::move(f));
  }
  features_ = std::move(kept);
}

void CfofTracker::cmdf(const CfofFrame& frame) {
  const cv::Rect roi = roi_at(centre_) & cv::Rect(0, 0, frame.hsv.cols, frame.hsv.rows);
  if (roi.empty()) {
    features_.clear();
    return;
  }
  const cv::Mat probability = colour_.back_project(frame.hsv, roi, frame.mask);
  const int threshold = static_cast<int>(std::ceil(params_.min_color * 255));
  auto colour_at = [&](cv::Point2f p) -> int {
    const int x = static_cast<int>(std::lround(p.x)) - roi.x,
              y = static_cast<int>(std::lround(p.y)) - roi.y;
    if (x < 0 || y < 0 || x >= roi.width || y >= roi.height) return 0;
    return probability.at<unsigned char>(y, x);
  };
  cv::Point2d med = centre_;
  if (!features_.empty()) {
    std::vector<double> xs, ys;
    for (const Feature& f : features_) xs.push_back(f.point.x), ys.push_back(f.point.y);
    med = {median(xs), median(ys)};
  }
  // Lines 2-9: the features near the median on the part's colour, in their order.
  std::vector<Feature> selection;
  for (const Feature& f : features_) {
    if (static_cast<int>(selection.size()) == params_.select) break;
    if (std::hypot(f.point.x - med.x, f.point.y - med.y) <= params_.max_dist &&
        colour_at(f.point) >= threshold) {
      selection.push_back(f);
    }
  }
  // Lines 13-21: fill the gaps with the most probable coloured pixels of the ROI (ties: the
  // pixel nearer the median first, so that equal probabilities do not favour one corner).
  if (static_cast<int>(selection.size()) < params_.select && !params_.fill_with_colour) {
    const cv::Mat coloured = probability >= threshold;
    std::vector<cv::Point2f> corners;
    cv::goodFeaturesToTrack(frame.grey(roi), corners, params_.max_detect,
                            params_.shi_tomasi_quality, params_.shi_tomasi_min_distance, coloured);
    for (const cv::Point2f& c : corners) {
      if (static_cast<int>(selection.size()) == params_.select) break;
      selection.push_back(make_feature(c + cv::Point2f(roi.tl())));
    }
  }
  if (static_cast<int>(selection.size()) < params_.select) {
    struct Pixel {
      int probability;
      double distance;
      cv::Point2f point;
    };
    std::vector<Pixel> pixels;
    for (int y = 0; y < roi.height; ++y) {
      const unsigned char* row = probability.ptr<unsigned char>(y);
      for (int x = 0; x < roi.width; ++x) {
        if (row[x] < threshold) continue;
        const cv::Point2f p(static_cast<float>(roi.x + x), static_cast<float>(roi.y + y));
        pixels.push_back({row[x], std::hypot(p.x - med.x, p.y - med.y), p});
      }
    }
    const size_t wanted = params_.select - selection.size();
    const size_t n = std::min(wanted, pixels.size());
    std::partial_sort(pixels.begin(), pixels.begin() + n, pixels.end(),
                      [](const Pixel& a, const Pixel& b) {
                        return a.probability != b.probability ? a.probability > b.probability
                                                              : a.distance < b.distance;
                      });
    for (size_t i = 0; i < n; ++i) selection.push_back(make_feature(pixels[i].point));
  }
  // Line 23: the selection overwrites the first features; the others keep flowing.
  for (size_t i = 0; i < selection.size(); ++i) {
    if (i < features_.size()) {
      features_[i] = std::move(selection[i]);
    } else {
      features_.push_back(std::move(selection[i]));
    }
  }
}

void CfofTracker::centre_on_selection() {
  const size_t n = std::min<size_t>(features_.size(), params_.select);
  if (n == 0) return;
  cv::Point2d sum;
  for (size_t i = 0; i < n; ++i) sum += cv::Point2d(features_[i].point);
  centre_ = sum / static_cast<double>(n);
}

void CfofTracker::shift(cv::Point2d delta) {
  centre_ += delta;
  const cv::Point2f d(static_cast<float>(delta.x), static_cast<float>(delta.y));
  for (Feature& f : features_) {
    f.point += d;
    f.filter.translate(delta);
  }
  roi_filter_.translate(delta);
}

void CfofTracker::coast(CfofState state, cv::Point2d carry) {
  if (state_ == CfofState::tracking) coast_velocity_ = roi_filter_.velocity() - carry;
  if (state == CfofState::lost) coast_velocity_ = {};
  centre_ += carry + coast_velocity_;
  coast_velocity_ *= params_.coast_velocity_decay;
  features_.clear();
  state_ = state;
}

void CfofTracker::track(const CfofFrame& previous, const CfofFrame& current, bool hidden,
                        cv::Point2d carry) {
  const CfofState hidden_state = state_ == CfofState::lost ? CfofState::lost : CfofState::occluded;
  if (hidden) {
    coast(hidden_state, carry);
    return;
  }
  const bool resume = state_ != CfofState::tracking || features_.empty();
  // A part that never showed its colours (hidden in its first view) has none to be found by.
  if (resume && !colour_.learned()) {
    coast(hidden_state, carry);
    return;
  }
  if (resume) {
    // Alg. 2 lines 2-5: search again once the ROI (where it is expected) shows enough colour.
    const cv::Point2d expected =
        state_ == CfofState::tracking ? predicted_centre() : predicted_centre() + carry;
    if (coloured_pixels(current, roi_at(expected)) <
        params_.restart_color_fraction * initial_coloured_) {
      coast(hidden_state, carry);
      return;
    }
    centre_ = expected;
    search(current);
  } else {
    const cv::Point2d before = centre_;
    flow(previous, current);
    centre_on_selection();
    // §3.3.2: where the flow led, too little of the part's colour means it is hidden behind
    // something else; the flow is not trusted and the ROI coasts from where it was.
    if (coloured_pixels(current, roi_at(centre_)) <
        params_.occlusion_color_fraction * initial_coloured_) {
      centre_ = before;
      coast(CfofState::occluded, carry);
      return;
    }
  }
  cmdf(current);
  if (features_.empty()) {
    coast(CfofState::lost, carry);
    return;
  }
  centre_on_selection();
  if (resume) {
    roi_filter_ = PointKalman(centre_, params_.kalman, 100.0, coast_velocity_ + carry);
  } else {
    roi_filter_.predict();
    roi_filter_.correct(centre_);
  }
  state_ = CfofState::tracking;
}

}  // namespace simcap::tracker
