#include "sim/render_setup.h"

#include <memory>

#include "sim/scene_meshes.h"
#include "sim/texture.h"

namespace simcap {
namespace {

void add_room_and_occluders(EmbreeScene& embree, const Scene& scene) {
  const Room& room = scene.room;
  std::shared_ptr<const Texture> floor_texture, wall_texture;
  if (!room.floor_texture.empty()) floor_texture = std::make_shared<Texture>(room.floor_texture);
  if (!room.wall_texture.empty()) wall_texture = std::make_shared<Texture>(room.wall_texture);
  for (const RoomSurface& s : room_surfaces(room)) {
    StaticLook look;
    look.color = s.floor ? room.floor_color : room.wall_color;
    look.texture = s.floor ? floor_texture : wall_texture;
    look.tex_u = s.tex_u;
    look.tex_v = s.tex_v;
    embree.add_static(s.mesh, look, false);
  }
  const auto base_dir = scene.source.parent_path();
  for (const Occluder& o : scene.occluders) {
    StaticLook look;
    look.color = o.color;
    embree.add_static(occluder_mesh(o, base_dir), look, true);
  }
}

std::vector<CameraRays> make_rays(const std::vector<Camera>& cameras) {
  std::vector<CameraRays> rays;
  rays.reserve(cameras.size());
  for (const Camera& c : cameras) rays.emplace_back(c);
  return rays;
}

}  // namespace

RenderSetup::RenderSetup(const Scene& scene, BodyBvhUpdate body_update)
    : scene_(scene),
      clock_(scene_),
      actors_(scene_),
      embree_(body_update, clock_.time_steps(), clock_.still_step()),
      cameras_(make_rays(scene_.cameras)),
      renderer_(embree_, scene_) {
  add_room_and_occluders(embree_, scene_);
  actors_.attach(embree_);
  embree_.commit();
  // Auto exposure needs every camera's reference brightness even when a resumed render does
  // not render the plates again.
  if (scene_.timing.auto_exposure) render_background();
}

void RenderSetup::pose(int frame) {
  actors_.pose(frame);
  embree_.commit();
}

std::vector<RenderedView> RenderSetup::render_background() {
  std::vector<RenderedView> views;
  embree_.set_actors_visible(false);
  embree_.commit();
  renderer_.render(cameras_, -1, views, false);
  embree_.set_actors_visible(true);
  embree_.commit();
  if (scene_.timing.auto_exposure) {
    std::vector<double> reference;
    for (const RenderedView& v : views) reference.push_back(v.mean_luminance);
    renderer_.set_exposure_reference(std::move(reference));
  }
  return views;
}

FrameTruth RenderSetup::capture(int frame, std::vector<RenderedView>* views) {
  if (clock_.still()) {
    pose(frame);
    FrameTruth truth = compute_frame_truth(frame, actors_.posed(), cameras_, embree_);
    if (views) renderer_.render(cameras_, frame, *views);
    return truth;
  }
  actors_.pose(frame, false);
  FrameTruth truth = compute_frame_truth(frame, actors_.posed(), {}, embree_);
  if (views) views->resize(cameras_.size());
  for (const CaptureClock::Group& g : clock_.groups()) {
    actors_.pose_bodies_over(frame, g.begin_s, g.end_s);
    embree_.commit();
    compute_timed_views(truth, g.cameras, cameras_, clock_, actors_, embree_);
    if (!views) continue;
    std::vector<Renderer::Shot> shots;
    for (const int c : g.cameras) {
      Renderer::Shot s;
      s.rays = &cameras_[c];
      s.view = c;
      s.times = clock_.ray_times(c);
      s.light_time_s = clock_.frame_time(frame) + g.offset_s;
      shots.push_back(s);
    }
    renderer_.render(shots, frame, *views);
  }
  return truth;
}

}  // namespace simcap
