// Everything needed to render a loaded scene, built once: the animated actors, the Embree scene
// (room, occluders, bodies), each camera's precomputed rays and the renderer.
#pragma once

#include <vector>

#include "scenes/scene.h"
#include "sim/animated_actors.h"
#include "sim/camera_rays.h"
#include "sim/capture_clock.h"
#include "sim/embree_scene.h"
#include "sim/ground_truth.h"
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
  // Renders the empty room (actors hidden, no sensor noise, the lights as at the first frame),
  // as background plates; with auto exposure their brightness is every camera's reference.
  std::vector<RenderedView> render_background();
  // Dataset frame `frame` as the cameras capture it: poses the actors (posed() holds them at
  // the frame's nominal time), computes the frame's ground truth and, when `views` is given,
  // renders every camera into it. Cameras out of sync, rolling shutters and motion blur are
  // rendered one group of cameras sharing a sync offset at a time, the bodies moving over the
  // group's window (CaptureClock).
  FrameTruth capture(int frame, std::vector<RenderedView>* views);

  AnimatedActors& actors() { return actors_; }
  const EmbreeScene& embree() const { return embree_; }
  const std::vector<CameraRays>& cameras() const { return cameras_; }
  const Renderer& renderer() const { return renderer_; }
  const CaptureClock& clock() const { return clock_; }

 private:
  Scene scene_;
  CaptureClock clock_;
  AnimatedActors actors_;
  EmbreeScene embree_;
  std::vector<CameraRays> cameras_;
  Renderer renderer_;
};

}  // namespace simcap
