// The scene's actors in motion: each actor's skeleton, skinned body and motion, posed frame by
// frame into the Embree scene. Actors whose body and motion are identical (a crowd sharing one
// clip) share one skinned mesh through Embree instancing and differ only by their transform.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "models/body_mesh.h"
#include "models/keypoint_sets.h"
#include "models/motion.h"
#include "models/pose.h"
#include "models/skeleton.h"
#include "scenes/scene.h"
#include "sim/embree_scene.h"

namespace simcap {

// One actor at the current frame.
struct PosedActor {
  std::string name;
  const Skeleton* skeleton = nullptr;
  Pose pose;  // in world coordinates: the actor's yaw and offset are applied to the root
  std::vector<Eigen::Isometry3d> joint_world;  // forward_kinematics(pose)
  // The body's keypoints of other datasets (models/keypoint_sets.h).
  const std::vector<BodyPoint>* coco17 = nullptr;
  const std::vector<BodyPoint>* h36m17 = nullptr;
};

// A labelled stretch of an actor's motion (a gesture corpus' gestures), in dataset frames.
struct ActorLabel {
  int actor = 0;
  int first_frame = 0, last_frame = 0;  // inclusive
  MotionLabel label;
};

class AnimatedActors {
 public:
  // Builds every actor's skeleton, body and motion (at the scene's frame rate). Motion files
  // are read here, so bad ones fail before anything is rendered.
  explicit AnimatedActors(const Scene& scene);
  ~AnimatedActors();

  // Dataset frames from the scene's first frame until the last actor's motion has ended.
  int frames_available() const { return frames_available_; }
  // Adds the bodies and the actors (in scene order) to `embree` and poses them at frame 0.
  void attach(EmbreeScene& embree);
  // Poses every actor at dataset frame `frame` and, with `move_bodies`, updates their bodies in
  // the attached scene (every time step in that pose); the caller commits it. Before its motion
  // starts an actor holds the first pose, after it ends the last one.
  void pose(int frame, bool move_bodies = true);
  // The actors `dt_s` seconds after frame `frame`'s nominal time, between two frames of their
  // motions interpolated as the motions are resampled (slerp of joint rotations, linear root).
  // posed() is not changed.
  std::vector<PosedActor> posed_at(int frame, double dt_s) const;
  PosedActor posed_actor_at(int actor, int frame, double dt_s) const;
  // Moves the bodies in the attached scene over [begin_s, end_s] after frame `frame`'s nominal
  // time: time step s of the scene's n holds the pose at begin_s + (end_s - begin_s) s / (n - 1).
  // posed() is not changed; the caller commits.
  void pose_bodies_over(int frame, double begin_s, double end_s);
  const std::vector<PosedActor>& posed() const { return posed_; }
  // The labels of every actor's motion that fall in dataset frames [0, frames), clipped to
  // them, by actor then start.
  std::vector<ActorLabel> labels(int frames) const;
  // Number of distinct skinned bodies (fewer than actors when actors share one).
  int body_count() const { return static_cast<int>(groups_.size()); }

 private:
  struct Group;
  Pose local_pose(const Group& g, int frame, double dt_s) const;
  PosedActor place(int actor, const Pose& local) const;
  // Skins every body at (frame, dt_s) into time step `step`.
  void skin_step(int frame, double dt_s, int step);
  std::vector<std::unique_ptr<Group>> groups_;
  std::vector<int> group_of_;                 // per actor
  std::vector<Eigen::Isometry3d> placement_;  // per actor: yaw about +Y, then offset
  std::vector<std::array<Rgb, kMaterialRegionCount>> colors_;  // per actor
  std::vector<PosedActor> posed_;
  EmbreeScene* embree_ = nullptr;
  double fps_;
  int first_frame_;
  int frames_available_ = 1;
};

}  // namespace simcap
