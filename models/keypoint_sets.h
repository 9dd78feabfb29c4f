// The keypoint sets of other datasets on any simcap body: COCO-17 (2D keypoints with
// visibility, as COCO's person_keypoints files) and Human3.6M-17 (3D joints in its order), each
// point fixed to one skeleton joint so that it moves with the pose.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <utility>
#include <vector>

#include "models/body_mesh.h"
#include "models/skeleton.h"

namespace simcap {

// A point carried by `joint`: world position = joint_world[joint] * offset, where offset is
// the point's neutral position minus the joint's centre (joint frames are world-aligned in the
// neutral pose).
struct BodyPoint {
  std::string name;
  int joint = 0;
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
};

Eigen::Vector3d body_point_world(const BodyPoint& point,
                                 const std::vector<Eigen::Isometry3d>& joint_world);

// COCO-17 in COCO's order: nose, left_eye, right_eye, left_ear, right_ear, left/right_shoulder,
// elbow, wrist, hip, knee, ankle (left before right). Limb points are H-Anim joint centres
// (wrist = radiocarpal, ankle = talocrural). The face points are carried by skullbase and
// placed on the head's skin in the neutral pose (the skin of skullbase and the joints below
// it, above the skull base): the nose at its foremost point, the ears at its leftmost and
// rightmost points, the eyes at the eyeball joints when the skeleton has them (H-Anim
// l/r_eyeball_joint), otherwise 31.5 mm either side of the nose (adult mean interpupillary
// distance 63 mm, Dodgson 2004), 35 mm above and 25 mm behind its tip (simcap's choice).
// Throws Error when the skeleton lacks a joint of the set or the head has no skin.
std::vector<BodyPoint> coco17_points(const Skeleton& skeleton, const BodyMesh& mesh);

// COCO's 19 limbs between keypoints (0-based indices into coco17_points), as in its
// categories[].skeleton (which is 1-based).
const std::vector<std::pair<int, int>>& coco17_limbs();

// Human3.6M's 17 evaluation joints in the order of its common 17-joint subset: Hip, RHip, RKnee,
// RFoot, LHip, LKnee, LFoot, Spine, Thorax, Neck/Nose, Head, LShoulder, LElbow, LWrist,
// RShoulder, RElbow, RWrist. Hip is the midpoint of the hip centres (carried by the hips'
// parent, sacroiliac); the hips, knees, shoulders and elbows are H-Anim joint centres, Foot =
// talocrural, Wrist = radiocarpal, Thorax = vc7 (at the shoulder line), Spine = the joint
// between the hips and vc7 whose height is nearest halfway between Hip and Thorax (vt10 on
// simcap's humanoid and on JoeSkin.x3d), Neck/Nose = the COCO nose and Head = skull_tip (the
// top of the head).
std::vector<BodyPoint> h36m17_points(const Skeleton& skeleton, const BodyMesh& mesh);

}  // namespace simcap
