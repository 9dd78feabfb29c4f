// BVH joint names to H-Anim names. BVH files name joints by convention (CMU's, Mixamo's,
// Poser/Daz's, Biovision's...), and the same name can mean different joints in two conventions
// (CMU 3dsMax "LeftShoulder" is the clavicle; CMU ASF-style "LeftShoulder" is the shoulder).
// So each convention is a table, and a clip is mapped by the table that knows most of its names.
#pragma once

#include <string>
#include <vector>

namespace simcap {

struct BvhNaming {
  std::string convention;  // the table that matched ("cmu-asf", "cmu-3dsmax", "mixamo", ...)
  // Per input name: its H-Anim joint or site name; empty when the table does not map it.
  std::vector<std::string> hanim;
  // Per input name: a joint the table knows as an intermediate (CMU's LHipJoint: a pelvis bone
  // from the hips' centre to the hip joint) whose rotation and offset are carried by its
  // mapped descendants rather than by a joint of its own.
  std::vector<bool> intermediate;
};

// Maps joint names (end sites as "<Parent>_End") by the best-matching table. Names are compared
// without case and without a namespace prefix ("mixamorig:Hips" is "Hips"). H-Anim names
// (simcap's own BVH exports) map to themselves.
BvhNaming map_bvh_names(const std::vector<std::string>& names);

// The names of the tables, in the order they win ties.
std::vector<std::string> bvh_naming_conventions();

}  // namespace simcap
