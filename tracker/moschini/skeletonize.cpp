#include "tracker/moschini/skeletonize.h"

#include <cmath>
#include <opencv2/imgproc.hpp>

namespace simcap::tracker {
namespace {

// Output buffers of connectedComponentsWithStats, reused from slice to slice.
struct Labels {
  cv::Mat labels, stats, centroids;
  std::vector<Eigen::Vector3d> moments;
};

template <typename ToBox>
void slice_blobs(const cv::Mat& slice, int axis, const Occupancy& occ, const SkeletonOptions& opt,
                 ToBox to_box, Labels& work, std::vector<CenterlinePoint>& out) {
  if (cv::countNonZero(slice) == 0) return;
  cv::Mat& labels = work.labels;
  cv::Mat& stats = work.stats;
  cv::Mat& centroids = work.centroids;
  const int n = cv::connectedComponentsWithStats(slice, labels, stats, centroids, 8, CV_32S);
  if (n <= 1) return;
  // Second moments per blob for the elongation test (connectedComponentsWithStats has none).
  std::vector<Eigen::Vector3d>& moments = work.moments;  // Σxx, Σyy, Σxy per blob
  moments.assign(n, Eigen::Vector3d::Zero());
  for (int r = 0; r < labels.rows; ++r) {
    const int* row = labels.ptr<int>(r);
    for (int c = 0; c < labels.cols; ++c) {
      const int l = row[c];
      if (l == 0) continue;
      const double dx = c - centroids.at<double>(l, 0), dy = r - centroids.at<double>(l, 1);
      moments[l] += Eigen::Vector3d(dx * dx, dy * dy, dx * dy);
    }
  }
  const double voxel_area = occ.grid.voxel * occ.grid.voxel;
  for (int l = 1; l < n; ++l) {
    const int area = stats.at<int>(l, cv::CC_STAT_AREA);
    if (area < opt.min_blob_voxels) continue;
    if (axis != 1 && opt.max_vertical_blob_m2 > 0 && area * voxel_area > opt.max_vertical_blob_m2) {
      continue;
    }
    const double cx = centroids.at<double>(l, 0), cy = centroids.at<double>(l, 1);
    const Eigen::Vector3d m = moments[l] / area;
    const double mean = 0.5 * (m.x() + m.y());
    const double spread = std::sqrt(0.25 * (m.x() - m.y()) * (m.x() - m.y()) + m.z() * m.z());
    const double major = mean + spread, minor = std::max(mean - spread, 0.0);
    // A one-voxel-wide blob has zero minor variance; the voxel's own extent (1/12) is its floor.
    const double elongation = std::sqrt((major + 1.0 / 12) / (minor + 1.0 / 12));
    if (elongation > opt.max_elongation) continue;
    if (opt.drop_centroids_outside) {
      const int ci = static_cast<int>(std::lround(cx)), ri = static_cast<int>(std::lround(cy));
      if (labels.at<int>(ri, ci) != l) continue;
    }
    const Eigen::Vector3d box = to_box(cy, cx);
    const Eigen::Vector3d voxel = box + occ.lo.cast<double>();
    out.push_back({occ.grid.origin + occ.grid.voxel * voxel, axis, area, elongation});
  }
}

}  // namespace

std::vector<CenterlinePoint> centerline(const Occupancy& occ, const SkeletonOptions& opt) {
  if (occ.count == 0) return {};
  const int sx = occ.size.x(), sy = occ.size.y(), sz = occ.size.z();
  // cells are (y, z, x): Y slices are (z rows, x cols) planes and Z slices are (y rows, x cols)
  // with a row step of sz·sx, both views; X slices need x outermost, so a (x, y, z) copy.
  std::vector<std::uint8_t> by_x;
  if (opt.sweep_x) {
    by_x.resize(occ.cells.size());
    for (int y = 0; y < sy; ++y)
      for (int z = 0; z < sz; ++z)
        for (int x = 0; x < sx; ++x)
          by_x[(static_cast<size_t>(x) * sy + y) * sz + z] =
              occ.cells[(static_cast<size_t>(y) * sz + z) * sx + x];
  }
  // Frames are processed in parallel by the caller, so the slices of one frame run in turn.
  std::vector<CenterlinePoint> points;
  Labels work;
  auto* cells = const_cast<std::uint8_t*>(occ.cells.data());  // cv::Mat views are read only here
  if (opt.sweep_x) {
    for (int i = 0; i < sx; ++i) {
      const cv::Mat slice(sy, sz, CV_8UC1, by_x.data() + static_cast<size_t>(i) * sy * sz);
      const double s = i;
      slice_blobs(
          slice, 0, occ, opt, [s](double r, double c) { return Eigen::Vector3d(s, r, c); }, work,
          points);
    }
  }
  if (opt.sweep_y) {
    for (int i = 0; i < sy; ++i) {
      const cv::Mat slice(sz, sx, CV_8UC1, cells + static_cast<size_t>(i) * sz * sx);
      const double s = i;
      slice_blobs(
          slice, 1, occ, opt, [s](double r, double c) { return Eigen::Vector3d(c, s, r); }, work,
          points);
    }
  }
  if (opt.sweep_z) {
    for (int i = 0; i < sz; ++i) {
      const cv::Mat slice(sy, sx, CV_8UC1, cells + static_cast<size_t>(i) * sx,
                          static_cast<size_t>(sz) * sx);
      const double s = i;
      slice_blobs(
          slice, 2, occ, opt, [s](double r, double c) { return Eigen::Vector3d(c, r, s); }, work,
          points);
    }
  }
  return points;
}

}  // namespace simcap::tracker
