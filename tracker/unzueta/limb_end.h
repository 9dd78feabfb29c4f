// Where a limb ends in the image: the part of a coloured blob farthest, along the blob, from where
// the body continues into it. CFOF's anchoring of end-effectors on untextured renders.
#pragma once

#include <opencv2/core.hpp>
#include <optional>
#include <vector>

namespace simcap::tracker {

// `part` and `body` (CV_8UC1, same size; nonzero = set) are a window of the part's colour mask and
// of the silhouette. The blob is the part pixels 8-connected to the part pixel nearest `near`.
// The body enters the blob where a blob pixel touches a body pixel of another colour (two
// pixels inside the silhouette's rim) -- with a `root` (where the limb starts, e.g. the
// shoulder), only at the contacts within `root_tolerance` px of the one nearest it, so that a hand
// lying on the thigh is not taken for the arm's start -- or, when it touches none, at the
// window's border; geodesic distances (8-neighbour steps of 1 and sqrt 2, inside the blob) run
// from there. The part is the blob pixels within `length` px of the largest distance; returns
// them and their mean (window coordinates); nullopt when `part` is empty or nothing enters the
// blob.
struct LimbEnd {
  cv::Point2d centre;
  std::vector<cv::Point> pixels;
};
std::optional<LimbEnd> limb_end(const cv::Mat& part, const cv::Mat& body, cv::Point2d near,
                                double length, std::optional<cv::Point2d> root = {},
                                double root_tolerance = 0);

}  // namespace simcap::tracker
