#include "tracker/moschini/inspection.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "core/csv.h"
#include "core/image_io.h"
#include "tracker/common/mask_box.h"
#include "tracker/moschini/rim.h"

namespace simcap::tracker {
namespace {

const cv::Scalar kEdge(0, 255, 255), kCenterline(255, 0, 255), kInside(0, 200, 0),
    kOutside(0, 0, 255), kStick(255, 128, 0), kJoint(255, 255, 255);

// The person's part of a camera's image, enlarged so that the drawing stays legible when the
// person fills a small part of the view.
struct Crop {
  cv::Rect box;
  double scale = 1;
  cv::Point map(const Eigen::Vector2d& p) const {
    return {static_cast<int>(std::lround((p.x() - box.x + 0.5) * scale - 0.5)),
            static_cast<int>(std::lround((p.y() - box.y + 0.5) * scale - 0.5))};
  }
};

Crop crop_for(const Camera& cam, const SilhouetteView* view,
              const std::vector<Eigen::Vector3d>& joints) {
  cv::Rect box = view && !view->empty() ? mask_box(view->silhouette()) : cv::Rect();
  for (const Eigen::Vector3d& j : joints) {
    if (const auto px = cam.project(j)) {
      const cv::Rect at(static_cast<int>(std::floor(px->x())),
                        static_cast<int>(std::floor(px->y())), 1, 1);
      box = box.empty() ? at : box | at;
    }
  }
  const int margin = 24;
  box = cv::Rect(box.x - margin, box.y - margin, box.width + 2 * margin, box.height + 2 * margin) &
        cv::Rect(0, 0, cam.width, cam.height);
  if (box.empty()) box = cv::Rect(0, 0, cam.width, cam.height);
  return {box, std::clamp(480.0 / box.height, 1.0, 4.0)};
}

cv::Mat camera_image(const Dataset& dataset, const SilhouetteView* view, int camera,
                     const Observation& obs, const PlacedSurface& surface, const StickGeometry& g,
                     const std::vector<Eigen::Vector3d>& joints) {
  const Camera& cam = dataset.cameras()[camera];
  cv::Mat full;
  if (std::filesystem::exists(dataset.image_path(camera, "rgb", obs.frame))) {
    full = dataset.rgb(camera, obs.frame);
  } else {
    cv::cvtColor(dataset.mask(camera, obs.frame), full, cv::COLOR_GRAY2BGR);
  }
  const Crop crop = crop_for(cam, view, joints);
  cv::Mat image;
  cv::resize(full(crop.box), image, {}, crop.scale, crop.scale, cv::INTER_NEAREST);
  auto dot = [&](const Eigen::Vector3d& x, int radius, const cv::Scalar& colour, int thickness) {
    if (const auto px = cam.project(x)) cv::circle(image, crop.map(*px), radius, colour, thickness);
  };
  if (view && !view->empty()) {
    std::vector<std::vector<cv::Point>> edges;
    cv::findContours(view->silhouette()(crop.box).clone(), edges, cv::RETR_LIST,
                     cv::CHAIN_APPROX_NONE);
    for (auto& edge : edges) {
      for (cv::Point& p : edge) p = crop.map(Eigen::Vector2d(p.x + crop.box.x, p.y + crop.box.y));
    }
    cv::polylines(image, edges, true, kEdge, 1);
  }
  for (const Eigen::Vector3d& p : obs.points) dot(p, 2, kCenterline, cv::FILLED);
  if (view && !view->empty()) {
    for_each_rim_point(*view, surface, 0.02, [&](const RimPoint& rim) {
      dot(rim.point, 2, rim.outside ? kOutside : kInside, cv::FILLED);
    });
  }
  for (int s = 0; s < kSegmentCount; ++s) {
    const auto a = cam.project(g.proximal[s]), b = cam.project(g.distal[s]);
    if (a && b) cv::line(image, crop.map(*a), crop.map(*b), kStick, 2, cv::LINE_AA);
  }
  for (const Eigen::Vector3d& j : joints) dot(j, 4, kJoint, 2);
  const std::string title = "frame " + std::to_string(obs.frame) + ", " + cam.name;
  cv::putText(image, title, {8, 20}, cv::FONT_HERSHEY_SIMPLEX, 0.5, kJoint, 1, cv::LINE_AA);
  cv::Mat rgb;  // write_image takes RGB order
  cv::cvtColor(image, rgb, cv::COLOR_BGR2RGB);
  return rgb;
}

}  // namespace

void write_inspection(const std::filesystem::path& dir, const Dataset& dataset,
                      const Observation& obs, const MoschiniTracker& tracker,
                      const StickPose& pose) {
  std::filesystem::create_directories(dir);
  const StickGeometry g = tracker.model().geometry(pose);
  const PlacedSurface surface = place(tracker.surface(), g);
  const std::vector<Eigen::Vector3d> joints = tracker.model().he15(pose);
  for (int c = 0; c < dataset.camera_count(); ++c) {
    const SilhouetteView* view = c < static_cast<int>(obs.views.size()) ? &obs.views[c] : nullptr;
    char name[32];
    std::snprintf(name, sizeof name, "cam%02d.png", c);
    write_image(dir / name, camera_image(dataset, view, c, obs, surface, g, joints));
  }
  CsvWriter hull(dir / "hull.csv", {"x", "y", "z"});
  const Occupancy& occ = obs.hull;
  char line[96];
  for (int y = 0; y < occ.size.y(); ++y) {
    for (int z = 0; z < occ.size.z(); ++z) {
      for (int x = 0; x < occ.size.x(); ++x) {
        if (!occ.cells[(static_cast<size_t>(y) * occ.size.z() + z) * occ.size.x() + x]) continue;
        const Eigen::Vector3d p = occ.grid.center(occ.lo + Eigen::Vector3i(x, y, z));
        std::snprintf(line, sizeof line, "%.3f,%.3f,%.3f\n", p.x(), p.y(), p.z());
        hull.out() << line;
      }
    }
  }
  hull.commit();
}

}  // namespace simcap::tracker
