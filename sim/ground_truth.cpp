#include "sim/ground_truth.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace simcap {
namespace {

Visibility classify(const CameraRays& rays, const EmbreeScene& scene, int actor,
                    const Eigen::Vector2d& pixel, double depth, const RayTimes& times = {}) {
  const double w = rays.width(), h = rays.height();
  if (!(depth > 0) ||
      !(pixel.x() >= -0.5 && pixel.x() < w - 0.5 && pixel.y() >= -0.5 && pixel.y() < h - 0.5)) {
    return Visibility::out_of_frame;
  }
  const int x = std::min(rays.width() - 1, static_cast<int>(std::floor(pixel.x() + 0.5)));
  const int y = std::min(rays.height() - 1, static_cast<int>(std::floor(pixel.y() + 0.5)));
  const Eigen::Vector3f d = rays.direction(x, y);
  RTCRayHit rh{};
  rh.ray.org_x = rays.origin().x();
  rh.ray.org_y = rays.origin().y();
  rh.ray.org_z = rays.origin().z();
  rh.ray.dir_x = d.x();
  rh.ray.dir_y = d.y();
  rh.ray.dir_z = d.z();
  rh.ray.tnear = 0.f;
  rh.ray.tfar = std::numeric_limits<float>::infinity();
  rh.ray.time = times.at_row(y);
  rh.ray.mask = ~0u;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcIntersect1(scene.scene_at(rh.ray.time), &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return Visibility::visible;
  const double hit_depth = static_cast<double>(rh.ray.tfar) * rays.z_scale(x, y);
  HitRecord hit;
  hit.geom_id = rh.hit.geomID;
  hit.inst_id = rh.hit.instID[0];
  const int hit_actor = scene.actor_of(hit);
  // The tolerance is for the joint's own flesh in front of its centre: another person's surface
  // anywhere in front of the joint hides it (the pixel is that person's in the mask).
  if (hit_actor >= 0 && hit_actor != actor) {
    return hit_depth < depth ? Visibility::scene_occluded : Visibility::visible;
  }
  if (hit_depth >= depth - kVisibilityTolerance) return Visibility::visible;
  return hit_actor == actor ? Visibility::self_occluded : Visibility::scene_occluded;
}

// A point of `actor` as the camera of `rays` sees it.
JointView view_of(const CameraRays& rays, const EmbreeScene& scene, int actor,
                  const Eigen::Vector3d& world) {
  const Camera& cam = rays.camera();
  JointView v;
  const Eigen::Vector3d c = cam.to_camera(world);
  v.depth = c.z();
  v.pixel = c.z() > 0 ? cam.project_camera(c)
                      : Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN());
  v.visibility = classify(rays, scene, actor, v.pixel, v.depth);
  return v;
}

// Where a point of `actor` (`point` of its posed self) was when camera `camera` captured it: the
// capture time solves dt = clock.row_offset_s(camera, v(dt)). The map is a contraction unless
// the point crosses the image faster than the readout sweeps it; bisection on [offset, offset +
// readout], where dt - row_offset_s(v(dt)) changes sign, settles any case the iteration does not.
template <typename Point>
JointView timed_view(const CameraRays& rays, int camera, const CaptureClock& clock,
                     const AnimatedActors& actors, int frame, int actor, const Point& point,
                     const EmbreeScene& scene) {
  const Camera& cam = rays.camera();
  auto residual = [&](double dt, Eigen::Vector3d& c) {
    c = cam.to_camera(point(actors.posed_actor_at(actor, frame, dt)));
    const double v = c.z() > 0 ? cam.project_camera(c).y() : 0.0;
    return clock.row_offset_s(camera, v) - dt;
  };
  double dt = clock.offset_s(camera);
  Eigen::Vector3d c;
  double r = residual(dt, c);
  for (int i = 0; i < 20 && std::abs(r) > 1e-13; ++i) {
    dt += r;
    r = residual(dt, c);
  }
  if (std::abs(r) > 1e-13) {
    double lo = clock.offset_s(camera), hi = lo + clock.readout_s();
    for (int i = 0; i < 100 && hi - lo > 1e-14; ++i) {
      const double mid = 0.5 * (lo + hi);
      (residual(mid, c) > 0 ? lo : hi) = mid;
    }
    dt = 0.5 * (lo + hi);
    residual(dt, c);
  }
  JointView v;
  v.depth = c.z();
  v.pixel = c.z() > 0 ? cam.project_camera(c)
                      : Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN());
  v.visibility = classify(rays, scene, actor, v.pixel, v.depth, clock.ray_times(camera));
  return v;
}

}  // namespace

