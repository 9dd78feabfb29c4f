#include "tracker/moschini/occlusion_map.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace simcap::tracker {

namespace {

constexpr std::uint8_t kEdge = 255;  // a cell on an edge of the plate: in no region

// The plate cut into regions, one label per cell from 1 (0 on the plate's edges): cells are
// clustered by colour (k-means in Lab), cells with a Canny edge of the plate are set apart, and
// each cluster splits into 4-connected components. Colour alone merges a pillar with a wall of
// a like colour where they meet; edges alone leak through a faint stretch of an outline.
cv::Mat plate_regions(const cv::Mat& plate, const OcclusionOptions& o) {
  const int cell = o.cell_px;
  const cv::Size cells((plate.cols + cell - 1) / cell, (plate.rows + cell - 1) / cell);
  cv::Mat small, lab, grey, edges, edge_cells;
  // Fewer cells than colours (a tiny image): nothing to cluster, the plate is one region.
  if (cells.area() < o.colour_classes) return cv::Mat(cells, CV_32S, cv::Scalar(1));
  cv::resize(plate, small, cells, 0, 0, cv::INTER_AREA);
  small.convertTo(small, CV_32FC3, 1.0 / 255);
  cv::cvtColor(small, lab, cv::COLOR_BGR2Lab);
  cv::Mat samples = lab.reshape(1, static_cast<int>(lab.total())), cluster, centres;
  // k-means++ seeding draws from OpenCV's RNG: a fixed state keeps the regions reproducible.
  cv::theRNG().state = 0x5eed;
  cv::kmeans(samples, o.colour_classes, cluster,
             cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 20, 0.1), 1,
             cv::KMEANS_PP_CENTERS, centres);
  cv::Mat classes = cluster.reshape(1, cells.height);
  classes.convertTo(classes, CV_8U);
  cv::medianBlur(classes, classes, 3);
  cv::cvtColor(plate, grey, cv::COLOR_BGR2GRAY);
  cv::GaussianBlur(grey, grey, cv::Size(3, 3), 0);
  cv::Canny(grey, edges, o.edge_low, o.edge_high);
  cv::resize(edges, edge_cells, cells, 0, 0, cv::INTER_AREA);
  classes.setTo(kEdge, edge_cells > 0);
  cv::Mat regions(cells, CV_32S, cv::Scalar(0)), component;
  int next = 1;
  for (int k = 0; k < o.colour_classes; ++k) {
    const int n = cv::connectedComponents(classes == k, component, 4, CV_32S);
    for (int v = 0; v < cells.height; ++v) {
      const int* in = component.ptr<int>(v);
      int* out = regions.ptr<int>(v);
      for (int u = 0; u < cells.width; ++u) {
        if (in[u] > 0) out[u] = next + in[u] - 1;
      }
    }
    next += n - 1;
  }
  return regions;
}

}  // namespace

OcclusionMap::OcclusionMap(const std::vector<Camera>& cameras, const std::vector<cv::Mat>& plates,
                           const OcclusionOptions& options)
    : cameras_(&cameras), options_(options), cameras_regions_(cameras.size()) {
  const int cell = options.cell_px;
  for (size_t c = 0; c < cameras.size(); ++c) {
    CameraRegions& cam = cameras_regions_[c];
    if (c < plates.size() && !plates[c].empty()) {
      cam.labels = plate_regions(plates[c], options);
    } else {
      cam.labels = cv::Mat((cameras[c].height + cell - 1) / cell,
                           (cameras[c].width + cell - 1) / cell, CV_32S, cv::Scalar(0));
    }
    double most = 0;
    cv::minMaxLoc(cam.labels, nullptr, &most);
    cam.regions.resize(static_cast<size_t>(most) + 1);
    cam.occluder.assign(cam.regions.size(), false);
  }
}

double OcclusionMap::coverage(const cv::Mat& silhouette, const Eigen::Vector2d& pixel,
                              double radius_px) {
  // The centre and eight points at 70% of the radius: enough to tell a part on the silhouette
  // from one cut off it, at nine lookups.
  int inside = 0, total = 0;
  for (int k = -1; k < 8; ++k) {
    const double a = k * M_PI / 4, r = k < 0 ? 0.0 : 0.7 * radius_px;
    const int u = static_cast<int>(std::lround(pixel.x() + r * std::cos(a)));
    const int v = static_cast<int>(std::lround(pixel.y() + r * std::sin(a)));
    if (u < 0 || v < 0 || u >= silhouette.cols || v >= silhouette.rows) continue;
    ++total;
    inside += silhouette.at<std::uint8_t>(v, u) ? 1 : 0;
  }
  return total ? static_cast<double>(inside) / total : 0.0;
}

bool OcclusionMap::is_occluder(const Region& r) const {
  return r.hidden_votes >= options_.votes &&
         (r.seen_votes == 0 || r.seen < r.hidden - static_cast<float>(options_.depth_margin_m));
}

