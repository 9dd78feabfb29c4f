// A body read from a file (H-Anim X3D, a rigged mesh through Assimp): the readers hand over a
// skeleton and a weighted skin; this turns them into a simcap body that any motion drives.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "models/body.h"
#include "models/body_mesh.h"
#include "models/skeleton.h"

namespace simcap {

// What a reader found. The skeleton has H-Anim joint names, humanoid_root first, centres in the
// neutral pose in metres with +Y up and the body facing +Z; segment names may be empty (they are
// filled from H-Anim's joint-segment pairs).
struct SkinnedSkeleton {
  Skeleton skeleton;
  std::vector<Eigen::Vector3f> vertices;                // neutral pose, metres
  std::vector<std::array<std::uint32_t, 3>> triangles;  // counter-clockwise seen from outside
  // Per vertex: (skeleton joint, weight) pairs as the file gives them (any number, any sum).
  std::vector<std::vector<std::pair<int, float>>> weights;
};

// The joints simcap needs in every body: humanoid_root, vc7, skullbase, and per side hip, knee,
// talocrural, metatarsophalangeal_2, shoulder, elbow, radiocarpal (motions retarget onto them,
// trackers are scored on them).
const std::vector<std::string>& required_body_joints();

// Checks and completes `found` (read from `file`, named in errors):
// - every required_body_joints() joint exists, else an Error listing the missing ones;
// - at most 255 joints (part labels are 8-bit);
// - triangle corners index existing vertices; every joint index is in the skeleton;
// - vertices no triangle uses are dropped; a used vertex without weights follows the bone
//   (parent centre to child centre) nearest to it; weights keep the four largest per vertex,
//   normalized to sum 1; a vertex's part label is its largest weight's joint;
// - the end sites simcap's feet and figures use are added when the file has none: skull_tip
//   at the highest skin point of the head, l/r_hand_tip at the hand's skin point farthest from
//   the wrist, l/r_toe_tip at the foot's foremost skin point (under the foot's last joint);
// - each triangle takes the material region of the body part most of its corners lie on
//   (feet: shoes; pelvis and legs: trousers; hands, neck and head: skin; the rest: shirt).
Body finish_imported_body(SkinnedSkeleton found, const std::filesystem::path& file);

// The H-Anim 2.0 segment a joint moves (l_knee -> l_calf, vt12 -> t12,
// l_carpometacarpal_2 -> l_metacarpal_2); the joint's own name when H-Anim names none.
std::string hanim_segment_of(std::string_view joint);

}  // namespace simcap
