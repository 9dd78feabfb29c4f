// simcap bench track DATASET: the Moschini tracker's throughput per stage and overall, against
// the rate at which the same threads can merely decode the dataset's masks.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <opencv2/imgcodecs.hpp>
#include <string_view>
#include <vector>

#include "apps/simcap/bench_commands.h"
#include "apps/simcap/number_checks.h"
#include "tracker/dataset.h"
#include "tracker/track_job.h"

namespace simcap::cli {
namespace {

struct BenchTrackOptions {
  std::string dataset;
  TrackOptions track;
  int frames = -1;
  int repeat = 3;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

int run(const BenchTrackOptions& o) {
  using Clock = std::chrono::steady_clock;
  TrackOptions options = o.track;
  options.quiet = true;
  double silhouettes = 0, hull = 0, centerline = 0, icp = 0, filter = 0;
  long voxels = 0, points = 0, observed = 0;
  TrackSummary s;
  const tracker::Dataset ds(o.dataset);
  std::vector<int> frames = ds.frames("mask");
  std::vector<double> fps, decode_fps;
  // Tracker and baseline alternate, so that a slow spell of a shared machine hits both.
  for (int r = 0; r < o.repeat; ++r) {
    s = run_moschini(o.dataset, options, o.frames,
                     [&](const tracker::Dataset&, const tracker::Observation& obs,
                         const tracker::TrackStep& step, const tracker::MoschiniTracker&) {
                       silhouettes += obs.silhouettes_ms;
                       hull += obs.hull_ms;
                       centerline += obs.centerline_ms;
                       icp += step.icp_ms;
                       filter += step.filter_ms;
                       voxels += obs.hull.count;
                       points += static_cast<long>(obs.points.size());
                       ++observed;
                     });
    fps.push_back(s.frames / std::max(s.seconds, 1e-9));
    // Baseline: decode the same masks with the same threads and nothing else.
    if (static_cast<int>(frames.size()) > s.frames) frames.resize(s.frames);
    const auto t0 = Clock::now();
    tbb::parallel_for(size_t{0}, frames.size(), [&](size_t i) {
      for (int c = 0; c < ds.camera_count(); ++c) ds.mask(c, frames[i]);
    });
    const double decode_s = std::chrono::duration<double>(Clock::now() - t0).count();
    decode_fps.push_back(static_cast<double>(frames.size()) / std::max(decode_s, 1e-9));
  }
  const double n = static_cast<double>(std::max(1L, observed));

  std::printf("dataset %s: %d cameras, %d frames, voxel %.3f m, silhouettes %s, init %s, %d runs\n",
              o.dataset.c_str(), ds.camera_count(), s.frames, options.voxel_m,
              options.silhouettes.c_str(), options.init.c_str(), o.repeat);
  std::printf("mean hull %.0f voxels, %.0f centerline points per frame\n", voxels / n, points / n);
  std::printf("%-22s %10s %12s\n", "stage (per frame)", "ms", "frames/s");
  const std::pair<const char*, double> stages[] = {{"silhouettes (decode)", silhouettes},
                                                   {"visual hull", hull},
                                                   {"centerline", centerline},
                                                   {"articulated ICP", icp},
                                                   {"EKF", filter}};
  for (const auto& [name, total] : stages) {
    if (name != std::string_view("EKF") || options.filter == "ekf") {
      std::printf("%-22s %10.3f %12.1f\n", name, total / n, n * 1000.0 / total);
    } else {
      std::printf("%-22s %10s %12s\n", name, "off", "-");
    }
  }
  std::printf("pipeline: %d frames with %d re-initializations; frames/s per run:", s.frames,
              s.reinitializations);
  for (const double f : fps) std::printf(" %.1f", f);
  std::vector<double> ratios;
  for (size_t r = 0; r < fps.size(); ++r) ratios.push_back(fps[r] / decode_fps[r]);
  std::printf(
      "\nbaseline (mask decoding alone, same threads): %.1f frames/s; tracker/baseline = "
      "%.3f (medians)\n",
      median(decode_fps), median(ratios));
  std::printf("frames_per_s=%.1f\n", median(fps));
  return 0;
}

}  // namespace

void add_bench_track(CLI::App& bench, Action& action) {
  auto* cmd = bench.add_subcommand("track", "Tracker frames/s per stage on a dataset");
  auto o = std::make_shared<BenchTrackOptions>();
  cmd->add_option("DATASET", o->dataset, "Dataset folder written by simcap render")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--frames", o->frames, "Frames to track (default: all)")
      ->check(positive_number());
  cmd->add_option("--repeat", o->repeat, "Runs; frames_per_s is their median")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  cmd->add_option("--voxel", o->track.voxel_m, "Voxel size, metres")->capture_default_str();
  cmd->add_option("--silhouettes", o->track.silhouettes, "gt, bgsub or mog2")
      ->check(CLI::IsMember({"gt", "bgsub", "mog2"}))
      ->capture_default_str();
  cmd->add_option("--init", o->track.init, "gt or auto")
      ->check(CLI::IsMember({"gt", "auto"}))
      ->capture_default_str();
  cmd->footer(
      "Example:\n  simcap bench track out/studio4\n"
      "Stage times are measured inside the running pipeline (perception runs on several frames\n"
      "at once). The last line is frames_per_s=<median overall rate of the runs>.");
  cmd->callback([&action, o] { action = [o] { return run(*o); }; });
}

}  // namespace simcap::cli
