// Colored Features Optical Flow (Unzueta 2009 §3.1, Alg. 1-3): one body part followed by a flock
// of Shi-Tomasi features moved by pyramidal Lucas-Kanade, each checked by its own Kalman filter,
// and kept on the part by the Colored Maximum Distance Filter (CMDF) on an HS colour model.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "tracker/unzueta/hs_color_model.h"
#include "tracker/unzueta/point_kalman.h"

namespace simcap::tracker {

// Table 7's values are for the thesis' images (320x240, a person about 170 px tall); `scale`
// multiplies every length in pixels (CfofParams::scaled_for).
struct CfofParams {
  int select = 10;         // nSelect, "number of flock features"
  int max_detect = 30;     // nMaxDetect, features searched (3x nSelect: the text's "higher number")
  double max_dist = 50.0;  // maxDist, px from the flock's median
  double min_color = 0.01;  // minColor, colour probability
  int lk_window = 10;       // PyrLK window side, px
  int lk_levels = 3;        // pyramid levels (maxLevel = levels - 1)
  PointKalmanNoise kalman;  // per feature and for the ROI
  // A feature whose optical-flow position lies further from its Kalman prediction than this
  // Mahalanobis distance is an outlier (Alg. 2 line 9; the thesis parameterizes the distance
  // with the prior covariance without giving the factor).
  double kalman_gate = 6.0;
  // Restart (Alg. 2 line 3) when the ROI holds at least this fraction of the coloured pixels it
  // held at initialization (minNColorPixels).
  double restart_color_fraction = 0.3;
  // §3.3.2: fewer coloured pixels than this fraction of the initial count means the part is
  // hidden behind something of another colour.
  double occlusion_color_fraction = 0.15;
  // While hidden the ROI keeps moving with its Kalman velocity, shrunk by this factor per frame
  // (between the thesis' two options: "will not move" and "continues its trajectory").
  double coast_velocity_decay = 0.8;
  // CMDF fills a short selection with the ROI's most probable coloured pixels (Alg. 3 lines
  // 13-21); off: it searches Shi-Tomasi corners on the part's colour instead.
  bool fill_with_colour = true;
  double shi_tomasi_quality = 0.01;
  double shi_tomasi_min_distance = 3.0;  // px; only for the search, as in the thesis

  // These parameters for a person `person_px` tall in the image (170 px: the thesis' scale).
  CfofParams scaled_for(double person_px) const;
};

// What CFOF reads of one frame; built once and shared by every tracked part.
struct CfofFrame {
  cv::Mat grey;
  std::vector<cv::Mat> pyramid;  // cv::buildOpticalFlowPyramid of `grey`
  cv::Mat hsv;                   // CV_8UC3, OpenCV HSV
  cv::Mat mask;                  // optional CV_8UC1 foreground; colour only counts inside it
  // Builds the pyramid for `params` from a BGR image.
  static CfofFrame from_bgr(const cv::Mat& bgr, const cv::Mat& mask, const CfofParams& params);
};

enum class CfofState { tracking, occluded, lost };
const char* cfof_state_name(CfofState state);

class CfofTracker {
 public:
  explicit CfofTracker(const CfofParams& params = {}) : params_(params) {}

  // Alg. 1: learns the part's colours in the centre of `roi`, searches features in it, starts
  // their filters and centres the ROI on the CMDF selection. Throws Error when the ROI holds no
  // pixel of the part.
  void initialize(const CfofFrame& frame, cv::Rect2d roi);
  // Starts the part again at `centre` in `frame` with the colours it learnt at initialization
  // (e.g. where its limb is found after it was lost): as Alg. 2's restart, only when that ROI
  // holds enough of the part's colour (restart_color_fraction). Returns whether it tracks.
  bool restart(const CfofFrame& frame, cv::Point2d centre);
  // Takes `donor`'s colours (the same part as another camera learnt them) when this part learnt
  // none (its first ROI held none of it), with an ROI `scale` times the donor's: the part can
  // then be restarted where the other cameras put it. No-op when it has colours of its own.
  void borrow_colours(const CfofTracker& donor, double scale);
  // Alg. 2 on the next frame. When `hidden` (another tracked part lies in front, §3.3.1) the
  // optical flow stops: the features are dropped and the ROI coasts on its Kalman filter.
  // `carry` is how far the body the part belongs to moved since the previous frame (e.g. the
  // pelvis' image motion): an ROI that is not tracked moves with it, plus its own decaying
  // velocity relative to it, so that a part hidden while the person walks stays on the person.
  void track(const CfofFrame& previous, const CfofFrame& current, bool hidden = false,
             cv::Point2d carry = {});

  cv::Point2d centre() const { return centre_; }
  cv::Rect2d roi() const;
  // Where the ROI is expected in the next frame (its Kalman prediction without advancing it).
  cv::Point2d predicted_centre() const;
  CfofState state() const { return state_; }
  // Moves the ROI and its features by `delta` px (a correction from outside CFOF).
  void shift(cv::Point2d delta);
  // Colour probability (0-255) of the pixels of `roi` (HsColorModel::back_project).
  cv::Mat colour_probability(const CfofFrame& frame, cv::Rect roi) const {
    return colour_.back_project(frame.hsv, roi, frame.mask);
  }
  // Whether the part learnt its colours (its first ROI held some of it).
  bool learned() const { return colour_.learned(); }
  // The first nSelect features (the selection the ROI is centred on).
  std::vector<cv::Point2f> selection() const;
  const CfofParams& params() const { return params_; }

 private:
  struct Feature {
    cv::Point2f point;
    PointKalman filter;
  };
  int coloured_pixels(const CfofFrame& frame, cv::Rect roi) const;
  void search(const CfofFrame& frame);
  void flow(const CfofFrame& previous, const CfofFrame& current);
  void cmdf(const CfofFrame& frame);
  void centre_on_selection();
  // Searches, selects and centres the flock at `centre_` and starts its filters.
  void start(const CfofFrame& frame);
  void coast(CfofState state, cv::Point2d carry);
  cv::Rect roi_at(cv::Point2d centre) const;
  Feature make_feature(cv::Point2f p) const;

  CfofParams params_;
  HsColorModel colour_;
  cv::Size2d size_;
  cv::Point2d centre_;
  PointKalman roi_filter_{cv::Point2d()};
  cv::Point2d coast_velocity_;  // relative to the carrying body's motion
  std::vector<Feature> features_;
  int initial_coloured_ = 0;
  CfofState state_ = CfofState::lost;
};

}  // namespace simcap::tracker
