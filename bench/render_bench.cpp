#include "bench/render_bench.h"

#include <unistd.h>

#include <oneapi/tbb/info.h>
#include <oneapi/tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <ctime>
#include <limits>

#include "core/progress.h"
#include "sim/embree_packets.h"
#include "sim/render_job.h"
#include "sim/render_setup.h"

namespace simcap {
namespace fs = std::filesystem;
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// CPU time of the whole process: on a shared machine it measures the work done, where wall
// time also measures the other processes.
double cpu_seconds() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// The lights the renderer traces shadow rays to: unit direction towards a directional light,
// or a point light's position.
struct ShadowLight {
  bool directional;
  Eigen::Vector3f vector;
};

std::vector<ShadowLight> shadow_lights(const Scene& scene) {
  std::vector<ShadowLight> out;
  for (const Light& l : scene.lights) {
    if (!l.shadows) continue;
    if (l.kind == Light::Kind::directional) {
      out.push_back({true, (-l.direction).normalized().cast<float>()});
    } else {
      out.push_back({false, l.position.cast<float>()});
    }
  }
  return out;
}

// Camera rays through every pixel centre of every camera (once per sample), then from each hit
// an occlusion ray towards each shadowing light; no shading and no output. Same tiles and TBB
// parallelism as the renderer.
template <int N>
RayCounts bare_embree_loop(RTCScene scene, const std::vector<CameraRays>& cameras,
                           const std::vector<ShadowLight>& lights, int samples) {
  using Shape = PacketShape<N>;
  struct Tile {
    int camera, x0, y0;
  };
  std::vector<Tile> tiles;
  for (size_t c = 0; c < cameras.size(); ++c) {
    for (int y = 0; y < cameras[c].height(); y += Renderer::kTileHeight) {
      for (int x = 0; x < cameras[c].width(); x += Renderer::kTileWidth) {
        tiles.push_back({static_cast<int>(c), x, y});
      }
    }
  }
  std::atomic<std::uint64_t> camera_rays{0}, shadow_rays{0};
  tbb::parallel_for(tbb::blocked_range<size_t>(0, tiles.size(), 1), [&](const auto& range) {
    RayCounts local;
    RTCIntersectContext context;
    for (size_t i = range.begin(); i != range.end(); ++i) {
      const CameraRays& rays = cameras[tiles[i].camera];
      const int x1 = std::min(rays.width(), tiles[i].x0 + Renderer::kTileWidth);
      const int y1 = std::min(rays.height(), tiles[i].y0 + Renderer::kTileHeight);
      const Eigen::Vector3f o = rays.origin();
      for (int s = 0; s < samples; ++s) {
        for (int py = tiles[i].y0; py < y1; py += Shape::height) {
          for (int px = tiles[i].x0; px < x1; px += Shape::width) {
            RayHitPacket<N> packet;
            alignas(64) int valid[N];
            const float* block = rays.block(px / CameraRays::kBlock, py / CameraRays::kBlock);
            if constexpr (N == CameraRays::kLanes) {  // the packet is one of CameraRays' blocks
              std::copy_n(block, N, packet.ray.dir_x);
              std::copy_n(block + N, N, packet.ray.dir_y);
              std::copy_n(block + 2 * N, N, packet.ray.dir_z);
            }
            for (int k = 0; k < N; ++k) {
              const int x = px + k % Shape::width, y = py + k / Shape::width;
              valid[k] = x < x1 && y < y1 ? -1 : 0;
              if constexpr (N < CameraRays::kLanes) {
                const int lane =
                    (y % CameraRays::kBlock) * CameraRays::kBlock + x % CameraRays::kBlock;
                packet.ray.dir_x[k] = block[lane];
                packet.ray.dir_y[k] = block[CameraRays::kLanes + lane];
                packet.ray.dir_z[k] = block[2 * CameraRays::kLanes + lane];
              }
              start_camera_ray(packet, k, o, 0);
              local.camera += valid[k] ? 1 : 0;
            }
            rtcInitIntersectContext(&context);
            context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
            intersect_packet<N>(valid, scene, &context, packet);
            for (const ShadowLight& light : lights) {
              RayPacket<N> shadow;
              alignas(64) int shadow_valid[N];
              for (int k = 0; k < N; ++k) {
                shadow_valid[k] =
                    valid[k] && packet.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID ? -1 : 0;
                if (!shadow_valid[k]) continue;
                const Eigen::Vector3f d(packet.ray.dir_x[k], packet.ray.dir_y[k],
                                        packet.ray.dir_z[k]);
                // Backing off along the ray keeps the origin on the camera's side of the surface.
                const Eigen::Vector3f p = o + (packet.ray.tfar[k] * 0.9999f) * d;
                Eigen::Vector3f l = light.vector;
                float far = std::numeric_limits<float>::infinity();
                if (!light.directional) {
                  l = light.vector - p;
                  far = l.norm();
                  l /= far;
                }
                shadow.org_x[k] = p.x();
                shadow.org_y[k] = p.y();
                shadow.org_z[k] = p.z();
                shadow.dir_x[k] = l.x();
                shadow.dir_y[k] = l.y();
                shadow.dir_z[k] = l.z();
                shadow.tnear[k] = 0.f;
                shadow.tfar[k] = far;
                shadow.time[k] = 0.f;
                shadow.mask[k] = kShadowCasterMask;
                shadow.id[k] = 0;
                shadow.flags[k] = 0;
                ++local.shadow;
              }
              rtcInitIntersectContext(&context);
              occluded_packet<N>(shadow_valid, scene, &context, shadow);
            }
          }
        }
      }
    }
    camera_rays += local.camera;
    shadow_rays += local.shadow;
  });
  return {camera_rays.load(), shadow_rays.load()};
}

using BareLoop = RayCounts (*)(RTCScene, const std::vector<CameraRays>&,
                               const std::vector<ShadowLight>&, int);

// Frames captured with motion blur and with one sample, alternating which goes first, so that
// both see the same share of the machine.
void measure_blur(const Scene& scene, int ray_frames, int frames, const RenderBenchOptions& options,
                  RenderBenchResult& result) {
  Scene one = scene, blurred = scene;
  one.render.samples_per_pixel = 1;
  blurred.render.samples_per_pixel = options.blur_samples;
  blurred.render.shutter = 1;
  RenderSetup one_setup(one), blur_setup(blurred);
  std::vector<RenderedView> views;
  double cpu[2] = {0, 0};
  Progress progress("bench render: blur", ray_frames, options.quiet);
  for (int i = 0; i < ray_frames; ++i) {
    const int frame = static_cast<int>(static_cast<long>(i) * frames / ray_frames);
    for (int k = 0; k < 2; ++k) {
      const int which = (i + k) % 2;
      const double c0 = cpu_seconds();
      (which == 0 ? one_setup : blur_setup).capture(frame, &views);
      cpu[which] += cpu_seconds() - c0;
    }
    progress.advance();
  }
  progress.finish();
  result.one_sample_cpu_ms = 1e3 * cpu[0] / ray_frames;
  result.blur_cpu_ms = 1e3 * cpu[1] / ray_frames;
}

}  // namespace

