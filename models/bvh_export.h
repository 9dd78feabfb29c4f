// BVH export of any simcap Skeleton + Motion, so that motions can be viewed and edited in other
// tools (Blender, MotionBuilder) and read back by read_bvh.
#pragma once

#include <Eigen/Geometry>
#include <filesystem>
#include <string>

#include "models/motion.h"
#include "models/skeleton.h"

namespace simcap {

struct BvhWriteOptions {
  double metres_per_unit = 1.0;  // file unit (1: metres, as Blender expects; 0.01: centimetres)
};

// Angles (a, b, c) in degrees with R = Rz(a) Ry(b) Rx(c), b in [-90, 90]: the values of the
// channels "Zrotation Yrotation Xrotation" (BVH, X3D HAnimMotion).
Eigen::Vector3d zyx_degrees(const Eigen::Quaterniond& q);

// Joints keep their names; sites become End Sites; a joint with no child gets a zero End Site
// (BVH requires one). The root has a zero OFFSET and its world position in the position
// channels, so readers agree whether they add root channels to the offset or not. Every joint
// has "Zrotation Yrotation Xrotation" channels (R = Rz Ry Rx), angles in degrees.
std::string format_bvh(const Skeleton& skeleton, const Motion& motion,
                       const BvhWriteOptions& options = {});
// The same, written atomically to `path`.
void write_bvh(const std::filesystem::path& path, const Skeleton& skeleton, const Motion& motion,
               const BvhWriteOptions& options = {});

}  // namespace simcap
