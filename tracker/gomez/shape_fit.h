// The thesis's shape adjustment (§3.3): the capsules' radii scaled to the person in the first
// image, by Nelder-Mead on the silhouette's non-overlap with the body in its known first pose.
#pragma once

#include <opencv2/core/mat.hpp>

#include "core/camera.h"
#include "models/pose.h"
#include "models/skeleton.h"
#include "tracker/gomez/body_shape.h"

namespace simcap::tracker::gomez {

struct ShapeFitOptions {
  double lower = 0.7, upper = 1.4;  // box of every scale
  int evaluations = 200;
};

// The scales minimizing the non-overlap of the body rendered at full resolution in `pose` with
// `silhouette` (CV_8UC1) of `camera`. Unit scales when the silhouette is empty.
ShapeScales fit_shape(const Skeleton& skeleton, BodyKind kind, const Pose& pose,
                      const Camera& camera, const cv::Mat& silhouette,
                      const ShapeFitOptions& options = {});

}  // namespace simcap::tracker::gomez
