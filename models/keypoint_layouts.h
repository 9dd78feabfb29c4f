// The keypoint layouts 2D detectors write (COCO-17, OpenPose BODY_25, MediaPipe BlazePose-33,
// Human3.6M-17): per keypoint its name, where simcap's ground truth has it, its mirror partner.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/name_table.h"

namespace simcap {

enum class KeypointLayoutId { coco17, body25, blazepose33, h36m17 };
inline constexpr NameTable<KeypointLayoutId, 4> kKeypointLayouts{
    {{"coco17", KeypointLayoutId::coco17},
     {"body25", KeypointLayoutId::body25},
     {"blazepose33", KeypointLayoutId::blazepose33},
     {"h36m17", KeypointLayoutId::h36m17}}};

// Where simcap's ground truth holds a keypoint: an H-Anim joint centre (gt/joints2d.csv), one of
// the COCO-17 or Human3.6M-17 points of models/keypoint_sets.h (gt/keypoints_coco.json,
// gt/joints3d_h36m17.csv), or nowhere (the keypoint is read and kept, never scored).
enum class TruthKind { none, hanim_joint, coco17_point, h36m17_point };

struct LayoutKeypoint {
  std::string_view name;
  TruthKind truth = TruthKind::none;
  // The H-Anim joint, or the point's name in coco17_points / h36m17_points; empty for none.
  std::string_view truth_name;
  // The COCO-17 keypoint that is the same body point, whose OKS sigma this keypoint uses;
  // empty when COCO has none.
  std::string_view coco_twin;
  double sigma = 0;  // COCO's OKS sigma of coco_twin; 0 when it has none
  int partner = -1;  // the mirror keypoint's index (left <-> right); -1 on the midline
};

struct KeypointLayout {
  KeypointLayoutId id;
  std::string_view title;  // e.g. "OpenPose BODY_25"
  std::vector<LayoutKeypoint> keypoints;

  int size() const { return static_cast<int>(keypoints.size()); }
  int index(std::string_view name) const;  // -1 when the layout has no such keypoint
};

const KeypointLayout& keypoint_layout(KeypointLayoutId id);

// The layout detectors write with `keypoints` points per person: 25 BODY_25, 33 BlazePose-33,
// 17 COCO-17 (Human3.6M-17 has 17 too, but detectors' 17-point output is COCO's; name h36m17
// to read it); nothing for other counts.
std::optional<KeypointLayoutId> layout_of_count(int keypoints);

// "17 (coco17, h36m17), 25 (body25) or 33 (blazepose33)", for messages.
std::string layout_counts_text();

}  // namespace simcap
