// The humanoid's kinematics and joint limits as URDF: written with pugixml, read back with
// urdfdom (urdf::parseURDF), so the reader is independent of the writer.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "models/joint_limits.h"
#include "models/skeleton.h"

// Layout. Links are H-Anim segments (the root link is humanoid_root's segment, "sacrum"; give it
// a floating base in your tool, since humanoid_root is free). Each degree of freedom of
// joint_limits.h is a revolute joint named like the DOF (l_shoulder_abduction); the DOFs of one
// H-Anim joint are chained in their order through massless links "<dof>_link", the first joint's
// origin being the skeleton offset of the H-Anim joint. Every frame is world-aligned in the
// neutral pose, so origins have no rotation and axes are +X, +Y or +Z. Sites (skull_tip,
// l_hand_tip, ...) are links on fixed joints of the same name. Effort and velocity, which URDF
// requires, are placeholders (simcap models no dynamics): 1000 N m and 100 rad/s.

namespace simcap {

// The URDF text for `skeleton` with `limits` (joints without limits become fixed joints).
// Numbers are written in shortest round-trip form, so reading gives back the same doubles.
std::string humanoid_urdf(const Skeleton& skeleton, const std::vector<JointLimits>& limits);

// Writes humanoid_urdf() to `path` atomically.
void write_humanoid_urdf(const std::filesystem::path& path, const Skeleton& skeleton,
                         const std::vector<JointLimits>& limits);

// The joint limits stored in a URDF written for `skeleton`'s joint names, grouped per H-Anim
// joint in skeleton order, each DOF's source taken from the comment "<dof>: <source>" just
// before its joint (as humanoid_urdf writes it), or "URDF <file>" without one. Throws Error naming
// the file (and the joint) when the file is not valid URDF (urdfdom's message, e.g. a revolute
// joint without <limit>), a revolute joint does not belong to a non-site joint of the skeleton, a
// joint is of another movable type, or an axis is not +X, +Y or +Z.
std::vector<JointLimits> read_urdf_limits(const std::filesystem::path& path,
                                          const Skeleton& skeleton);

}  // namespace simcap
