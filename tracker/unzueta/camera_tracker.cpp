#include "tracker/unzueta/camera_tracker.h"

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <utility>

#include "core/error.h"
#include "tracker/unzueta/limb_end.h"

namespace simcap::tracker {
namespace {

int part_index(Effector e) {
  if (e == Effector::pelvis) throw Error("the pelvis is not a CFOF part");
  return index_of(e);
}

}  // namespace

cv::Rect2d CameraTracker::part_box(const CfofTracker& t) const {
  const cv::Point2d c = t.predicted_centre();
  const cv::Size2d size = t.roi().size() * params_.part_box;
  return {c.x - 0.5 * size.width, c.y - 0.5 * size.height, size.width, size.height};
}

std::optional<LimbEnd> CameraTracker::far_end(Effector e, const CfofFrame& frame,
                                              const cv::Mat& silhouette,
                                              std::optional<cv::Point2d> root) const {
  const CfofTracker& t = parts_[part_index(e)];
  const cv::Point2d c = t.centre();
  const int half = static_cast<int>(std::ceil(params_.anchor_window * person_px_));
  const cv::Rect window =
      cv::Rect(static_cast<int>(std::lround(c.x)) - half, static_cast<int>(std::lround(c.y)) - half,
               2 * half + 1, 2 * half + 1) &
      cv::Rect(0, 0, frame.hsv.cols, frame.hsv.rows);
  if (window.empty()) return std::nullopt;
  const cv::Mat part = t.colour_probability(frame, window) >= std::ceil(params_.anchor_color * 255);
  std::optional<cv::Point2d> start;
  if (root) start = *root - cv::Point2d(window.tl());
  auto end = limb_end(part, silhouette(window), c - cv::Point2d(window.tl()),
                      params_.anchor_length[part_index(e)] * person_px_, start,
                      params_.anchor_root_tolerance * person_px_);
  if (!end) return std::nullopt;
  for (cv::Point& p : end->pixels) p += window.tl();
  end->centre += cv::Point2d(window.tl());
  return end;
}

void CameraTracker::refind(Effector e, const CfofFrame& frame, const cv::Mat& silhouette,
                           std::optional<cv::Point2d> root) {
  const int i = part_index(e);
  CfofTracker& t = parts_[i];
  untracked_[i] = t.state() == CfofState::tracking ? 0 : untracked_[i] + 1;
  const double reach = params_.refind_reach[i] * person_px_;
  // A part that never learnt its colours has nothing to be found by.
  if (reach <= 0 || !root || !t.learned() || untracked_[i] < params_.refind_patience) return;
  // The window holds a hand at the reach's end whole, so that a longer blob (an arm beyond
  // reach) is not cut to one that ends within it.
  const double length = params_.anchor_length[i] * person_px_;
  const int half = static_cast<int>(std::ceil(reach + length));
  const cv::Rect image(0, 0, frame.hsv.cols, frame.hsv.rows);
  const cv::Rect window =
      cv::Rect(static_cast<int>(std::lround(root->x)) - half,
               static_cast<int>(std::lround(root->y)) - half, 2 * half + 1, 2 * half + 1) &
      image;
  if (window.empty()) return;
  cv::Mat part = t.colour_probability(frame, window) >= std::ceil(params_.anchor_color * 255);
  // What another tracked part holds is that part's, not this one's (the head, the other hand).
  for (size_t j = 0; j < parts_.size(); ++j) {
    if (static_cast<int>(j) == i || parts_[j].state() != CfofState::tracking) continue;
    cv::Rect2d r = parts_[j].roi();
    r -= cv::Point2d(window.tl());
    part(cv::Rect(cv::Point(static_cast<int>(std::floor(r.x)), static_cast<int>(std::floor(r.y))),
                  cv::Point(static_cast<int>(std::ceil(r.br().x)),
                            static_cast<int>(std::ceil(r.br().y)))) &
         cv::Rect(0, 0, window.width, window.height))
        .setTo(0);
  }
  const cv::Point2d start = *root - cv::Point2d(window.tl());
  const auto end = limb_end(part, silhouette(window), start, length, start,
                            params_.anchor_root_tolerance * person_px_);
  if (!end) return;
  const cv::Point2d centre = end->centre + cv::Point2d(window.tl());
  if (std::hypot(centre.x - root->x, centre.y - root->y) > reach) return;
  if (!t.restart(frame, centre)) return;
  untracked_[i] = 0;
  surface_[i] = end->pixels;
  for (cv::Point& p : surface_[i]) p += window.tl();
}

CfofFrame CameraTracker::frame(const cv::Mat& bgr, const cv::Mat& silhouette) const {
  return CfofFrame::from_bgr(bgr, params_.colour_in_silhouette ? silhouette : cv::Mat(), cfof_);
}

void CameraTracker::start_lost(const cv::Mat& bgr, const cv::Mat& silhouette, double person_px) {
  person_px_ = person_px;
  cfof_ = params_.cfof.scaled_for(person_px_);
  pelvis_ = PelvisTracker(params_.pelvis.scaled_for(person_px_));
  previous_ = frame(bgr, silhouette);
  const auto pelvis = pelvis_.track(silhouette);
  pelvis_seen_ = pelvis.has_value();
  untracked_ = {};
  if (pelvis) pelvis_position_ = *pelvis;
  parts_.fill(CfofTracker(cfof_));
  for (auto& s : surface_) s.clear();
}

void CameraTracker::initialize(const cv::Mat& bgr, const cv::Mat& silhouette,
                               const InitialRegions& regions) {
  start_lost(bgr, silhouette, regions.person_px);
  int started = 0;
  for (Effector e : kEffectors) {
    if (e == Effector::pelvis) continue;
    CfofTracker& t = parts_[part_index(e)];
    if (!regions.roi[index_of(e)]) continue;
    try {
      t.initialize(previous_, *regions.roi[index_of(e)]);
      ++started;
    } catch (const Error&) {
      // A part whose ROI shows none of its colour starts lost; CFOF recovers it when it shows,
      // unless its ROI showed none of the person either: it has no colours and stays lost.
    }
  }
  if (started == 0) throw Error("CFOF: no body part could start in this camera");
}

void CameraTracker::track(const cv::Mat& bgr, const cv::Mat& silhouette,
                          const std::array<double, kEffectorCount>& depth,
                          const std::array<std::optional<cv::Point2d>, kEffectorCount>& root) {
  CfofFrame current = frame(bgr, silhouette);
  // §3.3.1: of two overlapping ROIs (where they are expected), the farther one is hidden -- by
  // a nearer part that is seen: two predicted parts moving together must not keep each other
  // hidden for ever.
  std::array<bool, kEffectorCount - 1> hidden{}, overlapping{};
  for (size_t i = 0; i < parts_.size(); ++i) {
    for (size_t j = i + 1; j < parts_.size(); ++j) {
      const CfofTracker &a = parts_[i], &b = parts_[j];
      if (a.state() == CfofState::lost || b.state() == CfofState::lost) continue;
      const cv::Rect2d ra = part_box(a), rb = part_box(b);
      const double overlap = (ra & rb).area();
      if (overlap < params_.overlap_fraction * std::min(ra.area(), rb.area())) continue;
      const double da = depth[i], db = depth[j];
      if (std::isnan(da) || std::isnan(db)) continue;
      const size_t far = da > db ? i : j, near = far == i ? j : i;
      if (parts_[near].state() == CfofState::tracking) hidden[far] = true;
      overlapping[i] = overlapping[j] = true;
    }
  }
  const auto pelvis = pelvis_.track(silhouette);
  cv::Point2d carry;
  if (pelvis) {
    if (pelvis_seen_ && params_.carry_with_pelvis) carry = *pelvis - pelvis_position_;
    pelvis_position_ = *pelvis;
    pelvis_seen_ = true;
  }
  for (size_t i = 0; i < parts_.size(); ++i) {
    parts_[i].track(previous_, current, hidden[i], carry);
    surface_[i].clear();
    for (const cv::Point2f& f : parts_[i].selection()) surface_[i].emplace_back(f);
    // Two overlapping parts may share one blob; neither is anchored on it.
    if (!params_.anchor || overlapping[i] || parts_[i].state() != CfofState::tracking ||
        !pelvis_seen_) {
      continue;
    }
    const auto end = far_end(static_cast<Effector>(i), current, silhouette, root[i]);
    const cv::Point2d shift = end ? end->centre - parts_[i].centre() : cv::Point2d();
    if (end && std::hypot(shift.x, shift.y) <=
                   params_.anchor_gate * params_.anchor_length[i] * person_px_) {
      parts_[i].shift(shift);
      surface_[i] = end->pixels;
    }
  }
  if (pelvis_seen_) {
    for (size_t i = 0; i < parts_.size(); ++i) {
      refind(static_cast<Effector>(i), current, silhouette, root[i]);
    }
  }
  previous_ = std::move(current);
}

void CameraTracker::correct(Effector e, cv::Point2d at) {
  const int i = part_index(e);
  CfofTracker& t = parts_[i];
  if (t.state() == CfofState::lost) {
    if (!t.restart(previous_, at)) return;
    untracked_[i] = 0;
  } else {
    t.shift(at - t.centre());
  }
  surface_[i].clear();
  for (const cv::Point2f& f : t.selection()) surface_[i].emplace_back(f);
}

void CameraTracker::borrow_colours(Effector e, const CameraTracker& donor, double scale) {
  parts_[part_index(e)].borrow_colours(donor.parts_[part_index(e)], scale);
}

void CameraTracker::swap(Effector a, Effector b) {
  const int i = part_index(a), j = part_index(b);
  std::swap(parts_[i], parts_[j]);
  std::swap(surface_[i], surface_[j]);
  std::swap(untracked_[i], untracked_[j]);
}

cv::Point2d CameraTracker::position(Effector e) const {
  return e == Effector::pelvis ? pelvis_position_ : parts_[part_index(e)].centre();
}

CfofState CameraTracker::state(Effector e) const {
  if (e == Effector::pelvis) {
    if (!pelvis_seen_) return CfofState::lost;
    return pelvis_.measured() ? CfofState::tracking : CfofState::occluded;
  }
  return parts_[part_index(e)].state();
}

const std::vector<cv::Point>& CameraTracker::surface(Effector e) const {
  return surface_[part_index(e)];
}

cv::Rect2d CameraTracker::roi(Effector e) const {
  return parts_[part_index(e)].roi();
}

}  // namespace simcap::tracker
