// Calibration as a COLMAP sparse model in its text format (cameras.txt, images.txt, an empty
// points3D.txt), so that COLMAP, nerfstudio, Gaussian-splatting and other SfM/MVS tools start
// from the exact rig instead of estimating it.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/camera.h"

namespace simcap {

struct ColmapModel {
  std::string cameras, images, points3d;  // the three files' text
};

// One COLMAP camera and one image per simcap camera, IDs 1, 2, ... in rig order.
// cameras.txt: model OPENCV (fx fy cx cy k1 k2 p1 p2) when k3 is zero, FULL_OPENCV
// (fx fy cx cy k1 k2 p1 p2 k3 k4 k5 k6, k4..k6 = 0) otherwise. COLMAP puts the centre of the
// top-left pixel at (0.5, 0.5) where OpenCV (and simcap) put it at (0, 0), so its cx and cy
// are simcap's plus 0.5. images.txt: QW QX QY QZ (world->camera rotation, QW >= 0), TX TY TZ
// (t, metres: X_cam = R X_world + t, as in simcap), the camera ID and `image_names[c]`,
// then an empty line of 2D points. The world is simcap's (+Y up).
ColmapModel colmap_model(const std::vector<Camera>& cams,
                         const std::vector<std::string>& image_names);
// Writes the three files into `folder` (each atomically), creating it.
void write_colmap_model(const std::filesystem::path& folder, const std::vector<Camera>& cams,
                        const std::vector<std::string>& image_names);

}  // namespace simcap