RenderBenchResult run_render_benchmark(const fs::path& scene_file,
                                       const RenderBenchOptions& options) {
  RenderBenchResult result;
  result.threads = tbb::info::default_concurrency();

  // 1. Whole frames, every output written, in a temporary folder.
  const fs::path out =
      fs::temp_directory_path() / ("simcap_bench_render_" + std::to_string(getpid()));
  fs::remove_all(out);
  RenderOptions render_options;
  render_options.frames = options.frames;
  render_options.overrides = options.overrides;
  render_options.quiet = options.quiet;
  RenderSummary summary;
  const double cpu0 = cpu_seconds();
  try {
    summary = render_dataset(scene_file, out, render_options);
  } catch (...) {
    fs::remove_all(out);
    throw;
  }
  const double render_cpu_s = cpu_seconds() - cpu0;
  fs::remove_all(out);
  result.frames = summary.frames;
  result.frames_per_cpu_s = summary.frames * result.threads / render_cpu_s;
  result.cameras = summary.cameras;
  result.frames_per_s = summary.frames / summary.seconds;
  result.write_share = summary.write_seconds / (summary.seconds * result.threads);

  // 2. Ray rates, renderer and bare loops interleaved frame by frame on the same geometry.
  Scene scene = load_scene(scene_file, options.overrides);
  const int ray_frames = std::max(1, std::min(options.ray_frames, summary.frames));
  const std::vector<ShadowLight> lights = shadow_lights(scene);
  const std::pair<int, BareLoop> loops[] = {{1, bare_embree_loop<1>},
                                            {4, bare_embree_loop<4>},
                                            {8, bare_embree_loop<8>},
                                            {16, bare_embree_loop<16>}};
  Progress progress("bench render: rays", 2L * ray_frames, options.quiet);
  for (const BodyBvhUpdate update : {BodyBvhUpdate::refit, BodyBvhUpdate::rebuild}) {
    RenderSetup setup(scene, update);
    double update_s = 0, render_s = 0, render_cpu = 0, bare_s[4] = {0, 0, 0, 0};
    double bare_cpu[4] = {0, 0, 0, 0};
    RayCounts rendered, bare[4];
    std::vector<RenderedView> views;
    for (int i = 0; i < ray_frames; ++i) {
      const int frame = static_cast<int>(static_cast<long>(i) * summary.frames / ray_frames);
      auto t0 = Clock::now();
      setup.pose(frame);
      update_s += seconds_since(t0);
      t0 = Clock::now();
      double c0 = cpu_seconds();
      const RayCounts n = setup.renderer().render(setup.cameras(), frame, views);
      render_s += seconds_since(t0);
      render_cpu += cpu_seconds() - c0;
      rendered.camera += n.camera;
      rendered.shadow += n.shadow;
      if (update == BodyBvhUpdate::refit) {
        for (int k = 0; k < 4; ++k) {
          t0 = Clock::now();
          c0 = cpu_seconds();
          const RayCounts b = loops[k].second(setup.embree().handle(), setup.cameras(), lights,
                                              std::max(1, scene.render.samples_per_pixel));
          bare_s[k] += seconds_since(t0);
          bare_cpu[k] += cpu_seconds() - c0;
          bare[k].camera += b.camera;
          bare[k].shadow += b.shadow;
        }
      }
      progress.advance();
    }
    result.bvh_updates.push_back(
        {update, 1e3 * update_s / ray_frames, 1e3 * render_s / ray_frames});
    if (update != BodyBvhUpdate::refit) continue;
    result.camera_rays_per_frame = static_cast<double>(rendered.camera) / ray_frames;
    result.shadow_rays_per_frame = static_cast<double>(rendered.shadow) / ray_frames;
    const auto rays = static_cast<double>(rendered.camera + rendered.shadow);
    result.mrays_per_s = 1e-6 * rays / render_s;
    result.mrays_per_cpu_s = 1e-6 * rays / render_cpu;
    for (int k = 0; k < 4; ++k) {
      const auto n = static_cast<double>(bare[k].camera + bare[k].shadow);
      result.embree_by_packet.push_back(
          {loops[k].first, 1e-6 * n / bare_s[k], 1e-6 * n / bare_cpu[k]});
      result.embree_mrays_per_s = std::max(result.embree_mrays_per_s, 1e-6 * n / bare_s[k]);
      result.embree_mrays_per_cpu_s =
          std::max(result.embree_mrays_per_cpu_s, 1e-6 * n / bare_cpu[k]);
    }
  }
  progress.finish();
  if (options.blur_samples > 1) measure_blur(scene, ray_frames, summary.frames, options, result);
  return result;
}

