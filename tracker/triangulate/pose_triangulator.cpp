#include "tracker/triangulate/pose_triangulator.h"

namespace simcap::tracker {

TriangulatedPose triangulate_pose(std::span<const Camera> cameras,
                                  std::span<const PersonKeypoints* const> views,
                                  std::span<const int> partner, int keypoint_count,
                                  const PoseTriangulationOptions& o) {
  std::vector<KeypointViews> keypoints(static_cast<size_t>(keypoint_count));
  for (size_t c = 0; c < views.size() && c < cameras.size(); ++c) {
    if (!views[c]) continue;
    const auto& kps = views[c]->keypoints;
    for (size_t k = 0; k < kps.size() && k < keypoints.size(); ++k) {
      if (kps[k].z() >= o.point.min_confidence) {
        keypoints[k].push_back({static_cast<int>(c), kps[k].head<2>(), kps[k].z()});
      }
    }
  }
  TriangulatedPose pose;
  if (o.repair_swaps) pose.swaps = repair_swaps(keypoints, partner, cameras, o.swaps);
  pose.keypoints.reserve(keypoints.size());
  for (const KeypointViews& k : keypoints) {
    pose.keypoints.push_back(triangulate_robust(k, cameras, o.point));
  }
  return pose;
}

}  // namespace simcap::tracker
