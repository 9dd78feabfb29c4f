// Where CFOF starts in one camera (Unzueta 2009 §3.4): the ROIs of head, hands and feet on the
// first frame, found in the calibration posture from the silhouette, or (--init gt, for
// diagnosis) around each part's pixels in the dataset's part-label image.
#pragma once

#include <array>
#include <filesystem>
#include <opencv2/core.hpp>
#include <optional>

#include "tracker/unzueta/effectors.h"

namespace simcap::tracker {

struct InitialRegions {
  // Indexed by index_of(Effector); the pelvis entry is unused. nullopt: the part is not seen.
  std::array<std::optional<cv::Rect2d>, kEffectorCount> roi;
  double person_px = 0;  // the person's height in the image (the silhouette's), px
};

// The calibration posture, facing the camera: feet apart on the floor, upper arms out to the
// sides and forearms up, hands beside the head (the thesis' Fig. 21 and "initial" action).
// From the largest blob of `mask` (CV_8UC1): each foot at the lowest silhouette point on its
// side of the median column, each hand at the highest one beyond a head's width from it, the
// head where the thesis finds the face: the first silhouette pixel from the top in the column
// midway between the hands. The person's left is the image's right. Throws Error when the mask
// holds no blob or the posture is not found (a hand or foot missing).
InitialRegions calibration_posture_regions(const cv::Mat& mask);

// Around each part's pixels in a part-label image (`labels`, CV_8UC1 or CV_16UC1: 1 + the
// joint index of `parts_json`'s legend, 0 = background): the box of the part's pixels, widened
// to a square no smaller than calibration_posture_regions' for the person's size. The person's
// height is that of all labelled pixels. Parts with fewer than `min_pixels` pixels are left unset
// (hidden in this view).
InitialRegions labelled_part_regions(const cv::Mat& labels, const std::filesystem::path& parts_json,
                                     int min_pixels = 12);

}  // namespace simcap::tracker
