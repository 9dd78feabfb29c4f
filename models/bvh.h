// A Biovision Hierarchy (BVH) motion clip as written in the file: joints, end sites, channels and
// per-frame channel values, converted to metres; plus the clip's own forward kinematics.
#pragma once

#include <Eigen/Geometry>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace simcap {

enum class BvhChannel { x_position, y_position, z_position, x_rotation, y_rotation, z_rotation };

// "Xposition", "Zrotation", ... as BVH spells them.
std::string_view bvh_channel_name(BvhChannel channel);

struct BvhJoint {
  std::string name;  // as in the file; an end site is named "<Parent>_End" ("_End2", ... for more)
  int parent = -1;   // index into BvhClip::joints; -1 for the root
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();  // from the parent, metres
  bool is_end_site = false;
  std::vector<BvhChannel> channels;  // in file order (empty for end sites)
  int first_channel = 0;             // index of channels[0] in a frame's values
};

struct BvhClip {
  std::filesystem::path file;    // where it was read from (for messages)
  std::vector<BvhJoint> joints;  // in file order: parents before children, end sites included
  double frame_time = 0.0;       // seconds
  double metres_per_unit = 1.0;  // the conversion applied to offsets and position channels
  bool units_detected = false;   // true when metres_per_unit came from the skeleton's size
  int channel_count = 0;         // values per frame
  // values[f * channel_count + c]: channel c of frame f; positions in metres, angles in degrees.
  std::vector<double> values;

  int frame_count() const {
    return channel_count ? static_cast<int>(values.size() / channel_count) : 0;
  }
  double fps() const { return 1.0 / frame_time; }
  // Index of the joint (or end site) called `name`, or -1.
  int find(std::string_view name) const;
  std::vector<int> children(int joint) const;
};

struct BvhReadOptions {
  // Metres per file unit. 0 detects it from the rest skeleton's size: the unit among metres,
  // centimetres, millimetres, inches and CMU's 1/0.45 inch (0.0254 / 0.45 m) that makes the
  // largest extent of the rest pose closest to 1.7 m (a standing adult or arm span). Set it
  // when a clip is of a child or a giant, or in an unusual unit.
  double metres_per_unit = 0.0;
};

// CMU's BVH unit: 1/0.45 inch.
inline constexpr double kCmuMetresPerUnit = 0.0254 / 0.45;

// Reads a BVH file (LF or CRLF, any channel order, end sites). Bad input throws Error naming
// file:line and what was expected; a file with no frames is an error.
BvhClip read_bvh(const std::filesystem::path& path, const BvhReadOptions& options = {});
// The same from text in memory; `file` is used in messages only.
BvhClip parse_bvh(std::string_view text, const std::filesystem::path& file,
                  const BvhReadOptions& options = {});

// Parent-relative transform of `joint` at `frame`: T(offset) followed by each channel in file
// order (position channels translate, rotation channels rotate by their angle). Position
// channels add to the offset (for the root as for any joint).
Eigen::Isometry3d bvh_local_transform(const BvhClip& clip, int joint, int frame);
// World transforms of every joint and end site at `frame` (frame < 0: the rest pose, every
// channel zero). Rest-pose joint frames are aligned with the world, as in simcap's skeletons.
std::vector<Eigen::Isometry3d> bvh_forward_kinematics(const BvhClip& clip, int frame);
// World positions (metres) of every joint and end site at `frame` (-1: rest pose).
std::vector<Eigen::Vector3d> bvh_joint_positions(const BvhClip& clip, int frame);

}  // namespace simcap
