// simcap bench render|track|ik|collect: the options of each benchmark; the measurements and their
// same-run baselines are the bench library's (bench/).
#include <cstdio>

#include "apps/simcap/commands.h"
#include "apps/simcap/number_checks.h"
#include "apps/simcap/track_cli.h"
#include "bench/collect_bench.h"
#include "bench/ik_bench.h"
#include "bench/render_bench.h"
#include "bench/track_bench.h"
#include "scenes/scene.h"

namespace simcap::cli {
namespace {

void add_bench_render(CLI::App& bench, Action& action) {
  auto* cmd = bench.add_subcommand(
      "render", "Renderer frames/s (images written) and its ray rate against a bare Embree loop");
  static std::filesystem::path scene;
  static RenderBenchOptions options;
  cmd->add_option("scene", scene, "Scene file (default: the shipped scenes/studio4.yaml)");
  cmd->add_option("--frames", options.frames, "Frames of the full render")
      ->capture_default_str()
      ->check(positive_number());
  cmd->add_option("--ray-frames", options.ray_frames,
                  "Frames (spread over those) for the ray-rate measurements")
      ->capture_default_str()
      ->check(positive_number());
  cmd->add_option("--set", options.overrides, "Scene override key.path=value, repeatable");
  cmd->add_option("--blur", options.blur_samples,
                  "Also the CPU cost of motion blur with this many samples per pixel "
                  "(render.shutter 1) against one sample, on --ray-frames frames")
      ->check(CLI::Range(2, 1024));
  cmd->add_flag("-q,--quiet", options.quiet, "No progress on stderr");
  cmd->footer(
      "Examples:\n"
      "  simcap bench render scenes/studio4.yaml\n"
      "  simcap bench render --frames 20 --ray-frames 10 --blur 8\n"
      "The last line is: frames_per_s=<x> mrays_per_s=<y> embree_mrays_per_s=<z> "
      "embree_ratio=<y/z>");
  cmd->callback([&action] {
    action = [] {
      const std::filesystem::path file = scene.empty() ? shipped_scene_path("studio4") : scene;
      print_render_benchmark(run_render_benchmark(file, options), file, stdout);
      return 0;
    };
  });
}

void add_bench_track(CLI::App& bench, Action& action) {
  auto* cmd = bench.add_subcommand("track", "Tracker frames/s (per stage for moschini)");
  static std::filesystem::path dataset;
  static TrackBenchOptions options;
  cmd->add_option("DATASET", dataset, "Dataset folder written by simcap render")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--frames", options.frames, "Frames to track (default: all)")
      ->check(positive_number());
  cmd->add_option("--repeat", options.repeat, "Runs; frames_per_s is their median")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  add_track_options(cmd, options.track, TrackOptionScope::loop);
  refuse_other_methods_options(cmd, options.track);
  cmd->footer(
      "Examples:\n"
      "  simcap bench track out/studio4\n"
      "  simcap bench track out/studio4 --silhouettes bgsub --repeat 5\n"
      "  simcap bench track out/studio4 --method triangulate --detections det.json\n"
      "Stage times are measured inside the running pipeline (perception runs on several frames\n"
      "at once). The baseline decodes the images the tracker reads, on the same threads, between\n"
      "the runs (triangulate: it reads and parses the detections file alone). The last line is\n"
      "frames_per_s=<median overall rate of the runs>.");
  cmd->callback([&action] {
    action = [] {
      run_track_benchmark(dataset, options, stdout);
      return 0;
    };
  });
}

void add_bench_ik(CLI::App& bench, Action& action) {
  auto* cmd = bench.add_subcommand("ik", "SIK, CCD and DLS time per frame");
  static IkBenchOptions options;
  cmd->add_option("motion", options.motion,
                  "BVH clip (default: a 10 s procedural walk on the canonical humanoid)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--repeat", options.repeat, "Runs per method; the median is reported")
      ->check(positive_number())
      ->capture_default_str();
  cmd->footer(
      "Examples:\n"
      "  simcap bench ik\n"
      "  simcap bench ik models/assets/cmu_131_01_start_walk_stop.bvh --repeat 5\n"
      "Each method runs on the same skeleton, limits and pelvis estimate (weights 1,1,0); the\n"
      "time is the median solve time per frame. The last line is\n"
      "ms_per_frame sik=<x> ccd=<y> dls=<z>.");
  cmd->callback([&action] {
    action = [] {
      run_ik_benchmark(options, stdout);
      return 0;
    };
  });
}

void add_bench_collect(CLI::App& bench, Action& action) {
  auto* cmd = bench.add_subcommand(
      "collect", "Collection frames/s of N shard processes against one process, same run");
  static std::filesystem::path spec;
  static CollectBenchOptions options;
  cmd->add_option("spec", spec, "Collection spec (YAML)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--shards", options.shards, "Shard processes run at once")
      ->capture_default_str()
      ->check(CLI::Range(1, 256));
  cmd->add_option("--repeat", options.repeat, "Runs; the medians are reported")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  cmd->footer(
      "Example:\n"
      "  simcap bench collect stress/collections/small.yaml --shards 2 --repeat 5\n"
      "Each run collects the spec into new temporary folders with one process (--shard 0/1)\n"
      "and with --shards processes at once (--shard K/N), alternating which goes first, then\n"
      "runs one process over the finished collection: the fixed cost of a task (start-up, spec\n"
      "checks, index). The last line is single_frames_per_s=<x> sharded_frames_per_s=<y>\n"
      "ratio=<y/x> empty_task_s=<z>.");
  cmd->callback([&action] {
    action = [] {
      options.simcap = std::filesystem::read_symlink("/proc/self/exe");
      run_collect_benchmark(spec, options, stdout);
      return 0;
    };
  });
}

}  // namespace

void add_bench(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      "bench",
      "Measure throughput of the renderer, the tracker, inverse kinematics or collections");
  cmd->require_subcommand(1);
  cmd->footer(
      "Examples:\n"
      "  simcap bench render scenes/studio4.yaml\n"
      "  simcap bench track out/studio4\n"
      "  simcap bench ik\n"
      "  simcap bench collect stress/collections/small.yaml --shards 2");
  add_bench_render(*cmd, action);
  add_bench_track(*cmd, action);
  add_bench_ik(*cmd, action);
  add_bench_collect(*cmd, action);
}

}  // namespace simcap::cli
