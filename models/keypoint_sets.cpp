#include "models/keypoint_sets.h"

#include <cmath>

#include "core/error.h"

namespace simcap {
namespace {

BodyPoint at_joint(const Skeleton& s, const std::string& name, const std::string& joint) {
  return {name, s.require(joint), Eigen::Vector3d::Zero()};
}

BodyPoint carried(const Skeleton& s, const std::string& name, const std::string& joint,
                  const Eigen::Vector3d& neutral) {
  const int j = s.require(joint);
  return {name, j, neutral - s[j].center};
}

struct Face {
  Eigen::Vector3d nose, left_eye, right_eye, left_ear, right_ear;
};

Face face_of(const Skeleton& s, const BodyMesh& mesh) {
  const int skull = s.require("skullbase");
  const double base = s[skull].center.y();
  Eigen::Vector3d front, left, right;
  bool any = false;
  for (size_t v = 0; v < mesh.vertices.size(); ++v) {
    const Eigen::Vector3d p = mesh.vertices[v].cast<double>();
    if (p.y() < base || !s.is_descendant(mesh.vertex_segment[v], skull)) continue;
    if (!any || p.z() > front.z()) front = p;
    if (!any || p.x() > left.x()) left = p;
    if (!any || p.x() < right.x()) right = p;
    any = true;
  }
  if (!any) throw Error("COCO keypoints: the body has no head skin above the skull base");
  Face f{front, {}, {}, left, right};
  const int l_eye = s.find("l_eyeball_joint"), r_eye = s.find("r_eyeball_joint");
  if (l_eye >= 0 && r_eye >= 0) {
    f.left_eye = s[l_eye].center;
    f.right_eye = s[r_eye].center;
  } else {
    // +X is the body's left.
    f.left_eye = front + Eigen::Vector3d(0.0315, 0.035, -0.025);
    f.right_eye = front + Eigen::Vector3d(-0.0315, 0.035, -0.025);
  }
  return f;
}

}  // namespace

Eigen::Vector3d body_point_world(const BodyPoint& point,
                                 const std::vector<Eigen::Isometry3d>& joint_world) {
  return joint_world.at(point.joint) * point.offset;
}

std::vector<BodyPoint> coco17_points(const Skeleton& s, const BodyMesh& mesh) {
  const Face f = face_of(s, mesh);
  std::vector<BodyPoint> out = {
      carried(s, "nose", "skullbase", f.nose),
      carried(s, "left_eye", "skullbase", f.left_eye),
      carried(s, "right_eye", "skullbase", f.right_eye),
      carried(s, "left_ear", "skullbase", f.left_ear),
      carried(s, "right_ear", "skullbase", f.right_ear),
  };
  for (const auto& [coco, hanim] : {std::pair{"shoulder", "shoulder"},
                                    {"elbow", "elbow"},
                                    {"wrist", "radiocarpal"},
                                    {"hip", "hip"},
                                    {"knee", "knee"},
                                    {"ankle", "talocrural"}}) {
    out.push_back(at_joint(s, std::string("left_") + coco, std::string("l_") + hanim));
    out.push_back(at_joint(s, std::string("right_") + coco, std::string("r_") + hanim));
  }
  return out;
}

const std::vector<std::pair<int, int>>& coco17_limbs() {
  // COCO's person category skeleton (1-based in the file): ankles to hips, hips, hips to
  // shoulders, arms, face.
  static const std::vector<std::pair<int, int>> limbs = {
      {15, 13}, {13, 11}, {16, 14}, {14, 12}, {11, 12}, {5, 11}, {6, 12}, {5, 6}, {5, 7}, {6, 8},
      {7, 9},   {8, 10},  {1, 2},   {0, 1},   {0, 2},   {1, 3},  {2, 4},  {3, 5}, {4, 6}};
  return limbs;
}

std::vector<BodyPoint> h36m17_points(const Skeleton& s, const BodyMesh& mesh) {
  const int l_hip = s.require("l_hip"), r_hip = s.require("r_hip");
  if (s[l_hip].parent != s[r_hip].parent) {
    throw Error("Human3.6M joints: l_hip and r_hip hang from different joints");
  }
  const Eigen::Vector3d hip_mid = 0.5 * (s[l_hip].center + s[r_hip].center);
  const int thorax = s.require("vc7");
  // The spine joint nearest halfway up from the hips to the thorax.
  const double mid_y = 0.5 * (hip_mid.y() + s[thorax].center.y());
  int spine = thorax;
  for (int j = s[thorax].parent; j >= 0; j = s[j].parent) {
    if (std::abs(s[j].center.y() - mid_y) < std::abs(s[spine].center.y() - mid_y)) spine = j;
  }
  return {
      carried(s, "Hip", s[s[l_hip].parent].name, hip_mid),
      at_joint(s, "RHip", "r_hip"),
      at_joint(s, "RKnee", "r_knee"),
      at_joint(s, "RFoot", "r_talocrural"),
      at_joint(s, "LHip", "l_hip"),
      at_joint(s, "LKnee", "l_knee"),
      at_joint(s, "LFoot", "l_talocrural"),
      at_joint(s, "Spine", s[spine].name),
      at_joint(s, "Thorax", "vc7"),
      carried(s, "Neck/Nose", "skullbase", face_of(s, mesh).nose),
      at_joint(s, "Head", "skull_tip"),
      at_joint(s, "LShoulder", "l_shoulder"),
      at_joint(s, "LElbow", "l_elbow"),
      at_joint(s, "LWrist", "l_radiocarpal"),
      at_joint(s, "RShoulder", "r_shoulder"),
      at_joint(s, "RElbow", "r_elbow"),
      at_joint(s, "RWrist", "r_radiocarpal"),
  };
}

}  // namespace simcap
