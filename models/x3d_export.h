// X3D H-Anim output (X3D 4.0, XML encoding): a body as an HAnimHumanoid (joint tree with
// centres, end sites, skin with weights) and optionally its motion as an HAnimMotion, so that
// X3D browsers (X_ITE, Castle Game Engine) play it and read_x3d_humanoid/read_x3d_motion read
// it back.
#pragma once

#include <Eigen/Core>
#include <array>
#include <filesystem>
#include <string>

#include "models/body_mesh.h"
#include "models/motion.h"
#include "models/skeleton.h"

namespace simcap {

// The humanoid named `name` in its default pose: nested HAnimJoints (DEF "J_<joint>", `center`
// the neutral centre, skinCoordIndex/skinCoordWeight the vertices each moves), listed again
// under containerField "joints"; HAnimSites for the end sites (translation = their centre);
// the skin as one Shape per material region (colours sRGB) on a shared skinCoord; and, when
// `motion` is given, an HAnimMotion (containerField "motions") with `joints` every non-site
// joint in skeleton order, channels "6 Xposition Yposition Zposition Zrotation Yrotation
// Xrotation" for humanoid_root and "3 Zrotation Yrotation Xrotation" for the others (R = Rz Ry
// Rx as in BVH; degrees), the root's position as its displacement from its centre (the X3D
// joint translation), frameDuration = 1 / fps.
std::string format_x3d_humanoid(const std::string& name, const Skeleton& skeleton,
                                const BodyMesh& mesh,
                                const std::array<Eigen::Vector3f, kMaterialRegionCount>& colors,
                                const Motion* motion = nullptr);
// Writes format_x3d_humanoid() to `path` atomically.
void write_x3d_humanoid(const std::filesystem::path& path, const std::string& name,
                        const Skeleton& skeleton, const BodyMesh& mesh,
                        const std::array<Eigen::Vector3f, kMaterialRegionCount>& colors,
                        const Motion* motion = nullptr);

}  // namespace simcap
