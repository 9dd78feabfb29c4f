#include "tracker/triangulate/reference_body.h"

#include "models/body_mesh.h"
#include "models/humanoid.h"
#include "models/keypoint_sets.h"

namespace simcap::tracker {

const Anchors& reference_anchors() {
  static const Anchors anchors = [] {
    const Skeleton s = build_humanoid();
    const BodyMesh mesh = build_body_mesh(s);
    Anchors a;
    for (const BodyPoint& p : coco17_points(s, mesh)) a[p.name] = s[p.joint].center + p.offset;
    for (const BodyPoint& p : h36m17_points(s, mesh)) {
      if (p.name == "Head") a["Head"] = s[p.joint].center + p.offset;
    }
    for (const char* j : {"humanoid_root", "vc7", "skullbase"}) a[j] = s[s.require(j)].center;
    return a;
  }();
  return anchors;
}

int keypoint_of(const KeypointLayout& layout, const std::string& anchor) {
  for (int k = 0; k < layout.size(); ++k) {
    const LayoutKeypoint& kp = layout.keypoints[k];
    if (kp.coco_twin == anchor) return k;
    if (kp.truth == TruthKind::h36m17_point && kp.truth_name == anchor) return k;
  }
  return -1;
}

std::vector<std::optional<Eigen::Vector3d>> reference_keypoints(const KeypointLayout& layout) {
  std::vector<std::optional<Eigen::Vector3d>> out(layout.size());
  for (const auto& [name, position] : reference_anchors()) {
    if (const int k = keypoint_of(layout, name); k >= 0) out[k] = position;
  }
  return out;
}

}  // namespace simcap::tracker
