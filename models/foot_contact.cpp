#include "models/foot_contact.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "models/pose.h"

namespace simcap {

std::string FootStats::summary() const {
  char line[400];
  std::snprintf(line, sizeof line,
                "lowest foot point over %d frames: min %+.4f m, mean %+.4f m; %d contacts of the "
                "feet's sole points (within %.3f m for >= %.2f s, %.1f s summed over the points): "
                "speed mean %.4f m/s, median "
                "%.4f m/s; drift per contact mean %.4f m, max %.4f m",
                frames, lowest_min, lowest_mean, contacts, contact_height, min_contact_s, contact_s,
                slide_mean, slide_median, drift_mean, drift_max);
  return line;
}

namespace {

double lowest(const std::array<std::vector<Eigen::Vector3d>, 2>& feet) {
  double low = INFINITY;
  for (const auto& foot : feet) {
    for (const auto& p : foot) low = std::min(low, p.y());
  }
  return low;
}

}  // namespace

double median_lowest_point(const FootTrack& track) {
  if (track.frames.empty()) throw Error("foot track has no frames");
  std::vector<double> values;
  for (const auto& feet : track.frames) values.push_back(lowest(feet));
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

FootStats measure_feet(const FootTrack& track, double contact_height, double min_contact_s,
                       double floor) {
  FootStats stats;
  stats.floor = floor;
  stats.contact_height = contact_height;
  stats.min_contact_s = min_contact_s;
  stats.frames = static_cast<int>(track.frames.size());
  if (track.frames.empty()) return stats;
  stats.lowest_min = INFINITY;
  double sum = 0;
  for (const auto& feet : track.frames) {
    const double low = lowest(feet) - floor;
    stats.lowest_min = std::min(stats.lowest_min, low);
    sum += low;
  }
  stats.lowest_mean = sum / track.frames.size();

  const int n = stats.frames;
  const int min_frames = std::max(2, static_cast<int>(std::ceil(min_contact_s * track.fps)));
  std::vector<double> speeds;
  double drift_sum = 0;
  for (int side = 0; side < 2; ++side) {
    const size_t points = track.frames[0][side].size();
    for (size_t k = 0; k < points; ++k) {
      auto at = [&](int f) { return track.frames[f][side].at(k); };
      auto down = [&](int f) { return at(f).y() - floor <= contact_height; };
      for (int start = 0; start < n;) {
        if (!down(start)) {
          ++start;
          continue;
        }
        int end = start;
        while (end + 1 < n && down(end + 1)) ++end;
        if (end - start + 1 >= min_frames) {
          ++stats.contacts;
          stats.contact_s += (end - start) / track.fps;
          for (int f = start; f < end; ++f) {
            const Eigen::Vector3d d = at(f + 1) - at(f);
            speeds.push_back(std::hypot(d.x(), d.z()) * track.fps);
          }
          const Eigen::Vector3d d = at(end) - at(start);
          const double drift = std::hypot(d.x(), d.z());
          drift_sum += drift;
          stats.drift_max = std::max(stats.drift_max, drift);
        }
        start = end + 1;
      }
    }
  }
  if (stats.contacts > 0) stats.drift_mean = drift_sum / stats.contacts;
  if (!speeds.empty()) {
    double total = 0;
    for (double s : speeds) total += s;
    stats.slide_mean = total / speeds.size();
    std::nth_element(speeds.begin(), speeds.begin() + speeds.size() / 2, speeds.end());
    stats.slide_median = speeds[speeds.size() / 2];
  }
  return stats;
}

FootTrack humanoid_feet(const Skeleton& skeleton, const Motion& motion) {
  struct Point {
    int joint;
    Eigen::Vector3d local;  // in the joint's frame
  };
  std::array<std::vector<Point>, 2> points;
  for (int side = 0; side < 2; ++side) {
    const std::string s = side == 0 ? "l_" : "r_";
    const int ankle = skeleton.require(s + "talocrural");
    const int ball = skeleton.require(s + "metatarsophalangeal_2");
    const int toe = skeleton.require(s + "toe_tip");
    const Eigen::Vector3d a = skeleton[ankle].center, b = skeleton[ball].center,
                          t = skeleton[toe].center;
    const Eigen::Vector3d heel(a.x() - (t.x() - a.x()) / 3, 0, a.z() - (t.z() - a.z()) / 3);
    // Neutral joint frames are world-aligned, so a neutral point's local coordinates are its
    // offset from the joint centre.
    points[side] = {{ankle, heel - a},
                    {ankle, Eigen::Vector3d(b.x(), 0, b.z()) - a},
                    {skeleton[toe].parent,
                     Eigen::Vector3d(t.x(), 0, t.z()) - skeleton[skeleton[toe].parent].center}};
  }
  FootTrack track;
  track.fps = motion.fps;
  for (const Pose& pose : motion.frames) {
    const auto world = forward_kinematics(skeleton, pose);
    auto& frame = track.frames.emplace_back();
    for (int side = 0; side < 2; ++side) {
      for (const Point& p : points[side]) frame[side].push_back(world[p.joint] * p.local);
    }
  }
  return track;
}

}  // namespace simcap
