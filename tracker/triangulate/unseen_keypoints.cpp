#include "tracker/triangulate/unseen_keypoints.h"

#include <Eigen/Geometry>

#include "tracker/triangulate/reference_body.h"

namespace simcap::tracker {

std::vector<int> place_unseen_keypoints(
    std::vector<std::vector<std::optional<Eigen::Vector3d>>>& frames,
    const KeypointLayout& layout) {
  const std::vector<std::optional<Eigen::Vector3d>> reference = reference_keypoints(layout);
  std::vector<int> unseen;
  for (int k = 0; k < layout.size(); ++k) {
    bool seen = false;
    for (const auto& frame : frames) seen = seen || frame[k].has_value();
    if (!seen && reference[k]) unseen.push_back(k);
  }
  if (unseen.empty()) return unseen;
  for (auto& frame : frames) {
    std::vector<int> known;
    for (int k = 0; k < layout.size(); ++k) {
      if (frame[k] && reference[k]) known.push_back(k);
    }
    if (known.size() < 3) continue;
    Eigen::Matrix3Xd from(3, known.size()), to(3, known.size());
    for (size_t i = 0; i < known.size(); ++i) {
      from.col(i) = *reference[known[i]];
      to.col(i) = *frame[known[i]];
    }
    const Eigen::Matrix4d t = Eigen::umeyama(from, to, true);
    if (!t.allFinite()) continue;
    for (const int k : unseen) {
      frame[k] =
          Eigen::Vector3d(t.topLeftCorner<3, 3>() * *reference[k] + t.topRightCorner<3, 1>());
    }
  }
  return unseen;
}

}  // namespace simcap::tracker
