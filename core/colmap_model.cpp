#include "core/colmap_model.h"

#include <Eigen/Geometry>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/literal_text.h"

namespace simcap {

ColmapModel colmap_model(const std::vector<Camera>& cams,
                         const std::vector<std::string>& image_names) {
  if (image_names.size() != cams.size()) {
    throw Error("COLMAP model: " + std::to_string(image_names.size()) + " image names for " +
                std::to_string(cams.size()) + " cameras");
  }
  const std::string count = std::to_string(cams.size());
  ColmapModel m;
  m.cameras =
      "# Camera list with one line of data per camera:\n"
      "#   CAMERA_ID, MODEL, WIDTH, HEIGHT, PARAMS[]\n"
      "# Number of cameras: " +
      count + "\n";
  m.images =
      "# Image list with two lines of data per image:\n"
      "#   IMAGE_ID, QW, QX, QY, QZ, TX, TY, TZ, CAMERA_ID, NAME\n"
      "#   POINTS2D[] as (X, Y, POINT3D_ID)\n"
      "# Number of images: " +
      count + ", mean observations per image: 0\n";
  m.points3d =
      "# 3D point list with one line of data per point:\n"
      "#   POINT3D_ID, X, Y, Z, R, G, B, ERROR, TRACK[] as (IMAGE_ID, POINT2D_IDX)\n"
      "# Number of points: 0, mean track length: 0\n";
  for (size_t c = 0; c < cams.size(); ++c) {
    const Camera& cam = cams[c];
    const std::string id = std::to_string(c + 1);
    const bool full = cam.dist[4] != 0;
    m.cameras += id + (full ? " FULL_OPENCV " : " OPENCV ") + std::to_string(cam.width) + " " +
                 std::to_string(cam.height);
    for (const double v : {cam.K(0, 0), cam.K(1, 1), cam.K(0, 2) + 0.5, cam.K(1, 2) + 0.5,
                           cam.dist[0], cam.dist[1], cam.dist[2], cam.dist[3]}) {
      m.cameras += " " + shortest_text(v);
    }
    if (full) m.cameras += " " + shortest_text(cam.dist[4]) + " 0 0 0";
    m.cameras += "\n";

    Eigen::Quaterniond q(cam.R);
    q.normalize();
    if (q.w() < 0) q.coeffs() = -q.coeffs();
    m.images += id;
    for (const double v : {q.w(), q.x(), q.y(), q.z(), cam.t.x(), cam.t.y(), cam.t.z()}) {
      m.images += " " + shortest_text(v);
    }
    m.images += " " + id + " " + image_names[c] + "\n\n";
  }
  return m;
}

void write_colmap_model(const std::filesystem::path& folder, const std::vector<Camera>& cams,
                        const std::vector<std::string>& image_names) {
  const ColmapModel m = colmap_model(cams, image_names);
  write_text_atomic(folder / "cameras.txt", m.cameras);
  write_text_atomic(folder / "images.txt", m.images);
  write_text_atomic(folder / "points3D.txt", m.points3d);
}

}  // namespace simcap