std::string_view visibility_name(Visibility v) {
  switch (v) {
    case Visibility::visible:
      return "visible";
    case Visibility::self_occluded:
      return "self_occluded";
    case Visibility::scene_occluded:
      return "scene_occluded";
    case Visibility::out_of_frame:
      return "out_of_frame";
  }
  return "";
}

std::vector<int> truth_joints(const Skeleton& skeleton) {
  std::vector<int> out;
  for (int j = 0; j < skeleton.size(); ++j) {
    if (!skeleton[j].is_site) out.push_back(j);
  }
  return out;
}

FrameTruth compute_frame_truth(int frame, const std::vector<PosedActor>& actors,
                               const std::vector<CameraRays>& cameras, const EmbreeScene& scene) {
  FrameTruth t;
  t.frame = frame;
  for (const PosedActor& a : actors) {
    auto& coco = t.coco_positions.emplace_back();
    auto& h36m = t.h36m_positions.emplace_back();
    if (a.coco17) {
      for (const BodyPoint& p : *a.coco17) coco.push_back(body_point_world(p, a.joint_world));
    }
    if (a.h36m17) {
      for (const BodyPoint& p : *a.h36m17) h36m.push_back(body_point_world(p, a.joint_world));
    }
    auto& pos = t.positions.emplace_back();
    auto& rot = t.rotations.emplace_back();
    for (const int j : truth_joints(*a.skeleton)) {
      pos.push_back(a.joint_world[j].translation());
      Eigen::Quaterniond q = a.pose.rotations[j].normalized();
      if (q.w() < 0) q.coeffs() = -q.coeffs();
      rot.push_back(q);
    }
  }
  for (const CameraRays& rays : cameras) {
    auto& per_actor = t.views.emplace_back();
    auto& coco_per_actor = t.coco_views.emplace_back();
    for (size_t a = 0; a < actors.size(); ++a) {
      const int actor = static_cast<int>(a);
      auto& joints = per_actor.emplace_back();
      for (const Eigen::Vector3d& p : t.positions[a]) {
        joints.push_back(view_of(rays, scene, actor, p));
      }
      auto& coco = coco_per_actor.emplace_back();
      for (const Eigen::Vector3d& p : t.coco_positions[a]) {
        coco.push_back(view_of(rays, scene, actor, p));
      }
    }
  }
  return t;
}

void compute_timed_views(FrameTruth& truth, const std::vector<int>& cameras,
                         const std::vector<CameraRays>& rays, const CaptureClock& clock,
                         const AnimatedActors& actors, const EmbreeScene& scene) {
  truth.views.resize(rays.size());
  truth.coco_views.resize(rays.size());
  const auto& posed = actors.posed();
  for (const int c : cameras) {
    auto& per_actor = truth.views[c];
    auto& coco_per_actor = truth.coco_views[c];
    per_actor.clear();
    coco_per_actor.clear();
    for (size_t a = 0; a < posed.size(); ++a) {
      const int actor = static_cast<int>(a);
      auto& joints = per_actor.emplace_back();
      for (const int j : truth_joints(*posed[a].skeleton)) {
        joints.push_back(timed_view(
            rays[c], c, clock, actors, truth.frame, actor,
            [j](const PosedActor& p) { return p.joint_world[j].translation(); }, scene));
      }
      auto& coco = coco_per_actor.emplace_back();
      if (!posed[a].coco17) continue;
      for (const BodyPoint& k : *posed[a].coco17) {
        coco.push_back(timed_view(
            rays[c], c, clock, actors, truth.frame, actor,
            [&k](const PosedActor& p) { return body_point_world(k, p.joint_world); }, scene));
      }
    }
  }
}

}  // namespace simcap
