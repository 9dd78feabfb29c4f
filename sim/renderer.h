// Renders the images of one frame for every camera: RGB (Lambert + ambient, shadowed lights,
// optional anti-aliasing), z-depth, actor mask, body-part labels and optionally normals.
// Lights have no distance falloff: a light's intensity scales the cosine term everywhere.
// Parallel over tiles of all cameras; 4x4-pixel Embree ray packets within a tile.
#pragma once

#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "scenes/scene.h"
#include "sim/camera_rays.h"
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
// Depth, mask, parts and normal come from the ray through the pixel centre; with several
// samples per pixel only the colour averages the jittered samples.
struct RenderedView {
  cv::Mat rgb, depth, mask, parts, normal;
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

  // Renders all `cameras` for dataset frame `frame` (which keys the anti-aliasing jitter and
  // sensor noise, together with the camera's name). `sensor_noise` = false renders the noise-free
  // image (background plates).
  RayCounts render(const std::vector<CameraRays>& cameras, int frame,
                   std::vector<RenderedView>& views, bool sensor_noise = true) const;

 private:
  struct LightSource {
    bool directional = true;
    Eigen::Vector3f towards_light;  // directional: unit vector to the light
    Eigen::Vector3f position;       // point light
    float intensity = 0;
    bool shadows = true;
  };
  struct Tile {
    int camera, x0, y0, x1, y1;
  };
  struct Lanes;  // one ray packet and the per-pixel state of its 4x4 block (renderer.cpp)
  RayCounts render_tile(const CameraRays& rays, const Tile& tile, int frame, RenderedView& view,
                        bool sensor_noise) const;
  // The steps for one packet: camera rays for one sample, the surfaces they hit, one light.
  void trace_camera_rays(const CameraRays& rays, int px, int py, int sample,
                         std::uint64_t camera_key, std::uint64_t frame_key, Lanes& lanes) const;
  void look_up_surfaces(Lanes& lanes) const;
  int add_light(const LightSource& light, Lanes& lanes) const;  // returns shadow rays traced
  void add_sensor_noise(int px, int py, int width, std::uint64_t camera_key,
                        std::uint64_t frame_key, const Lanes& lanes, cv::Vec3b* const* rgb_rows,
                        float* const* depth_rows) const;

  const EmbreeScene& embree_;
  std::vector<LightSource> lights_;
  float ambient_;
  int samples_;
  std::uint64_t seed_;
  SensorNoise noise_;
  bool normals_;
  SrgbEncoder encode_;
};

}  // namespace simcap
