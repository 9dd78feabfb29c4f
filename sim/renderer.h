// Renders the images of one frame for every camera: RGB (Lambert + ambient, shadowed lights,
// optional anti-aliasing), z-depth, actor mask, body-part labels and optionally normals.
// Lights have no distance falloff: a light's intensity scales the cosine term everywhere.
// Parallel over tiles of all cameras; 4x4-pixel Embree ray packets within a tile.
#pragma once

#include <array>
#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "scenes/scene.h"
#include "sim/camera_rays.h"
#include "sim/capture_clock.h"
#include "sim/embree_scene.h"
#include "sim/srgb.h"

namespace simcap {

// One camera's images. Conventions (also in the dataset's meta.json):
//  - rgb: CV_8UC3, sRGB, RGB channel order.
//  - depth: CV_32FC1, z-depth in metres, i.e. the hit point's z in camera coordinates (distance
//    along the optical axis, not along the ray); +infinity where the ray hits nothing.
//  - mask: CV_8UC1, 0 where no actor is seen; 255 for the actor when the scene has one actor,
//    otherwise 1 + the actor's index.
//  - parts: CV_8UC1, 1 + skeleton index of the joint whose H-Anim segment is seen, 0 elsewhere.
//  - normal: CV_32FC3, unit world-space shading normal facing the camera, 0 where no hit; only
//    filled when the scene asks for normals.
// Depth, mask, parts and normal come from the ray through the pixel centre at the middle of the
// row's exposure; with several samples per pixel only the colour averages the jittered samples
// (and, with motion blur, samples spread over the exposure).
struct RenderedView {
  cv::Mat rgb, depth, mask, parts, normal;
  cv::Mat linear;  // CV_32FC3 scratch: the colour before exposure, with auto exposure only
  // Auto exposure: mean linear luminance before the gain, and the gain applied to the colour.
  double mean_luminance = 0, gain = 1;
};

struct RayCounts {
  std::uint64_t camera = 0;  // primary rays, all samples
  std::uint64_t shadow = 0;  // occlusion rays towards lights
};

class Renderer {
 public:
  // Pixels of a tile, the unit of parallel work: whole 4x4 blocks of CameraRays, and 64 pixels
  // wide so that each image row of a tile fills whole cache lines (measured: ~4% faster than
  // 16x16 tiles, whose 16-byte mask rows share cache lines with other threads' tiles).
  static constexpr int kTileWidth = 64, kTileHeight = 16;

  // Lights, ambient level, samples per pixel, seed, noise and the normals switch come from
  // `scene`; geometry comes from `embree`, which must stay alive and committed while rendering.
  Renderer(const EmbreeScene& embree, const Scene& scene);

  // One camera to render: its rays, their times in the committed scene (see CaptureClock), the
  // scene time its lights are evaluated at, and where its images go (views[view]).
  struct Shot {
    const CameraRays* rays = nullptr;
    int view = 0;
    RayTimes times;
    double light_time_s = 0;
  };

  // Renders all `cameras` for dataset frame `frame` (which keys the anti-aliasing jitter and
  // sensor noise, together with the camera's name) at the frame's nominal time. `sensor_noise` =
  // false renders the noise-free image (background plates; frame -1 lights them as frame 0).
  RayCounts render(const std::vector<CameraRays>& cameras, int frame,
                   std::vector<RenderedView>& views, bool sensor_noise = true) const;
  // Renders the shots into `views` (resized to hold every shot's view).
  RayCounts render(const std::vector<Shot>& shots, int frame, std::vector<RenderedView>& views,
                   bool sensor_noise = true) const;

  // Auto exposure (rig.auto_exposure): every later image is scaled by reference / its mean
  // linear luminance, per camera (indexed as Shot::view). Without a reference the gain is 1.
  void set_exposure_reference(std::vector<double> mean_luminance) {
    exposure_reference_ = std::move(mean_luminance);
  }

 private:
  struct LightSource {
    bool directional = true;
    Eigen::Vector3f towards_light;  // directional: unit vector to the light
    Eigen::Vector3f position;       // point light
    float intensity = 0;
    bool shadows = true;
  };
  struct Tile {
    int shot, x0, y0, x1, y1;
  };
  struct Lanes;      // one ray packet and the per-pixel state of its 4x4 block (renderer.cpp)
  struct ShotState;  // a shot's lights and keys while it renders
  RayCounts render_tile(const ShotState& shot, const Tile& tile, RenderedView& view,
                        bool sensor_noise, double& luminance) const;
  // The steps for one packet: camera rays for one sample, the surfaces they hit, one light.
  void trace_camera_rays(const ShotState& shot, int px, int py, int sample, Lanes& lanes) const;
  void look_up_surfaces(Lanes& lanes) const;
  int add_light(const LightSource& light, Lanes& lanes) const;  // returns shadow rays traced
  // Encodes a block's linear colour (structure of arrays) into the image rows, adds noise.
  void write_colour(int px, int py, const ShotState& shot, const int* valid, float* linear,
                    bool sensor_noise, cv::Vec3b* const* rgb_rows, float* const* depth_rows) const;
  // Auto exposure's second pass over a tile: the stored linear colour times the gain.
  void expose_tile(const ShotState& shot, const Tile& tile, RenderedView& view,
                   bool sensor_noise) const;
  void add_sensor_noise(int px, int py, const ShotState& shot, const int* valid,
                        cv::Vec3b* const* rgb_rows, float* const* depth_rows) const;
  std::vector<LightSource> lights_at(double time_s) const;

  const EmbreeScene& embree_;
  std::vector<Light> lights_;
  float ambient_;
  int samples_;
  std::uint64_t seed_;
  SensorNoise noise_;
  bool normals_;
  bool auto_exposure_;
  double fps_;
  int first_frame_;
  std::vector<double> exposure_reference_;
  std::vector<std::array<float, 3>> pattern_;  // per sample: x, y and time offsets in [0, 1)
  SrgbEncoder encode_;
};

}  // namespace simcap
