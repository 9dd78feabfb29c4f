// `simcap bench render`: the renderer's throughput on a scene, measured three ways in one run —
// whole frames with every output written, the renderer's ray rate without writing, and a bare
// Embree loop tracing the same rays against the same geometry (the attainable limit).
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "sim/embree_scene.h"

namespace simcap {

struct RenderBenchOptions {
  int frames = 60;                     // frames of the full render (with image writing)
  int ray_frames = 20;                 // frames spread over those for the ray measurements
  std::vector<std::string> overrides;  // scene overrides (load_scene)
  // > 1: also the cost of motion blur, ray_frames frames captured with this many samples per
  // pixel over the whole frame period (render.shutter 1) and with one sample, alternated.
  int blur_samples = 0;
  bool quiet = false;
};

struct RenderBenchResult {
  int frames = 0, cameras = 0, threads = 0;
  // Full render into a temporary folder: every image, table and plate written.
  double frames_per_s = 0;
  // Frame sets per CPU-second of the process times the threads: what `threads` idle cores would
  // reach if the frames kept them all busy (a shared machine slows frames_per_s, not this).
  double frames_per_cpu_s = 0;
  double write_share = 0;  // image-writing thread-seconds / (wall seconds * threads)
  // Rays traced by the renderer (camera + shadow rays) per second of rendering (shading and
  // labels included, no writing), and by the bare loop: the same camera rays, then an
  // occlusion ray towards each shadowing light from every hit, nothing else.
  double camera_rays_per_frame = 0, shadow_rays_per_frame = 0;
  double mrays_per_s = 0;
  double embree_mrays_per_s = 0;  // best packet width
  // The same per CPU-second of the process, which a shared machine disturbs less.
  double mrays_per_cpu_s = 0, embree_mrays_per_cpu_s = 0;
  struct Packet {
    int width;
    double mrays_per_s, mrays_per_cpu_s;
  };
  std::vector<Packet> embree_by_packet;
  // Per-frame cost of updating the bodies' BVH and of rendering after it, per strategy.
  struct BvhUpdate {
    BodyBvhUpdate update;
    double update_ms, render_ms;
  };
  std::vector<BvhUpdate> bvh_updates;
  // Motion blur (blur_samples > 1): CPU milliseconds per frame set of RenderSetup::capture
  // (bodies posed over the exposure, ground truth, every camera rendered; no writing).
  double blur_cpu_ms = 0, one_sample_cpu_ms = 0;
};

RenderBenchResult run_render_benchmark(const std::filesystem::path& scene_file,
                                       const RenderBenchOptions& options);

// The report `simcap bench render` prints; its last line is
// "frames_per_s=X mrays_per_s=Y embree_mrays_per_s=Z embree_ratio=Y/Z".
void print_render_benchmark(const RenderBenchResult& result,
                            const std::filesystem::path& scene_file, std::FILE* out);

}  // namespace simcap
