// Everything needed to render a loaded scene, built once: the animated actors, the Embree scene
// (room, occluders, bodies), each camera's precomputed rays and the renderer.
#pragma once

#include <vector>

#include "scenes/scene.h"
#include "sim/animated_actors.h"
#include "sim/camera_rays.h"
#include "sim/embree_scene.h"
#include "sim/renderer.h"

namespace simcap {

class RenderSetup {
 public:
  // Reads textures, occluder meshes and motion files; throws Error naming a bad one.
  explicit RenderSetup(const Scene& scene, BodyBvhUpdate body_update = BodyBvhUpdate::refit);
  RenderSetup(const RenderSetup&) = delete;
  RenderSetup& operator=(const RenderSetup&) = delete;

  // Poses the actors at dataset frame `frame` and rebuilds what changed in the Embree scene.
  void pose(int frame);
  // Renders the empty room (actors hidden, no sensor noise), as background plates.
  std::vector<RenderedView> render_background();

  AnimatedActors& actors() { return actors_; }
  const EmbreeScene& embree() const { return embree_; }
  const std::vector<CameraRays>& cameras() const { return cameras_; }
  const Renderer& renderer() const { return renderer_; }

 private:
  Scene scene_;
  AnimatedActors actors_;
  EmbreeScene embree_;
  std::vector<CameraRays> cameras_;
  Renderer renderer_;
};

}  // namespace simcap
