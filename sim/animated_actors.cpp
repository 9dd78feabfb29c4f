#include "sim/animated_actors.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "models/body_source.h"
#include "models/motion_source.h"

namespace simcap {

struct AnimatedActors::Group {
  Skeleton skeleton;
  BodyMesh mesh;
  std::unique_ptr<Skinner> skinner;
  std::vector<BodyPoint> coco17, h36m17;
  Motion motion;
  long start_frame = 0;  // scene frame at which the motion's first frame plays
  std::vector<int> actors;
  int body = -1;
};

namespace {

bool same_motion(const Motion& a, const Motion& b) {
  if (a.frames.size() != b.frames.size()) return false;
  for (size_t f = 0; f < a.frames.size(); ++f) {
    const Pose &p = a.frames[f], &q = b.frames[f];
    if (p.root_position != q.root_position || p.rotations.size() != q.rotations.size())
      return false;
    for (size_t j = 0; j < p.rotations.size(); ++j) {
      if (p.rotations[j].coeffs() != q.rotations[j].coeffs()) return false;
    }
  }
  return true;
}

bool same_body(const Skeleton& sa, const BodyMesh& a, const Skeleton& sb, const BodyMesh& b) {
  if (sa.size() != sb.size()) return false;
  for (int j = 0; j < sa.size(); ++j) {
    if (sa[j].name != sb[j].name || sa[j].center != sb[j].center) return false;
  }
  return a.vertices == b.vertices && a.triangles == b.triangles;
}

}  // namespace

AnimatedActors::AnimatedActors(const Scene& scene)
    : fps_(scene.render.fps), first_frame_(scene.render.first_frame) {
  if (scene.actors.empty()) throw Error("scene " + scene.source.string() + ": it has no actors");
  for (const Actor& actor : scene.actors) {
    auto g = std::make_unique<Group>();
    Body body = build_body(actor.body);
    g->skeleton = std::move(body.skeleton);
    g->mesh = std::move(body.mesh);
    g->motion = load_motion(actor.motion, g->skeleton, fps_);
    if (g->motion.frames.empty()) {
      throw Error("actor '" + actor.name + "': its motion has no frames");
    }
    g->start_frame = std::lround(actor.time_offset_s * fps_);
    const int actor_index = static_cast<int>(group_of_.size());
    auto shared = std::find_if(groups_.begin(), groups_.end(), [&](const auto& other) {
      return other->start_frame == g->start_frame &&
             same_body(other->skeleton, other->mesh, g->skeleton, g->mesh) &&
             same_motion(other->motion, g->motion);
    });
    if (shared == groups_.end()) {
      g->skinner = std::make_unique<Skinner>(g->skeleton, g->mesh);
      g->coco17 = coco17_points(g->skeleton, g->mesh);
      g->h36m17 = h36m17_points(g->skeleton, g->mesh);
      groups_.push_back(std::move(g));
      shared = groups_.end() - 1;
    }
    (*shared)->actors.push_back(actor_index);
    group_of_.push_back(static_cast<int>(shared - groups_.begin()));
    colors_.push_back(actor.colors);
    placement_.push_back(Eigen::Translation3d(actor.offset) *
                         Eigen::AngleAxisd(actor.yaw_rad, Eigen::Vector3d::UnitY()));
    PosedActor p;
    p.name = actor.name;
    p.skeleton = &(*shared)->skeleton;
    p.coco17 = &(*shared)->coco17;
    p.h36m17 = &(*shared)->h36m17;
    posed_.push_back(std::move(p));
    const long end = (*shared)->start_frame + static_cast<long>((*shared)->motion.frames.size());
    frames_available_ = std::max<long>(frames_available_, end - first_frame_);
  }
}

AnimatedActors::~AnimatedActors() = default;

void AnimatedActors::attach(EmbreeScene& embree) {
  embree_ = &embree;
  for (auto& g : groups_) g->body = embree.add_body(g->mesh, g->actors.size() > 1);
  // Actors are added in scene order so that Embree's actor index is the scene's.
  for (size_t a = 0; a < posed_.size(); ++a) {
    embree.add_actor(groups_[group_of_[a]]->body, colors_[a]);
    embree.set_actor_transform(static_cast<int>(a), placement_[a]);
  }
  pose(0);
}

Pose AnimatedActors::local_pose(const Group& g, int frame, double dt_s) const {
  const long last = static_cast<long>(g.motion.frames.size()) - 1;
  const long k = first_frame_ + frame - g.start_frame;
  if (dt_s == 0) return g.motion.frames[std::clamp<long>(k, 0, last)];
  const double position = static_cast<double>(k) + dt_s * fps_;
  if (position <= 0) return g.motion.frames.front();
  if (position >= static_cast<double>(last)) return g.motion.frames.back();
  const long i0 = static_cast<long>(std::floor(position));
  const double a = position - static_cast<double>(i0);
  const Pose& p0 = g.motion.frames[i0];
  if (a == 0) return p0;
  const Pose& p1 = g.motion.frames[i0 + 1];
  Pose p;
  p.root_position = (1 - a) * p0.root_position + a * p1.root_position;
  p.rotations.resize(p0.rotations.size());
  for (size_t j = 0; j < p0.rotations.size(); ++j) {
    p.rotations[j] = p0.rotations[j].slerp(a, p1.rotations[j]).normalized();
  }
  return p;
}

PosedActor AnimatedActors::place(int actor, const Pose& local) const {
  PosedActor p;
  p.name = posed_[actor].name;
  p.skeleton = posed_[actor].skeleton;
  p.coco17 = posed_[actor].coco17;
  p.h36m17 = posed_[actor].h36m17;
  p.pose = local;
  p.pose.root_position = placement_[actor] * local.root_position;
  p.pose.rotations[0] = Eigen::Quaterniond(placement_[actor].linear()) * local.rotations[0];
  p.joint_world = forward_kinematics(*p.skeleton, p.pose);
  return p;
}

std::vector<PosedActor> AnimatedActors::posed_at(int frame, double dt_s) const {
  std::vector<PosedActor> out(posed_.size());
  for (const auto& g : groups_) {
    const Pose local = local_pose(*g, frame, dt_s);
    for (const int a : g->actors) out[a] = place(a, local);
  }
  return out;
}

std::vector<ActorLabel> AnimatedActors::labels(int frames) const {
  std::vector<ActorLabel> out;
  for (size_t a = 0; a < group_of_.size(); ++a) {
    const Group& g = *groups_[group_of_[a]];
    // Motion frame k plays at scene frame start_frame + k, shown by dataset frame
    // start_frame + k - first_frame.
    const long shift = g.start_frame - first_frame_;
    for (const MotionLabel& l : g.motion.labels) {
      const long first = std::lround(std::ceil(l.start_s * fps_ - 1e-9)) + shift;
      const long last = std::lround(std::floor(l.end_s * fps_ + 1e-9)) + shift;
      if (last < 0 || first >= frames || last < first) continue;
      out.push_back({static_cast<int>(a), static_cast<int>(std::max(first, 0L)),
                     static_cast<int>(std::min<long>(last, frames - 1)), l});
    }
  }
  return out;
}

PosedActor AnimatedActors::posed_actor_at(int actor, int frame, double dt_s) const {
  return place(actor, local_pose(*groups_[group_of_.at(actor)], frame, dt_s));
}

void AnimatedActors::skin_step(int frame, double dt_s, int step) {
  for (auto& g : groups_) {
    const Pose local = local_pose(*g, frame, dt_s);
    // A body worn by one actor is skinned in world coordinates; a shared one in the motion's
    // own frame, which each actor's instance transform then places.
    const std::vector<Eigen::Isometry3d> joints = g->actors.size() == 1
                                                      ? place(g->actors[0], local).joint_world
                                                      : forward_kinematics(g->skeleton, local);
    g->skinner->skin(joints, embree_->body_vertices(g->body, step));
  }
}

void AnimatedActors::pose(int frame, bool move_bodies) {
  for (auto& g : groups_) {
    const Pose local = local_pose(*g, frame, 0);
    for (const int a : g->actors) posed_[a] = place(a, local);
    if (!embree_ || !move_bodies) continue;
    const std::vector<Eigen::Isometry3d> joints = g->actors.size() == 1
                                                      ? posed_[g->actors[0]].joint_world
                                                      : forward_kinematics(g->skeleton, local);
    for (int step = 0; step < embree_->time_steps(); ++step) {
      g->skinner->skin(joints, embree_->body_vertices(g->body, step));
    }
    embree_->body_updated(g->body);
  }
}

void AnimatedActors::pose_bodies_over(int frame, double begin_s, double end_s) {
  const int steps = embree_->time_steps();
  for (int step = 0; step < steps; ++step) {
    const double a = steps > 1 ? static_cast<double>(step) / (steps - 1) : 0.0;
    skin_step(frame, begin_s + a * (end_s - begin_s), step);
  }
  for (auto& g : groups_) embree_->body_updated(g->body);
}

}  // namespace simcap
