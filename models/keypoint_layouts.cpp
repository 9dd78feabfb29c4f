#include "models/keypoint_layouts.h"

#include <array>

namespace simcap {
namespace {

constexpr TruthKind kNone = TruthKind::none, kJoint = TruthKind::hanim_joint,
                    kCoco = TruthKind::coco17_point, kH36m = TruthKind::h36m17_point;

struct CocoPoint {
  std::string_view name;
  double sigma;
  TruthKind truth;
  std::string_view truth_name;
};

// COCO-17 in COCO's order with its OKS sigmas (pycocotools cocoeval.py; Ronchi & Perona 2017).
// Limb points are H-Anim joint centres, the face points simcap's own (models/keypoint_sets.h).
constexpr std::array<CocoPoint, 17> kCoco17{{{"nose", 0.026, kCoco, "nose"},
                                             {"left_eye", 0.025, kCoco, "left_eye"},
                                             {"right_eye", 0.025, kCoco, "right_eye"},
                                             {"left_ear", 0.035, kCoco, "left_ear"},
                                             {"right_ear", 0.035, kCoco, "right_ear"},
                                             {"left_shoulder", 0.079, kJoint, "l_shoulder"},
                                             {"right_shoulder", 0.079, kJoint, "r_shoulder"},
                                             {"left_elbow", 0.072, kJoint, "l_elbow"},
                                             {"right_elbow", 0.072, kJoint, "r_elbow"},
                                             {"left_wrist", 0.062, kJoint, "l_radiocarpal"},
                                             {"right_wrist", 0.062, kJoint, "r_radiocarpal"},
                                             {"left_hip", 0.107, kJoint, "l_hip"},
                                             {"right_hip", 0.107, kJoint, "r_hip"},
                                             {"left_knee", 0.087, kJoint, "l_knee"},
                                             {"right_knee", 0.087, kJoint, "r_knee"},
                                             {"left_ankle", 0.089, kJoint, "l_talocrural"},
                                             {"right_ankle", 0.089, kJoint, "r_talocrural"}}};

const CocoPoint* coco_point(std::string_view name) {
  for (const CocoPoint& p : kCoco17) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

// A keypoint that is COCO's `coco_twin` (then it has that point's truth and sigma), or else
// the point `truth` names, or nothing.
struct Row {
  std::string_view name, coco_twin;
  TruthKind truth = kNone;
  std::string_view truth_name = {};
};

// The mirror keypoint's name: left_x <-> right_x, x_left <-> x_right (BlazePose's mouth),
// Lx <-> Rx before a capital (BODY_25, Human3.6M); the name itself on the midline.
std::string mirrored(std::string_view n) {
  const auto swap_prefix = [&](std::string_view a, std::string_view b) -> std::string {
    return std::string(b) + std::string(n.substr(a.size()));
  };
  if (n.starts_with("left_")) return swap_prefix("left_", "right_");
  if (n.starts_with("right_")) return swap_prefix("right_", "left_");
  if (n.ends_with("_left")) return std::string(n.substr(0, n.size() - 4)) + "right";
  if (n.ends_with("_right")) return std::string(n.substr(0, n.size() - 5)) + "left";
  if (n.size() > 1 && (n[0] == 'L' || n[0] == 'R') && n[1] >= 'A' && n[1] <= 'Z') {
    return (n[0] == 'L' ? "R" : "L") + std::string(n.substr(1));
  }
  return std::string(n);
}

KeypointLayout build(KeypointLayoutId id, std::string_view title, const std::vector<Row>& rows) {
  KeypointLayout layout{id, title, {}};
  for (const Row& r : rows) {
    const CocoPoint* twin = coco_point(r.coco_twin);
    layout.keypoints.push_back({r.name, twin ? twin->truth : r.truth,
                                twin ? twin->truth_name : r.truth_name, r.coco_twin,
                                twin ? twin->sigma : 0.0, -1});
  }
  for (LayoutKeypoint& k : layout.keypoints) {
    const std::string m = mirrored(k.name);
    if (m != k.name) k.partner = layout.index(m);
  }
  return layout;
}

KeypointLayout coco17() {
  std::vector<Row> rows;
  for (const CocoPoint& p : kCoco17) rows.push_back({p.name, p.name});
  return build(KeypointLayoutId::coco17, "COCO-17", rows);
}

KeypointLayout body25() {
  return build(KeypointLayoutId::body25, "OpenPose BODY_25",
               {{"Nose", "nose"},
                {"Neck", ""},
                {"RShoulder", "right_shoulder"},
                {"RElbow", "right_elbow"},
                {"RWrist", "right_wrist"},
                {"LShoulder", "left_shoulder"},
                {"LElbow", "left_elbow"},
                {"LWrist", "left_wrist"},
                {"MidHip", "", kH36m, "Hip"},
                {"RHip", "right_hip"},
                {"RKnee", "right_knee"},
                {"RAnkle", "right_ankle"},
                {"LHip", "left_hip"},
                {"LKnee", "left_knee"},
                {"LAnkle", "left_ankle"},
                {"REye", "right_eye"},
                {"LEye", "left_eye"},
                {"REar", "right_ear"},
                {"LEar", "left_ear"},
                {"LBigToe", ""},
                {"LSmallToe", ""},
                {"LHeel", ""},
                {"RBigToe", ""},
                {"RSmallToe", ""},
                {"RHeel", ""}});
}

KeypointLayout blazepose33() {
  // MediaPipe names the points COCO has as COCO does. The hand points are knuckles and the
  // foot points the heel and the toe tip as the training labels place them, on the skin: none
  // is an H-Anim joint centre.
  std::vector<Row> rows;
  for (const std::string_view name :
       {"nose",        "left_eye_inner",  "left_eye",        "left_eye_outer", "right_eye_inner",
        "right_eye",   "right_eye_outer", "left_ear",        "right_ear",      "mouth_left",
        "mouth_right", "left_shoulder",   "right_shoulder",  "left_elbow",     "right_elbow",
        "left_wrist",  "right_wrist",     "left_pinky",      "right_pinky",    "left_index",
        "right_index", "left_thumb",      "right_thumb",     "left_hip",       "right_hip",
        "left_knee",   "right_knee",      "left_ankle",      "right_ankle",    "left_heel",
        "right_heel",  "left_foot_index", "right_foot_index"}) {
    rows.push_back({name, coco_point(name) ? name : ""});
  }
  return build(KeypointLayoutId::blazepose33, "MediaPipe BlazePose-33", rows);
}

KeypointLayout h36m17() {
  return build(KeypointLayoutId::h36m17, "Human3.6M-17",
               {{"Hip", "", kH36m, "Hip"},
                {"RHip", "right_hip"},
                {"RKnee", "right_knee"},
                {"RFoot", "right_ankle"},
                {"LHip", "left_hip"},
                {"LKnee", "left_knee"},
                {"LFoot", "left_ankle"},
                {"Spine", "", kH36m, "Spine"},
                {"Thorax", "", kJoint, "vc7"},
                {"Neck/Nose", "nose"},
                {"Head", "", kH36m, "Head"},
                {"LShoulder", "left_shoulder"},
                {"LElbow", "left_elbow"},
                {"LWrist", "left_wrist"},
                {"RShoulder", "right_shoulder"},
                {"RElbow", "right_elbow"},
                {"RWrist", "right_wrist"}});
}

}  // namespace

int KeypointLayout::index(std::string_view name) const {
  for (size_t i = 0; i < keypoints.size(); ++i) {
    if (keypoints[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

const KeypointLayout& keypoint_layout(KeypointLayoutId id) {
  static const std::array<KeypointLayout, 4> layouts = {coco17(), body25(), blazepose33(),
                                                        h36m17()};
  return layouts.at(static_cast<size_t>(id));
}

std::optional<KeypointLayoutId> layout_of_count(int keypoints) {
  switch (keypoints) {
    case 17:
      return KeypointLayoutId::coco17;
    case 25:
      return KeypointLayoutId::body25;
    case 33:
      return KeypointLayoutId::blazepose33;
    default:
      return std::nullopt;
  }
}

std::string layout_counts_text() {
  return "17 (coco17, h36m17), 25 (body25) or 33 (blazepose33)";
}

}  // namespace simcap