void print_render_benchmark(const RenderBenchResult& result,
                            const std::filesystem::path& scene_file, std::FILE* out) {
  std::fprintf(out, "bench render: %s, %d cameras, %d threads\n", scene_file.string().c_str(),
               result.cameras, result.threads);
  std::fprintf(out,
               "full render (RGB, depth, mask, parts, truth; images written): %d frames, "
               "%.2f frames/s, image writing %.0f%% of the CPU\n",
               result.frames, result.frames_per_s, 100 * result.write_share);
  std::fprintf(out,
               "the same per CPU-second x %d threads (what idle cores would give): %.2f frames/s\n",
               result.threads, result.frames_per_cpu_s);
  std::fprintf(out, "rays per frame: %.0f camera + %.0f shadow\n", result.camera_rays_per_frame,
               result.shadow_rays_per_frame);
  for (const auto& p : result.embree_by_packet) {
    std::fprintf(out, "bare Embree loop, packets of %2d: %.1f Mrays/s\n", p.width, p.mrays_per_s);
  }
  std::fprintf(out,
               "per CPU-second of this process (less disturbed by other processes): renderer "
               "%.1f Mrays, bare Embree %.1f Mrays, ratio %.2f\n",
               result.mrays_per_cpu_s, result.embree_mrays_per_cpu_s,
               result.mrays_per_cpu_s / result.embree_mrays_per_cpu_s);
  for (const auto& b : result.bvh_updates) {
    std::fprintf(out, "body BVH %-7s: update %.2f ms/frame, render %.1f ms/frame\n",
                 b.update == BodyBvhUpdate::refit ? "refit" : "rebuild", b.update_ms, b.render_ms);
  }
  if (result.blur_cpu_ms > 0) {
    std::fprintf(out,
                 "motion blur (shutter 1): %.1f CPU-ms per frame set, one sample %.1f, ratio "
                 "%.2f\n",
                 result.blur_cpu_ms, result.one_sample_cpu_ms,
                 result.blur_cpu_ms / result.one_sample_cpu_ms);
  }
  std::fprintf(out,
               "frames_per_s=%.2f mrays_per_s=%.1f embree_mrays_per_s=%.1f embree_ratio=%.2f\n",
               result.frames_per_s, result.mrays_per_s, result.embree_mrays_per_s,
               result.mrays_per_s / result.embree_mrays_per_s);
}

}  // namespace simcap