void OcclusionMap::observe(const PlacedSurface& body, const std::vector<cv::Mat>& silhouettes) {
  const int nc = static_cast<int>(cameras_regions_.size());
  const int cell = options_.cell_px;
  struct Sample {
    Eigen::Vector2d pixel;
    double depth = 0, coverage = 0;
    bool in_view = false;
  };
  std::vector<Sample> samples(nc);
  std::vector<cv::Rect> extent(nc);
  std::vector<double> deepest(nc, 0.0);
  for (const PlacedCapsule& capsule : body) {
    const int steps =
        std::max(1, static_cast<int>(std::ceil(capsule.ab.norm() / options_.sample_step_m)));
    for (int s = 0; s <= steps; ++s) {
      const double t = static_cast<double>(s) / steps;
      const Eigen::Vector3d x = capsule.a + t * capsule.ab;
      int seen_by = 0;
      for (int c = 0; c < nc; ++c) {
        const Camera& cam = (*cameras_)[c];
        Sample& sample = samples[c];
        sample.in_view = cam.in_frustum(x);
        if (!sample.in_view) continue;
        const Eigen::Vector3d xc = cam.to_camera(x);
        sample.depth = xc.z();
        deepest[c] = std::max(deepest[c], sample.depth);
        sample.pixel = cam.project_camera(xc);
        const double radius_px = cam.K(0, 0) * capsule.radius(t) / sample.depth;
        sample.coverage = coverage(silhouettes[c], sample.pixel, radius_px);
        seen_by += sample.coverage >= options_.seen_coverage ? 1 : 0;
        const int reach = static_cast<int>(radius_px);
        extent[c] |=
            cv::Rect(static_cast<int>(sample.pixel.x()) - reach,
                     static_cast<int>(sample.pixel.y()) - reach, 2 * reach + 1, 2 * reach + 1);
      }
      for (int c = 0; c < nc; ++c) {
        const Sample& sample = samples[c];
        if (!sample.in_view) continue;
        const int u =
            std::clamp(static_cast<int>(std::lround(sample.pixel.x())), 0, silhouettes[c].cols - 1);
        const int v =
            std::clamp(static_cast<int>(std::lround(sample.pixel.y())), 0, silhouettes[c].rows - 1);
        CameraRegions& cam = cameras_regions_[c];
        const int label = cam.labels.at<int>(v / cell, u / cell);
        if (label == 0) continue;
        Region& region = cam.regions[label];
        const auto depth = static_cast<float>(sample.depth);
        // Seen evidence needs the axis's own pixel on the silhouette: a part beside an
        // occluder's edge covers some of its region with a disc, never with its axis.
        if (sample.coverage >= options_.seen_coverage && silhouettes[c].at<std::uint8_t>(v, u)) {
          region.seen = region.seen_votes++ ? std::max(region.seen, depth) : depth;
        } else if (sample.coverage <= options_.hidden_coverage &&
                   seen_by >= options_.confirming_cameras) {
          region.hidden = region.hidden_votes++ ? std::min(region.hidden, depth) : depth;
        }
      }
    }
  }
  for (int c = 0; c < nc; ++c) {
    CameraRegions& cam = cameras_regions_[c];
    cam.body = extent[c];
    cam.hides_body.assign(cam.regions.size(), false);
    for (size_t r = 1; r < cam.regions.size(); ++r) {
      const Region& region = cam.regions[r];
      cam.occluder[r] = is_occluder(region);
      cam.hides_body[r] = cam.occluder[r] && (region.seen_votes == 0 ||
                                              deepest[c] > region.seen + options_.depth_margin_m);
    }
  }
}

cv::Mat OcclusionMap::mask(const CameraRegions& cam, const std::vector<bool>& flags,
                           const cv::Rect& cells) const {
  cv::Mat out(cells.size(), CV_8U, cv::Scalar(0));
  bool any = false;
  for (int v = 0; v < cells.height; ++v) {
    const int* labels = cam.labels.ptr<int>(cells.y + v) + cells.x;
    std::uint8_t* row = out.ptr<std::uint8_t>(v);
    for (int u = 0; u < cells.width; ++u) {
      if (flags[labels[u]]) row[u] = 255, any = true;
    }
  }
  if (!any) return {};
  // An occluder's outline lies on edge cells, which belong to no region: they join it.
  cv::Mat grown;
  cv::dilate(out, grown, cv::getStructuringElement(cv::MORPH_RECT, {3, 3}));
  out.setTo(255, grown & (cam.labels(cells) == 0));
  return out;
}

cv::Mat OcclusionMap::blocked(int camera) const {
  const CameraRegions& cam = cameras_regions_[camera];
  const cv::Mat cells = mask(cam, cam.occluder, cv::Rect(0, 0, cam.labels.cols, cam.labels.rows));
  const Camera& c = (*cameras_)[camera];
  if (cells.empty()) return cv::Mat(c.height, c.width, CV_8U, cv::Scalar(0));
  cv::Mat pixels;
  cv::resize(cells, pixels, cv::Size(cells.cols * options_.cell_px, cells.rows * options_.cell_px),
             0, 0, cv::INTER_NEAREST);
  return pixels(cv::Rect(0, 0, c.width, c.height)).clone();
}

cv::Mat OcclusionMap::widen(int camera, const cv::Mat& silhouette) const {
  const CameraRegions& cam = cameras_regions_[camera];
  const int cell = options_.cell_px;
  const int reach = static_cast<int>(options_.reach_px);
  cv::Rect near = cam.body;
  near.x -= reach, near.y -= reach, near.width += 2 * reach, near.height += 2 * reach;
  near &= cv::Rect(0, 0, silhouette.cols, silhouette.rows);
  if (near.empty()) return silhouette;
  const cv::Rect cells(near.x / cell, near.y / cell, (near.br().x - 1) / cell - near.x / cell + 1,
                       (near.br().y - 1) / cell - near.y / cell + 1);
  if (cam.hides_body.empty()) return silhouette;
  const cv::Mat occluders = mask(cam, cam.hides_body, cells);
  if (occluders.empty()) return silhouette;
  cv::Mat out = silhouette.clone();
  for (int v = near.y; v < near.br().y; ++v) {
    const std::uint8_t* blocked = occluders.ptr<std::uint8_t>(v / cell - cells.y);
    std::uint8_t* row = out.ptr<std::uint8_t>(v);
    for (int u = near.x; u < near.br().x; ++u) {
      if (blocked[u / cell - cells.x]) row[u] = 255;
    }
  }
  return out;
}

}  // namespace simcap::tracker
