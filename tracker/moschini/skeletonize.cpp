#include "tracker/moschini/skeletonize.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

namespace simcap::tracker {
namespace {

// Output buffers of connectedComponentsWithStats, reused from slice to slice.
struct Labels {
  cv::Mat labels, stats, centroids;
  std::vector<Eigen::Vector3d> moments;
};

// Rows and columns a slice's occupied cells span. Only that part of a slice is labelled: the
// labelling costs per cell, and most of a slice of the body's box is empty (a leg's cross-section
// in a horizontal slice).
struct Span {
  int r0 = std::numeric_limits<int>::max(), r1 = -1, c0 = std::numeric_limits<int>::max(), c1 = -1;
  void add(int r, int c) {
    r0 = std::min(r0, r), r1 = std::max(r1, r), c0 = std::min(c0, c), c1 = std::max(c1, c);
  }
  // Starts on even rows and columns, as the whole slice does, so that the labelling's 2x2 blocks
  // and hence its label order are the whole slice's: the points come out in the same order.
  cv::Rect rect() const {
    const int r = r0 & ~1, c = c0 & ~1;
    return {c, r, c1 + 1 - c, r1 + 1 - r};
  }
};

template <typename ToBox>
void slice_blobs(const cv::Mat& slice, const Span& span, int axis, const Occupancy& occ,
                 const SkeletonOptions& opt, ToBox to_box, Labels& work,
                 std::vector<CenterlinePoint>& out) {
  if (span.r1 < 0) return;
  const cv::Rect roi = span.rect();
  cv::Mat& labels = work.labels;
  cv::Mat& stats = work.stats;
  cv::Mat& centroids = work.centroids;
  const int n = cv::connectedComponentsWithStats(slice(roi), labels, stats, centroids, 8, CV_32S);
  if (n <= 1) return;
  // The centroids in the whole slice's coordinates, exactly as labelling it whole gives them:
  // the sums of the cells' coordinates are integers (recovered from the mean) over the area.
  const long long offset[2] = {roi.x, roi.y};
  for (int l = 1; l < n; ++l) {
    const long long area = stats.at<int>(l, cv::CC_STAT_AREA);
    double* c = centroids.ptr<double>(l);
    for (int a = 0; a < 2; ++a) {
      const long long sum = std::llround(c[a] * static_cast<double>(area)) + offset[a] * area;
      c[a] = static_cast<double>(sum) / static_cast<double>(area);
    }
  }
  // Second moments per blob for the elongation test (connectedComponentsWithStats has none).
  std::vector<Eigen::Vector3d>& moments = work.moments;  // Σxx, Σyy, Σxy per blob
  moments.assign(n, Eigen::Vector3d::Zero());
  for (int r = 0; r < labels.rows; ++r) {
    const int* row = labels.ptr<int>(r);
    for (int c = 0; c < labels.cols; ++c) {
      const int l = row[c];
      if (l == 0) continue;
      const double dx = c + roi.x - centroids.at<double>(l, 0);
      const double dy = r + roi.y - centroids.at<double>(l, 1);
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
      if (!roi.contains({ci, ri}) || labels.at<int>(ri - roi.y, ci - roi.x) != l) continue;
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
  std::vector<Span> x_spans(opt.sweep_x ? sx : 0), y_spans(opt.sweep_y ? sy : 0),
      z_spans(opt.sweep_z ? sz : 0);
  for (int y = 0; y < sy; ++y)
    for (int z = 0; z < sz; ++z) {
      const std::uint8_t* row = &occ.cells[(static_cast<size_t>(y) * sz + z) * sx];
      for (int x = 0; x < sx; ++x) {
        if (!row[x]) continue;
        if (opt.sweep_x) x_spans[x].add(y, z);
        if (opt.sweep_y) y_spans[y].add(z, x);
        if (opt.sweep_z) z_spans[z].add(y, x);
      }
    }
  // Frames are processed in parallel by the caller, so the slices of one frame run in turn.
  std::vector<CenterlinePoint> points;
  Labels work;
  auto* cells = const_cast<std::uint8_t*>(occ.cells.data());  // cv::Mat views are read only here
  for (int i = 0; i < static_cast<int>(x_spans.size()); ++i) {
    const cv::Mat slice(sy, sz, CV_8UC1, by_x.data() + static_cast<size_t>(i) * sy * sz);
    const double s = i;
    slice_blobs(
        slice, x_spans[i], 0, occ, opt,
        [s](double r, double c) { return Eigen::Vector3d(s, r, c); }, work, points);
  }
  for (int i = 0; i < static_cast<int>(y_spans.size()); ++i) {
    const cv::Mat slice(sz, sx, CV_8UC1, cells + static_cast<size_t>(i) * sz * sx);
    const double s = i;
    slice_blobs(
        slice, y_spans[i], 1, occ, opt,
        [s](double r, double c) { return Eigen::Vector3d(c, s, r); }, work, points);
  }
  for (int i = 0; i < static_cast<int>(z_spans.size()); ++i) {
    const cv::Mat slice(sy, sx, CV_8UC1, cells + static_cast<size_t>(i) * sx,
                        static_cast<size_t>(sz) * sx);
    const double s = i;
    slice_blobs(
        slice, z_spans[i], 2, occ, opt,
        [s](double r, double c) { return Eigen::Vector3d(c, r, s); }, work, points);
  }
  return points;
}

}  // namespace simcap::tracker
