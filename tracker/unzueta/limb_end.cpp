#include "tracker/unzueta/limb_end.h"

#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <queue>
#include <vector>

namespace simcap::tracker {

std::optional<LimbEnd> limb_end(const cv::Mat& part, const cv::Mat& body, cv::Point2d near,
                                double length, std::optional<cv::Point2d> root,
                                double root_tolerance) {
  cv::Mat labels;
  if (cv::connectedComponents(part != 0, labels, 8, CV_32S) < 2) return std::nullopt;
  const int w = labels.cols, h = labels.rows;
  int blob = 0;
  double nearest = std::numeric_limits<double>::infinity();
  for (int y = 0; y < h; ++y) {
    const int* row = labels.ptr<int>(y);
    for (int x = 0; x < w; ++x) {
      const double d = std::hypot(x - near.x, y - near.y);
      if (row[x] && d < nearest) nearest = d, blob = row[x];
    }
  }
  auto in_blob = [&](int x, int y) { return labels.at<int>(y, x) == blob; };
  // The silhouette's rim mixes the part's colour with the background's; only the body's inside
  // (two pixels in) counts as where the body continues.
  cv::Mat inside;
  cv::erode(body, inside, cv::Mat(), cv::Point(-1, -1), 2, cv::BORDER_REPLICATE);
  constexpr int dx[8] = {1, -1, 0, 0, 1, 1, -1, -1}, dy[8] = {0, 0, 1, -1, 1, -1, 1, -1};
  const double step[8] = {1, 1, 1, 1, M_SQRT2, M_SQRT2, M_SQRT2, M_SQRT2};
  std::vector<double> dist(static_cast<size_t>(w) * h, std::numeric_limits<double>::infinity());
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  // Entries: where the body's inside touches the blob (of those, the ones nearest `root`);
  // failing that, the window's border.
  std::vector<int> contacts;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (!in_blob(x, y)) continue;
      for (int k = 0; k < 8; ++k) {
        const int u = x + dx[k], v = y + dy[k];
        if (u >= 0 && v >= 0 && u < w && v < h && inside.at<unsigned char>(v, u) &&
            !part.at<unsigned char>(v, u)) {
          contacts.push_back(y * w + x);
          break;
        }
      }
    }
  }
  auto to_root = [&](int i) { return root ? std::hypot(i % w - root->x, i / w - root->y) : 0.0; };
  double closest = std::numeric_limits<double>::infinity();
  for (int i : contacts) closest = std::min(closest, to_root(i));
  for (int i : contacts) {
    if (to_root(i) <= closest + root_tolerance) {
      dist[i] = 0;
      queue.emplace(0.0, i);
    }
  }
  if (queue.empty()) {
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        if (in_blob(x, y) && (x == 0 || y == 0 || x == w - 1 || y == h - 1)) {
          dist[y * w + x] = 0;
          queue.emplace(0.0, y * w + x);
        }
      }
    }
  }
  if (queue.empty()) return std::nullopt;
  double farthest = 0;
  while (!queue.empty()) {
    const auto [d, i] = queue.top();
    queue.pop();
    if (d > dist[i]) continue;
    farthest = std::max(farthest, d);
    const int x = i % w, y = i / w;
    for (int k = 0; k < 8; ++k) {
      const int u = x + dx[k], v = y + dy[k];
      if (u < 0 || v < 0 || u >= w || v >= h || !in_blob(u, v)) continue;
      const int j = v * w + u;
      if (d + step[k] < dist[j]) {
        dist[j] = d + step[k];
        queue.emplace(dist[j], j);
      }
    }
  }
  LimbEnd end;
  cv::Point2d sum;
  for (int i = 0; i < w * h; ++i) {
    if (dist[i] >= farthest - length && std::isfinite(dist[i])) {
      end.pixels.emplace_back(i % w, i / w);
      sum += cv::Point2d(end.pixels.back());
    }
  }
  end.centre = sum / static_cast<double>(end.pixels.size());
  return end;
}

}  // namespace simcap::tracker
