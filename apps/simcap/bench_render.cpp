#include <cstdio>
#include <filesystem>

#include "apps/simcap/bench_commands.h"
#include "apps/simcap/number_checks.h"
#include "scenes/scene.h"
#include "sim/render_benchmark.h"

namespace simcap::cli {
namespace {

struct BenchRenderArgs {
  std::filesystem::path scene;
  RenderBenchOptions options;
};

int run_bench_render(const BenchRenderArgs& args) {
  const std::filesystem::path scene =
      args.scene.empty() ? shipped_scene_path("studio4") : args.scene;
  const RenderBenchResult r = run_render_benchmark(scene, args.options);
  std::printf("bench render: %s, %d cameras, %d threads\n", scene.string().c_str(), r.cameras,
              r.threads);
  std::printf(
      "full render (RGB, depth, mask, parts, truth; images written): %d frames, "
      "%.2f frames/s, image writing %.0f%% of the CPU\n",
      r.frames, r.frames_per_s, 100 * r.write_share);
  std::printf("rays per frame: %.0f camera + %.0f shadow\n", r.camera_rays_per_frame,
              r.shadow_rays_per_frame);
  for (const auto& p : r.embree_by_packet) {
    std::printf("bare Embree loop, packets of %2d: %.1f Mrays/s\n", p.width, p.mrays_per_s);
  }
  std::printf(
      "per CPU-second of this process (less disturbed by other processes): renderer "
      "%.1f Mrays, bare Embree %.1f Mrays, ratio %.2f\n",
      r.mrays_per_cpu_s, r.embree_mrays_per_cpu_s, r.mrays_per_cpu_s / r.embree_mrays_per_cpu_s);
  for (const auto& b : r.bvh_updates) {
    std::printf("body BVH %-7s: update %.2f ms/frame, render %.1f ms/frame\n",
                b.update == BodyBvhUpdate::refit ? "refit" : "rebuild", b.update_ms, b.render_ms);
  }
  std::printf("frames_per_s=%.2f mrays_per_s=%.1f embree_mrays_per_s=%.1f embree_ratio=%.2f\n",
              r.frames_per_s, r.mrays_per_s, r.embree_mrays_per_s,
              r.mrays_per_s / r.embree_mrays_per_s);
  return 0;
}

}  // namespace

void add_bench_render(CLI::App& bench, Action& action) {
  auto* cmd = bench.add_subcommand(
      "render", "Renderer frames/s (images written) and its ray rate against a bare Embree loop");
  static BenchRenderArgs args;
  cmd->add_option("scene", args.scene, "Scene file (default: the shipped scenes/studio4.yaml)");
  cmd->add_option("--frames", args.options.frames, "Frames of the full render")
      ->capture_default_str()
      ->check(positive_number());
  cmd->add_option("--ray-frames", args.options.ray_frames,
                  "Frames (spread over those) for the ray-rate measurements")
      ->capture_default_str()
      ->check(positive_number());
  cmd->add_option("--set", args.options.overrides, "Scene override key.path=value, repeatable");
  cmd->add_flag("-q,--quiet", args.options.quiet, "No progress on stderr");
  cmd->footer(
      "Example:\n"
      "  simcap bench render scenes/studio4.yaml\n"
      "The last line is: frames_per_s=<x> mrays_per_s=<y> embree_mrays_per_s=<z> "
      "embree_ratio=<y/z>");
  cmd->callback([&action] { action = [] { return run_bench_render(args); }; });
}

}  // namespace simcap::cli
