// Where static scene objects hide the person from each camera, learned from the silhouettes: a
// body part that other cameras see but one camera does not is hidden from that one by whatever
// its empty-room plate shows there, so that camera abstains from carving the hull and from
// pulling the outline over that object.
#pragma once

#include <opencv2/core/mat.hpp>
#include <vector>

#include "core/camera.h"
#include "tracker/moschini/body_surface.h"

namespace simcap::tracker {

struct OcclusionOptions {
  double sample_step_m = 0.03;  // capsule axes are sampled this often
  // A capsule's cross-section (its projected disc) covered this little by a camera's silhouette
  // is hidden from it; covered this much, it is seen.
  double hidden_coverage = 0.2;
  double seen_coverage = 0.6;
  // A part counts as hidden from one camera only when this many others see it: a part the fit
  // misplaced lies off the silhouettes of several cameras, not of one.
  int confirming_cameras = 2;
  // Hidden samples a plate region needs before it counts as an occluder.
  int votes = 2;
  // A region stays an occluder while the person was never seen on it deeper than this margin
  // in front of where it was hidden there: a person passing in front of a pillar leaves it an
  // occluder, a person seen on the wall at the depth the fit once lost a limb proves the wall
  // is none.
  double depth_margin_m = 0.15;
  // The plate is cut into regions on a grid of cells this size: cells of one of this many
  // colours between the plate's Canny edges (grey, after a 3x3 blur).
  int cell_px = 4;
  int colour_classes = 10;
  double edge_low = 20, edge_high = 60;
  // Occluders widen a silhouette only this close to where the body was last seen: far from it
  // they would only let phantoms into the hull.
  double reach_px = 48;
};

class OcclusionMap {
 public:
  // `plates`: each camera's empty-room image (8-bit colour as Dataset::background() decodes it);
  // an empty one leaves that camera carving everywhere.
  OcclusionMap(const std::vector<Camera>& cameras, const std::vector<cv::Mat>& plates,
               const OcclusionOptions& options = {});

  // Adds one frame's evidence: the body's capsules placed at the fitted (or true) pose against
  // the frame's silhouettes, one per camera (8-bit, nonzero = person).
  void observe(const PlacedSurface& body, const std::vector<cv::Mat>& silhouettes);

  // Where a camera cannot see the person: 8-bit, 255 on the plate regions found to be occluders.
  cv::Mat blocked(int camera) const;
  // The silhouette with the camera's occluders near the body added: what the hull and the
  // outline cues read. The silhouette itself when no occluder is near the body.
  cv::Mat widen(int camera, const cv::Mat& silhouette) const;

 private:
  struct Region {
    float hidden = 0;  // nearest depth at which a part was hidden on this region
    float seen = 0;    // farthest depth at which a part was seen on it
    int hidden_votes = 0;
    int seen_votes = 0;
  };
  struct CameraRegions {
    cv::Mat labels;  // CV_32S per cell: the plate's regions from 1; 0 on edges and without a plate
    std::vector<Region> regions;
    std::vector<bool> occluder;  // per label, refreshed after each observe()
    // Per label: an occluder that can hide the body where it was last observed, i.e. some of
    // it lay deeper than the person was ever seen in front of that occluder.
    std::vector<bool> hides_body;
    cv::Rect body;  // the body's projection when last observed
  };
  // Fraction of the disc of `radius_px` around `pixel` on the silhouette.
  static double coverage(const cv::Mat& silhouette, const Eigen::Vector2d& pixel, double radius_px);
  bool is_occluder(const Region& region) const;
  // Per cell of `cells`, 255 on the regions `flags` marks; empty when there is none.
  cv::Mat mask(const CameraRegions& cam, const std::vector<bool>& flags,
               const cv::Rect& cells) const;

  const std::vector<Camera>* cameras_;
  OcclusionOptions options_;
  std::vector<CameraRegions> cameras_regions_;
};

}  // namespace simcap::tracker
