// Ground truth of one frame: every actor's joint positions (world) and local rotations, and
// each joint's pixel, camera depth and visibility in every camera, decided by ray casting.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <string_view>
#include <vector>

#include "sim/animated_actors.h"
#include "sim/camera_rays.h"
#include "sim/capture_clock.h"
#include "sim/embree_scene.h"

namespace simcap {

enum class Visibility { visible, self_occluded, scene_occluded, out_of_frame };
std::string_view visibility_name(Visibility v);

// How far (z-depth, metres) the first surface seen at a joint's pixel may lie in front of the
// joint for the joint to count as visible. Joint centres lie inside the body: measured over all
// 249 frames and 4 cameras of studio4, the skin seen in front of a visible limb joint is a median
// 3-8 cm (wrists, elbows, shoulders, knees, ankles) and in front of the pelvis and the lumbar and
// thoracic spine 13-15 cm, as these sit near the back of the torso. 0.15 m counts limb joints
// visible unless something is in front of them; the torso-centre joints are self_occluded in
// about half their views. (The Occlusion-Person dataset used 0.30 m.) Users who want another
// threshold have each joint's depth in joints2d.csv and the depth image.
inline constexpr double kVisibilityTolerance = 0.15;

// A joint as one camera sees it.
struct JointView {
  Eigen::Vector2d pixel;  // projection (OpenCV model); NaN when behind the camera
  double depth = 0;       // z in camera coordinates, metres
  Visibility visibility = Visibility::out_of_frame;
};

struct FrameTruth {
  int frame = 0;
  // [actor][joint], joints as in truth_joints() of the actor's skeleton.
  std::vector<std::vector<Eigen::Vector3d>> positions;
  std::vector<std::vector<Eigen::Quaterniond>> rotations;  // local, relative to neutral, w >= 0
  std::vector<std::vector<std::vector<JointView>>> views;  // [camera][actor][joint]
  // The actors' COCO-17 and Human3.6M-17 keypoints (PosedActor::coco17, h36m17): world
  // positions [actor][keypoint], and the COCO ones as the cameras see them [camera][actor][k].
  std::vector<std::vector<Eigen::Vector3d>> coco_positions, h36m_positions;
  std::vector<std::vector<std::vector<JointView>>> coco_views;
};

// The joints ground truth reports: every skeleton joint except end sites, in skeleton order.
std::vector<int> truth_joints(const Skeleton& skeleton);

// Visibility of a joint in front of the camera and inside the image: the ray through the
// centre of the pixel the joint projects into (the very ray that gave that pixel's depth, mask
// and part label, so the tables always agree with the images) is traced; if it meets a surface
// more than kVisibilityTolerance (z-depth) in front of the joint, the joint is self_occluded when
// that surface is the joint's own actor, scene_occluded when it is the room or an occluder;
// another actor's surface in front of the joint at all makes it scene_occluded (the tolerance
// is for the joint's own flesh, and the pixel is the other actor's in the mask); otherwise it is
// visible. Joints behind the camera or projecting outside
// [-0.5, width - 0.5) x [-0.5, height - 0.5) are out_of_frame.
FrameTruth compute_frame_truth(int frame, const std::vector<PosedActor>& actors,
                               const std::vector<CameraRays>& cameras, const EmbreeScene& scene);

// The views of `cameras` (indices into `rays`) when they capture as `clock` says, the scene
// holding their group's moving bodies: each joint is projected where it was when the row it
// lands on was captured, the fixed point t = row_offset_s(v(t)) (v clamped to the image's rows;
// joints behind the camera take the first row's time), and its visibility ray is that pixel's
// own ray at that row's time. Fills truth.views[c] for those cameras.
void compute_timed_views(FrameTruth& truth, const std::vector<int>& cameras,
                         const std::vector<CameraRays>& rays, const CaptureClock& clock,
                         const AnimatedActors& actors, const EmbreeScene& scene);

}  // namespace simcap
