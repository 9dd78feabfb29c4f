// The first pose without ground truth (--init auto): the thesis assumes a person facing the camera
// with no self-occlusion on the first image; simcap's datasets show people standing, so the start
// is an upright person on the floor (y = 0), facing the camera, arms hanging, as tall as the
// silhouette's top row is above its bottom row, then fitted to the silhouette by Nelder-Mead.
#pragma once

#include <opencv2/core/mat.hpp>

#include "core/camera.h"
#include "models/pose.h"
#include "models/skeleton.h"
#include "tracker/gomez/frame_cues.h"
#include "tracker/gomez/registration.h"

namespace simcap::tracker::gomez {

struct UprightStart {
  Skeleton skeleton;  // build_humanoid at the estimated height
  Pose pose;          // standing at the feet's floor point, facing the camera
  double height = 0;  // metres
};

// From a silhouette (CV_8UC1) of one camera. Throws Error when the silhouette is empty or its
// lowest row's sight line does not reach the floor in front of the camera.
UprightStart upright_start(const Camera& camera, const cv::Mat& silhouette);

// The full-body pose closest to the silhouette from `start`: its region non-overlap (one class:
// the whole silhouette) minimized by Nelder-Mead (`options.evaluations` of them).
Pose fit_silhouette(const UprightStart& start, const Camera& camera, const cv::Mat& silhouette,
                    const CueOptions& cues, const RegistrationOptions& options);

}  // namespace simcap::tracker::gomez
