// What the monocular tracker sees in one frame, at its working resolution inside a crop around
// the person: the silhouette segmented into colour classes (the thesis's skin / head / clothes
// regions) and the distance to the nearest image edge inside the silhouette (its chamfer map).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "core/camera.h"
#include "tracker/gomez/colour_classes.h"
#include "tracker/gomez/label_renderer.h"

namespace simcap::tracker::gomez {

struct CueOptions {
  // The crop is shrunk by an integer factor so that the silhouette is about this tall (the
  // thesis tracked 160 x 120 images of a seated person).
  int work_height = 120;
  double margin = 0.3;  // crop margin around the boxes, a fraction of the silhouette's height
  // Canny's hysteresis thresholds on the working-resolution grey image (the thesis used a
  // Deriche filter; Canny is its usual stand-in), and the band in working pixels around the
  // silhouette inside which edges count, so that the outline itself is an edge.
  double canny_low = 30, canny_high = 90;
  int edge_band_px = 2;
};

struct FrameCues {
  View view;
  std::vector<std::uint8_t> cls;  // colour class per working pixel; 0: background, no class
  std::array<int, kMaxColourClasses + 1> class_area{};  // pixels per class
  std::vector<float> distance;                          // to the nearest image edge, working pixels
  std::vector<std::uint8_t> grey;  // the crop's grey at working resolution (the shading cue)
  float far = 0;                   // the largest distance (no edge at all: width + height)
  // The silhouette's lowest extent (full-resolution pixel coordinates, the bottom edge of its
  // lowest row): where the feet stand. NaN when the silhouette is empty or touches the image's
  // bottom (the feet are cut off).
  double feet_row = NAN;
  // Its highest extent (the top edge of its highest row); NaN when empty or touching the top.
  double top_row = NAN;
  cv::Mat small;  // the colour crop at working resolution (diagnostics)

  std::uint8_t cls_at(int u, int v) const { return cls[v * view.width + u]; }
};

// The silhouette's bounding box united with `hint` (e.g. where the previous estimate projects;
// may be empty), grown by the margin and clipped to the image, at the factor that brings the
// silhouette to about `work_height`. `image` CV_8UC3, `silhouette` CV_8UC1 at the camera's size.
// An empty silhouette gives a view of the hint alone (or the whole image).
FrameCues make_cues(const Camera& camera, const cv::Mat& image, const cv::Mat& silhouette,
                    const ColourClasses& classes, const cv::Rect& hint, const CueOptions& options);

}  // namespace simcap::tracker::gomez
