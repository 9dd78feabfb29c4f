#include "sim/renderer.h"

#include <oneapi/tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>

#include "sim/avx2_clones.h"
#include "sim/embree_packets.h"
#include "sim/random.h"

namespace simcap {
namespace {

// Shadow rays start this far off the surface (metres) so they do not hit it again.
constexpr float kShadowOffset = 2e-4f;
constexpr float kInf = std::numeric_limits<float>::infinity();

enum Stream : std::uint64_t { kJitter = 1, kRgbNoise = 2, kDepthNoise = 3, kShutter = 4 };

// Rec. 709 luminance of linear RGB, what auto exposure meters.
constexpr float kLuma[3] = {0.2126f, 0.7152f, 0.0722f};

// x in [0, 2) wrapped into [0, 1).
inline float wrap01(float x) {
  return x >= 1.f ? x - 1.f : x;
}

// Sample s > 0 of every pixel: the s-th point of the R3 sequence (Roberts 2018, "The unreasonable
// effectiveness of quasirandom sequences": the fractional parts of s / phi, s / phi^2, s / phi^3
// with phi^4 = phi + 1), which fills the cube evenly for every sample count. Each pixel shifts
// it by its own random offset (Cranley-Patterson rotation), so pixels do not share a pattern.
std::vector<std::array<float, 3>> sample_pattern(int samples) {
  constexpr double phi = 1.2207440846057596;
  std::vector<std::array<float, 3>> out(samples);
  for (int s = 1; s < samples; ++s) {
    double a = 1;
    for (int d = 0; d < 3; ++d) {
      a /= phi;
      const double x = s * a;
      out[s][d] = std::min(static_cast<float>(x - std::floor(x)), 0x1.fffffep-1f);
    }
  }
  return out;
}

// Writes a 4x4 block's lanes into its image rows: whole rows at once when every lane is inside
// the tile, otherwise lane by lane where `valid`.
template <typename T>
inline void store_block(const T* lanes, const int* valid, bool whole_block, int px,
                        T* const* rows) {
  constexpr int B = CameraRays::kBlock;
  for (int r = 0; r < B; ++r) {
    if (whole_block) {
      std::memcpy(rows[r] + px, lanes + r * B, B * sizeof(T));
      continue;
    }
    for (int c = 0; c < B; ++c) {
      if (valid[r * B + c]) rows[r][px + c] = lanes[r * B + c];
    }
  }
}

}  // namespace

struct Renderer::ShotState {
  const CameraRays* rays = nullptr;
  RayTimes times;
  std::vector<LightSource> lights;
  // Each random stream's hash of (seed, stream, camera, frame), which every pixel continues.
  std::uint64_t jitter = 0, rgb_noise = 0, depth_noise = 0, shutter = 0;
  bool blur = false;
  float gain = 1;
};

Renderer::Renderer(const EmbreeScene& embree, const Scene& scene)
    : embree_(embree),
      lights_(scene.lights),
      ambient_(static_cast<float>(scene.ambient)),
      samples_(std::max(1, scene.render.samples_per_pixel)),
      seed_(scene.render.seed),
      noise_(scene.noise),
      normals_(scene.render.normals),
      auto_exposure_(scene.timing.auto_exposure),
      fps_(scene.render.fps),
      first_frame_(scene.render.first_frame),
      pattern_(sample_pattern(samples_)) {}

std::vector<Renderer::LightSource> Renderer::lights_at(double time_s) const {
  std::vector<LightSource> out;
  for (const Light& light : lights_) {
    const Light l = light_at(light, time_s);
    LightSource s;
    s.directional = l.kind == Light::Kind::directional;
    s.towards_light = (-l.direction).normalized().cast<float>();
    s.position = l.position.cast<float>();
    s.intensity = static_cast<float>(l.intensity);
    s.shadows = l.shadows;
    out.push_back(s);
  }
  return out;
}

RayCounts Renderer::render(const std::vector<CameraRays>& cameras, int frame,
                           std::vector<RenderedView>& views, bool sensor_noise) const {
  std::vector<Shot> shots;
  for (size_t c = 0; c < cameras.size(); ++c) {
    Shot s;
    s.rays = &cameras[c];
    s.view = static_cast<int>(c);
    s.light_time_s = (first_frame_ + std::max(frame, 0)) / fps_;
    shots.push_back(s);
  }
  views.resize(cameras.size());
  return render(shots, frame, views, sensor_noise);
}

RayCounts Renderer::render(const std::vector<Shot>& shots, int frame,
                           std::vector<RenderedView>& views, bool sensor_noise) const {
  std::vector<ShotState> states;
  std::vector<Tile> tiles;
  for (size_t i = 0; i < shots.size(); ++i) {
    const Shot& shot = shots[i];
    ShotState st;
    st.rays = shot.rays;
    st.times = shot.times;
    st.lights = lights_at(shot.light_time_s);
    // Keyed by name: a camera rendered alone (render --cameras) gets the images it gets in its
    // rig.
    const std::uint64_t camera_key = text_key(shot.rays->camera().name);
    const auto frame_key = static_cast<std::uint64_t>(static_cast<std::int64_t>(frame));
    st.jitter = random_bits(seed_, {kJitter, camera_key, frame_key});
    st.rgb_noise = random_bits(seed_, {kRgbNoise, camera_key, frame_key});
    st.depth_noise = random_bits(seed_, {kDepthNoise, camera_key, frame_key});
    st.shutter = random_bits(seed_, {kShutter, camera_key, frame_key});
    st.blur = shot.times.exposure > 0 && samples_ > 1;
    states.push_back(std::move(st));
    const int w = shot.rays->width(), h = shot.rays->height();
    if (static_cast<int>(views.size()) <= shot.view) views.resize(shot.view + 1);
    RenderedView& v = views[shot.view];
    v.rgb.create(h, w, CV_8UC3);
    v.depth.create(h, w, CV_32FC1);
    v.mask.create(h, w, CV_8UC1);
    v.parts.create(h, w, CV_8UC1);
    if (normals_) {
      v.normal.create(h, w, CV_32FC3);
    } else {
      v.normal.release();
    }
    if (auto_exposure_) v.linear.create(h, w, CV_32FC3);
    for (int y = 0; y < h; y += kTileHeight) {
      for (int x = 0; x < w; x += kTileWidth) {
        tiles.push_back(
            {static_cast<int>(i), x, y, std::min(w, x + kTileWidth), std::min(h, y + kTileHeight)});
      }
    }
  }
  std::vector<double> tile_luminance(tiles.size(), 0.0);
  std::atomic<std::uint64_t> camera_rays{0}, shadow_rays{0};
  tbb::parallel_for(tbb::blocked_range<size_t>(0, tiles.size(), 1), [&](const auto& range) {
    RayCounts local;
    for (size_t i = range.begin(); i != range.end(); ++i) {
      const Tile& t = tiles[i];
      const RayCounts n = render_tile(states[t.shot], t, views[shots[t.shot].view], sensor_noise,
                                      tile_luminance[i]);
      local.camera += n.camera;
      local.shadow += n.shadow;
    }
    camera_rays += local.camera;
    shadow_rays += local.shadow;
  });
  if (auto_exposure_) {
    // Summed in tile order, so the gain does not depend on the thread schedule.
    std::vector<double> sums(shots.size(), 0.0);
    for (size_t i = 0; i < tiles.size(); ++i) sums[tiles[i].shot] += tile_luminance[i];
    for (size_t i = 0; i < shots.size(); ++i) {
      RenderedView& v = views[shots[i].view];
      v.mean_luminance = sums[i] / static_cast<double>(v.rgb.total());
      const auto view = static_cast<size_t>(shots[i].view);
      v.gain = view < exposure_reference_.size() && v.mean_luminance > 0
                   ? exposure_reference_[view] / v.mean_luminance
                   : 1.0;
      states[i].gain = static_cast<float>(v.gain);
    }
    tbb::parallel_for(size_t{0}, tiles.size(), [&](size_t i) {
      const Tile& t = tiles[i];
      expose_tile(states[t.shot], t, views[shots[t.shot].view], sensor_noise);
    });
  }
  return {camera_rays.load(), shadow_rays.load()};
}

// Per-lane state as structure-of-arrays, so that the lighting loops vectorise.
struct Renderer::Lanes {
  static constexpr int N = CameraRays::kLanes;
  RayHitPacket<N> packet;
  RTCScene scene = nullptr;  // what this sample's camera rays trace
  bool spread = false;       // their times differ (blur samples, rolling shutter)
  alignas(64) int valid[N], hit[N];
  alignas(64) float red[N], green[N], blue[N];  // radiance, summed over samples
  alignas(64) float albedo[3][N], normal[3][N], geometric[3][N], position[3][N];
  int part[N], actor[N];
  // Each lane's pixel's random shift of the sample pattern: x and y jitter, time in the part.
  alignas(64) float shift[3][N];
};

SIMCAP_AVX2_CLONES void Renderer::trace_camera_rays(const ShotState& shot, int px, int py,
                                                    int sample, Lanes& l) const {
  constexpr int N = Lanes::N, B = CameraRays::kBlock;
  const CameraRays& rays = *shot.rays;
  auto& ray = l.packet.ray;
  if (sample == 0) {
    // memcpy of a constant size is inlined as vector moves; std::copy_n became memmove calls.
    const float* block = rays.block(px / B, py / B);
    std::memcpy(ray.dir_x, block, sizeof ray.dir_x);
    std::memcpy(ray.dir_y, block + N, sizeof ray.dir_y);
    std::memcpy(ray.dir_z, block + 2 * N, sizeof ray.dir_z);
  } else {
    alignas(64) float jx[N], jy[N];
    const std::array<float, 3>& p = pattern_[sample];
    for (int k = 0; k < N; ++k) {
      jx[k] = wrap01(l.shift[0][k] + p[0]) - 0.5f;
      jy[k] = wrap01(l.shift[1][k] + p[1]) - 0.5f;
    }
    rays.jittered_block(px, py, jx, jy, l.valid, ray.dir_x, ray.dir_y, ray.dir_z);
  }
  const Eigen::Vector3f o = rays.origin();
  for (int k = 0; k < N; ++k) start_camera_ray(l.packet, k, o, static_cast<unsigned>(k));
  for (int k = 0; k < N; ++k) ray.time[k] = shot.times.at_row(py + k / B);
  if (shot.blur && sample > 0) {
    // The exposure is cut into samples_ equal parts: sample 0, the pixel-centre ray at the
    // exposure's middle that also gives the labels, is the midpoint of the central part
    // [1/2 - 1/(2n), 1/2 + 1/(2n)); sample s > 0 is jittered within the s-th of the others, u
    // counting the exposure without the central part.
    const float part = 1.f / static_cast<float>(samples_);
    const float gap_start = 0.5f - 0.5f * part;
    const float in_part = pattern_[sample][2];
    for (int k = 0; k < N; ++k) {
      const float u = (static_cast<float>(sample - 1) + wrap01(l.shift[2][k] + in_part)) * part;
      const float t = ray.time[k] + shot.times.exposure * ((u < gap_start ? u : u + part) - 0.5f);
      ray.time[k] = std::clamp(t, 0.f, 1.f);
    }
  }
  // Without a rolling shutter, the pixel-centre rays (and every sample without blur) share one
  // time, which may have a still scene of its own; rays at other times need the motion-blur
  // scene only near the moving bodies.
  l.spread = shot.times.per_row != 0 || (sample > 0 && shot.blur);
  if (l.spread) {
    const float* const org[3] = {ray.org_x, ray.org_y, ray.org_z};
    const float* const dir[3] = {ray.dir_x, ray.dir_y, ray.dir_z};
    l.scene = embree_.scene_for<N>(l.valid, org, dir, ray.tfar);
  } else {
    l.scene = embree_.scene_at(ray.time[0]);
  }
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  intersect_packet<N>(l.valid, l.scene, &context, l.packet);
  for (int k = 0; k < N; ++k) {
    l.hit[k] = l.valid[k] && l.packet.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID ? -1 : 0;
    const float t = l.hit[k] ? ray.tfar[k] : 0.f;
    l.position[0][k] = o.x() + t * ray.dir_x[k];
    l.position[1][k] = o.y() + t * ray.dir_y[k];
    l.position[2][k] = o.z() + t * ray.dir_z[k];
  }
}

// A gather, lane by lane. Neighbouring rays mostly hit the same flat, untextured triangle of a
// wall, whose surface point is then the same for all of them: it is looked up once.
SIMCAP_AVX2_CLONES void Renderer::look_up_surfaces(Lanes& l) const {
  constexpr int N = Lanes::N;
  const auto& hit = l.packet.hit;
  auto look_up = [&](int k) {
    HitRecord h;
    h.geom_id = hit.geomID[k];
    h.inst_id = hit.instID[0][k];
    h.prim_id = hit.primID[k];
    h.u = hit.u[k];
    h.v = hit.v[k];
    h.ng = {hit.Ng_x[k], hit.Ng_y[k], hit.Ng_z[k]};
    h.time = l.packet.ray.time[k];
    const SurfacePoint sp =
        embree_.surface(h, {l.position[0][k], l.position[1][k], l.position[2][k]},
                        {l.packet.ray.dir_x[k], l.packet.ray.dir_y[k], l.packet.ray.dir_z[k]});
    l.actor[k] = sp.actor;
    l.part[k] = sp.part;
    for (int c = 0; c < 3; ++c) {
      l.albedo[c][k] = sp.albedo[c];
      l.normal[c][k] = sp.normal[c];
      l.geometric[c][k] = sp.geometric_normal[c];
    }
    return embree_.uniform_surface(h);
  };
  auto copy_lane = [&](int from, int to) {
    l.actor[to] = l.actor[from];
    l.part[to] = l.part[from];
    for (int c = 0; c < 3; ++c) {
      l.albedo[c][to] = l.albedo[c][from];
      l.normal[c][to] = l.normal[c][from];
      l.geometric[c][to] = l.geometric[c][from];
    }
  };
  auto same_triangle = [&](int a, int b) {
    return hit.geomID[a] == hit.geomID[b] && hit.primID[a] == hit.primID[b] &&
           hit.instID[0][a] == hit.instID[0][b];
  };
  int all_same = -1;
  for (int k = 0; k < N; ++k) all_same &= l.hit[k] & -static_cast<int>(same_triangle(k, 0));
  if (all_same && look_up(0)) {
    for (int k = 1; k < N; ++k) copy_lane(0, k);
    return;
  }
  int uniform_lane = -1;
  for (int k = 0; k < N; ++k) {
    if (!l.hit[k]) {
      l.actor[k] = -1;
      l.part[k] = 0;
      for (int c = 0; c < 3; ++c) l.albedo[c][k] = l.normal[c][k] = l.geometric[c][k] = 0.f;
    } else if (uniform_lane >= 0 && same_triangle(k, uniform_lane)) {
      copy_lane(uniform_lane, k);
    } else {
      uniform_lane = look_up(k) ? k : -1;
    }
  }
}

SIMCAP_AVX2_CLONES int Renderer::add_light(const LightSource& light, Lanes& l) const {
  constexpr int N = Lanes::N;
  // The shadow packet's direction and length arrays double as the light vectors.
  RayPacket<N> shadow;
  alignas(64) int lit[N];
  alignas(64) float weight[N];
  float* const dir[3] = {shadow.dir_x, shadow.dir_y, shadow.dir_z};
  if (light.directional) {
    const Eigen::Vector3f v = light.towards_light;
    for (int k = 0; k < N; ++k) {
      shadow.dir_x[k] = v.x();
      shadow.dir_y[k] = v.y();
      shadow.dir_z[k] = v.z();
      shadow.tfar[k] = kInf;
    }
  } else {
    for (int k = 0; k < N; ++k) {
      for (int c = 0; c < 3; ++c) dir[c][k] = light.position[c] - l.position[c][k];
      shadow.tfar[k] =
          std::sqrt(dir[0][k] * dir[0][k] + dir[1][k] * dir[1][k] + dir[2][k] * dir[2][k]);
      for (int c = 0; c < 3; ++c) dir[c][k] /= shadow.tfar[k];
    }
  }
  const float intensity = light.intensity;
  for (int k = 0; k < N; ++k) {
    const float cosine =
        l.normal[0][k] * dir[0][k] + l.normal[1][k] * dir[1][k] + l.normal[2][k] * dir[2][k];
    const float facing = l.geometric[0][k] * dir[0][k] + l.geometric[1][k] * dir[1][k] +
                         l.geometric[2][k] * dir[2][k];
    const bool lights_it = (l.hit[k] != 0) & (cosine > 0.f) & (facing > 0.f);
    lit[k] = lights_it ? -1 : 0;
    weight[k] = lights_it ? intensity * cosine : 0.f;
  }
  int shadow_rays = 0;
  if (light.shadows) {
    for (int k = 0; k < N; ++k) shadow_rays -= lit[k];
  }
  if (shadow_rays > 0) {
    for (int k = 0; k < N; ++k) {
      shadow.org_x[k] = l.position[0][k] + kShadowOffset * l.geometric[0][k];
      shadow.org_y[k] = l.position[1][k] + kShadowOffset * l.geometric[1][k];
      shadow.org_z[k] = l.position[2][k] + kShadowOffset * l.geometric[2][k];
      shadow.tnear[k] = 0.f;
      shadow.time[k] = l.packet.ray.time[k];
      shadow.mask[k] = kShadowCasterMask;
      shadow.id[k] = static_cast<unsigned>(k);
      shadow.flags[k] = 0;
    }
    RTCScene scene = l.scene;
    if (l.spread) {
      const float* const org[3] = {shadow.org_x, shadow.org_y, shadow.org_z};
      scene = embree_.scene_for<N>(lit, org, dir, shadow.tfar);
    }
    scene = embree_.casters_of(scene);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    occluded_packet<N>(lit, scene, &context, shadow);
    for (int k = 0; k < N; ++k) {
      if (shadow.tfar[k] < 0.f) weight[k] = 0.f;
    }
  }
  for (int k = 0; k < N; ++k) {
    l.red[k] += weight[k] * l.albedo[0][k];
    l.green[k] += weight[k] * l.albedo[1][k];
    l.blue[k] += weight[k] * l.albedo[2][k];
  }
  return shadow_rays;
}

void Renderer::add_sensor_noise(int px, int py, const ShotState& shot, const int* valid,
                                cv::Vec3b* const* rgb_rows, float* const* depth_rows) const {
  constexpr int B = CameraRays::kBlock;
  for (int k = 0; k < Lanes::N; ++k) {
    if (!valid[k]) continue;
    const int x = px + k % B, y = py + k / B;
    const std::uint64_t pixel = static_cast<std::uint64_t>(y) * shot.rays->width() + x;
    cv::Vec3b& rgb = rgb_rows[k / B][x];
    if (noise_.rgb_sigma > 0) {
      for (int c = 0; c < 3; ++c) {
        const float n = standard_normal(
            random_bits_after(shot.rgb_noise, {3 * pixel + static_cast<std::uint64_t>(c)}));
        const float level = std::round(rgb[c] + static_cast<float>(noise_.rgb_sigma) * n);
        rgb[c] = static_cast<std::uint8_t>(std::clamp(level, 0.f, 255.f));
      }
    }
    float& depth = depth_rows[k / B][x];
    if (noise_.depth_sigma_m > 0 && std::isfinite(depth)) {
      depth += static_cast<float>(noise_.depth_sigma_m) *
               standard_normal(random_bits_after(shot.depth_noise, {pixel}));
    }
  }
}

SIMCAP_AVX2_CLONES void Renderer::write_colour(int px, int py, const ShotState& shot,
                                               const int* valid, float* linear, bool sensor_noise,
                                               cv::Vec3b* const* rgb_rows,
                                               float* const* depth_rows) const {
  constexpr int N = Lanes::N, B = CameraRays::kBlock;
  static_assert(3 * N == SrgbEncoder::kBatch);
  alignas(64) std::uint8_t codes[3 * N];
  // Blocks of a uniformly lit wall share one colour: encode it once.
  int one_colour = 1;
  for (int k = 0; k < N; ++k) {
    one_colour &= (linear[k] == linear[0]) & (linear[N + k] == linear[N]) &
                  (linear[2 * N + k] == linear[2 * N]);
  }
  if (one_colour) {
    for (int c = 0; c < 3; ++c) std::memset(codes + c * N, encode_(linear[c * N]), N);
  } else {
    encode_.encode(linear, codes);
  }
  for (int k = 0; k < N; ++k) {
    if (valid[k]) {
      rgb_rows[k / B][px + k % B] = cv::Vec3b(codes[k], codes[N + k], codes[2 * N + k]);
    }
  }
  if (sensor_noise && (noise_.rgb_sigma > 0 || noise_.depth_sigma_m > 0)) {
    add_sensor_noise(px, py, shot, valid, rgb_rows, depth_rows);
  }
}

SIMCAP_AVX2_CLONES RayCounts Renderer::render_tile(const ShotState& shot, const Tile& tile,
                                                   RenderedView& view, bool sensor_noise,
                                                   double& luminance) const {
  constexpr int N = Lanes::N, B = CameraRays::kBlock;
  const CameraRays& rays = *shot.rays;
  const bool single_actor = embree_.actor_count() == 1;
  const int last_sample = samples_ - 1;
  RayCounts counts;
  Lanes l;
  for (int py = tile.y0; py < tile.y1; py += B) {
    // Image rows of the blocks; rows below the image are never written (their lanes are invalid).
    float* depth_rows[B];
    std::uint8_t *mask_rows[B], *parts_rows[B];
    cv::Vec3b* rgb_rows[B];
    for (int r = 0; r < B; ++r) {
      const int y = std::min(py + r, tile.y1 - 1);
      depth_rows[r] = view.depth.ptr<float>(y);
      mask_rows[r] = view.mask.ptr<std::uint8_t>(y);
      parts_rows[r] = view.parts.ptr<std::uint8_t>(y);
      rgb_rows[r] = view.rgb.ptr<cv::Vec3b>(y);
    }
    for (int px = tile.x0; px < tile.x1; px += B) {
      const bool whole_block = px + B <= tile.x1 && py + B <= tile.y1;
      int valid_lanes = 0;
      for (int k = 0; k < N; ++k) {
        l.valid[k] = px + k % B < tile.x1 && py + k / B < tile.y1 ? -1 : 0;
        valid_lanes -= l.valid[k];
      }
      counts.camera += static_cast<std::uint64_t>(valid_lanes * samples_);
      if (last_sample > 0) {
        for (int k = 0; k < N; ++k) {
          const std::uint64_t pixel =
              static_cast<std::uint64_t>(py + k / B) * rays.width() + px + k % B;
          const std::uint64_t bits = random_bits_after(shot.jitter, {pixel});
          l.shift[0][k] = uniform01(bits);
          l.shift[1][k] = uniform01(bits << 24);
          l.shift[2][k] = shot.blur ? uniform01(random_bits_after(shot.shutter, {pixel})) : 0.f;
        }
      }
      for (int s = 0; s <= last_sample; ++s) {
        trace_camera_rays(shot, px, py, s, l);
        look_up_surfaces(l);
        if (s == 0) {
          const float* z_scale = rays.block(px / B, py / B) + 3 * N;
          alignas(64) float depth[N];
          alignas(64) std::uint8_t mask[N], parts[N];
          for (int k = 0; k < N; ++k) {
            depth[k] = l.hit[k] ? l.packet.ray.tfar[k] * z_scale[k] : kInf;
            mask[k] = static_cast<std::uint8_t>(
                l.actor[k] < 0 ? 0 : (single_actor ? 255 : l.actor[k] + 1));
            parts[k] = static_cast<std::uint8_t>(l.part[k]);
          }
          store_block(depth, l.valid, whole_block, px, depth_rows);
          store_block(mask, l.valid, whole_block, px, mask_rows);
          store_block(parts, l.valid, whole_block, px, parts_rows);
          if (normals_) {
            for (int k = 0; k < N; ++k) {
              if (!l.valid[k]) continue;
              view.normal.at<cv::Vec3f>(py + k / B, px + k % B) =
                  cv::Vec3f(l.normal[0][k], l.normal[1][k], l.normal[2][k]);
            }
          }
        }
        // The first sample starts the sums, which are not zeroed per block (a memset, 1.5 %).
        const bool first = s == 0;
        for (int k = 0; k < N; ++k) {
          l.red[k] = (first ? 0.f : l.red[k]) + ambient_ * l.albedo[0][k];
          l.green[k] = (first ? 0.f : l.green[k]) + ambient_ * l.albedo[1][k];
          l.blue[k] = (first ? 0.f : l.blue[k]) + ambient_ * l.albedo[2][k];
        }
        for (const LightSource& light : shot.lights) {
          counts.shadow += static_cast<std::uint64_t>(add_light(light, l));
        }
      }

      alignas(64) float linear[3 * N];
      const float scale = 1.f / static_cast<float>(samples_);
      for (int k = 0; k < N; ++k) {
        linear[k] = scale * l.red[k];
        linear[N + k] = scale * l.green[k];
        linear[2 * N + k] = scale * l.blue[k];
      }
      if (!auto_exposure_) {
        write_colour(px, py, shot, l.valid, linear, sensor_noise, rgb_rows, depth_rows);
        continue;
      }
      // Auto exposure needs the whole image's mean first: keep the colour for expose_tile().
      for (int k = 0; k < N; ++k) {
        if (!l.valid[k]) continue;
        const cv::Vec3f c(linear[k], linear[N + k], linear[2 * N + k]);
        view.linear.at<cv::Vec3f>(py + k / B, px + k % B) = c;
        luminance += kLuma[0] * c[0] + kLuma[1] * c[1] + kLuma[2] * c[2];
      }
    }
  }
  return counts;
}

void Renderer::expose_tile(const ShotState& shot, const Tile& tile, RenderedView& view,
                           bool sensor_noise) const {
  constexpr int N = Lanes::N, B = CameraRays::kBlock;
  for (int py = tile.y0; py < tile.y1; py += B) {
    float* depth_rows[B];
    cv::Vec3b* rgb_rows[B];
    for (int r = 0; r < B; ++r) {
      const int y = std::min(py + r, tile.y1 - 1);
      depth_rows[r] = view.depth.ptr<float>(y);
      rgb_rows[r] = view.rgb.ptr<cv::Vec3b>(y);
    }
    for (int px = tile.x0; px < tile.x1; px += B) {
      alignas(64) int valid[N];
      alignas(64) float linear[3 * N];
      for (int k = 0; k < N; ++k) {
        const int x = px + k % B, y = py + k / B;
        valid[k] = x < tile.x1 && y < tile.y1 ? -1 : 0;
        const cv::Vec3f c = valid[k] ? view.linear.at<cv::Vec3f>(y, x) : cv::Vec3f();
        for (int ch = 0; ch < 3; ++ch) linear[ch * N + k] = shot.gain * c[ch];
      }
      write_colour(px, py, shot, valid, linear, sensor_noise, rgb_rows, depth_rows);
    }
  }
}

}  // namespace simcap
