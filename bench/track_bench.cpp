#include "bench/track_bench.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <string_view>
#include <vector>

#include "models/detections.h"
#include "tracker/common/dataset.h"
#include "tracker/common/track_folder.h"
#include "tracker/registry.h"
#include "tracker/triangulate/triangulate_job.h"

namespace simcap {
namespace fs = std::filesystem;
using namespace tracker;

namespace {

using Clock = std::chrono::steady_clock;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

// Decodes `kind` images of `frames` on the same threads as the trackers: the baseline rate.
double decode_rate(const Dataset& ds, const std::vector<int>& frames, const std::string& kind) {
  const auto t0 = Clock::now();
  tbb::parallel_for(size_t{0}, frames.size(), [&](size_t i) {
    for (int c = 0; c < ds.camera_count(); ++c) {
      if (kind == "mask") {
        ds.mask(c, frames[i]);
      } else {
        ds.rgb(c, frames[i]);
      }
    }
  });
  const double s = std::chrono::duration<double>(Clock::now() - t0).count();
  return static_cast<double>(frames.size()) / std::max(s, 1e-9);
}

struct StageTimes {
  double silhouettes = 0, hull = 0, centerline = 0, icp = 0, filter = 0;
  long voxels = 0, points = 0, observed = 0;
};

// Moschini's pipeline without files, its stages timed inside the running pipeline.
TrackSummary run_moschini_timed(const fs::path& dataset, const TrackBenchOptions& o,
                                StageTimes& t) {
  MoschiniOptions m = o.track.moschini;
  m.init = o.track.init;
  m.silhouettes = o.track.silhouettes;
  m.quiet = true;
  return run_moschini(
      dataset, m, o.frames,
      [&](const Dataset&, const Observation& obs, const TrackStep& step, const MoschiniTracker&) {
        t.silhouettes += obs.silhouettes_ms;
        t.hull += obs.hull_ms;
        t.centerline += obs.centerline_ms;
        t.icp += step.icp_ms;
        t.filter += step.filter_ms;
        t.voxels += obs.hull.count;
        t.points += static_cast<long>(obs.points.size());
        ++t.observed;
      });
}

// Any other family: its whole run into a scratch track folder that is never committed.
TrackSummary run_family(const fs::path& dataset, const TrackBenchOptions& o) {
  TrackOptions options = o.track;
  options.max_frames = o.frames;
  options.quiet = true;
  const TrackerFamily& family = tracker_family(options.method);
  const fs::path scratch =
      fs::temp_directory_path() / ("simcap-bench-track-" + std::to_string(getpid()));
  TrackFolder folder(scratch);
  return family.run(dataset, folder.path(), options);
}

// Triangulation: its stages timed inside run_triangulation; the baseline reads and parses the
// detections file alone (what the method reads instead of images).
void run_triangulate_benchmark(const fs::path& dataset, const TrackBenchOptions& o,
                               std::FILE* out) {
  TriangulateOptions t = o.track.triangulate;
  t.init = o.track.init;
  t.actor = o.track.actor;
  t.max_frames = o.frames;
  t.quiet = true;
  const Dataset ds(dataset, t.actor);
  std::vector<std::string> cameras;
  for (const Camera& c : ds.cameras()) cameras.push_back(c.name);
  std::vector<double> fps, core_fps, read_fps;
  TriangulateStages sum;
  int frames = 0;
  for (int r = 0; r < o.repeat; ++r) {
    const auto t0 = Clock::now();
    const TriangulationResult result = run_triangulation(ds, t);
    const double s = std::chrono::duration<double>(Clock::now() - t0).count();
    frames = result.frames;
    const TriangulateStages& st = result.stages;
    fps.push_back(frames / std::max(s, 1e-9));
    core_fps.push_back(frames / std::max(st.associate_s + st.triangulate_s + st.smooth_s, 1e-9));
    sum.read_s += st.read_s;
    sum.associate_s += st.associate_s;
    sum.triangulate_s += st.triangulate_s;
    sum.smooth_s += st.smooth_s;
    const auto t1 = Clock::now();
    const Detections d =
        read_detections(t.detections, cameras, ds.frames("rgb").back() + 1, t.layout);
    read_fps.push_back(d.frames() /
                       std::max(std::chrono::duration<double>(Clock::now() - t1).count(), 1e-9));
  }
  std::fprintf(out, "dataset %s: %d cameras, %d frames, method triangulate, %d threads, %d runs\n",
               dataset.string().c_str(), ds.camera_count(), frames,
               tbb::this_task_arena::max_concurrency(), o.repeat);
  std::fprintf(out, "%-26s %10s %12s\n", "stage (per frame)", "ms", "frames/s");
  const double n = static_cast<double>(std::max(1, frames)) * o.repeat;
  const std::pair<const char*, double> stages[] = {{"read detections", sum.read_s},
                                                   {"associate people", sum.associate_s},
                                                   {"triangulate (parallel)", sum.triangulate_s},
                                                   {"fill gaps, filter, joints", sum.smooth_s}};
  for (const auto& [name, total] : stages) {
    std::fprintf(out, "%-26s %10.4f %12.1f\n", name, 1000.0 * total / n, n / std::max(total, 1e-9));
  }
  std::fprintf(out, "triangulation without reading: %.1f frames/s (median)\n", median(core_fps));
  std::vector<double> ratios;
  for (size_t r = 0; r < fps.size(); ++r) ratios.push_back(fps[r] / read_fps[r]);
  std::fprintf(out,
               "pipeline: %.1f frames/s; baseline (reading the detections alone): %.1f frames/s; "
               "tracker/baseline = %.3f (medians)\n",
               median(fps), median(read_fps), median(ratios));
  std::fprintf(out, "frames_per_s=%.1f\n", median(fps));
}

void print_stages(const StageTimes& t, const MoschiniOptions& m, std::FILE* out) {
  const double n = static_cast<double>(std::max(1L, t.observed));
  std::fprintf(out, "mean hull %.0f voxels, %.0f centerline points per frame\n", t.voxels / n,
               t.points / n);
  std::fprintf(out, "%-22s %10s %12s\n", "stage (per frame)", "ms", "frames/s");
  const std::pair<const char*, double> stages[] = {{"silhouettes (decode)", t.silhouettes},
                                                   {"visual hull", t.hull},
                                                   {"centerline", t.centerline},
                                                   {"articulated ICP", t.icp},
                                                   {"EKF", t.filter}};
  for (const auto& [name, total] : stages) {
    if (name != std::string_view("EKF") || m.filter == MotionFilter::ekf) {
      std::fprintf(out, "%-22s %10.3f %12.1f\n", name, total / n, n * 1000.0 / total);
    } else {
      std::fprintf(out, "%-22s %10s %12s\n", name, "off", "-");
    }
  }
}

}  // namespace

void run_track_benchmark(const fs::path& dataset, const TrackBenchOptions& given, std::FILE* out) {
  const Dataset ds(dataset);
  TrackBenchOptions o = given;
  o.track.method = resolve_method(given.track.method, ds);
  const TrackerFamily& family = tracker_family(o.track.method);
  check_dataset(o.track, dataset);
  if (o.track.method == TrackMethod::triangulate) {
    run_triangulate_benchmark(dataset, o, out);
    return;
  }
  const bool moschini = o.track.method == TrackMethod::moschini;
  // The baseline decodes what the tracker's first stage reads.
  const bool reads_masks = !family.needs(o.track).colour;
  const std::string kind = reads_masks ? "mask" : "rgb";
  std::vector<int> frames = ds.frames(kind);
  StageTimes times;
  TrackSummary s;
  std::vector<double> fps, decode_fps;
  // Tracker and baseline alternate, so that a slow spell of a shared machine hits both.
  for (int r = 0; r < o.repeat; ++r) {
    s = moschini ? run_moschini_timed(dataset, o, times) : run_family(dataset, o);
    fps.push_back(s.frames / std::max(s.seconds, 1e-9));
    if (static_cast<int>(frames.size()) > s.frames) frames.resize(s.frames);
    decode_fps.push_back(decode_rate(ds, frames, kind));
  }

  std::fprintf(out, "dataset %s: %d cameras, %d frames, method %s", dataset.string().c_str(),
               ds.camera_count(), s.frames,
               std::string(name_of(kTrackMethods, o.track.method)).c_str());
  if (moschini) {
    std::fprintf(out, ", voxel %.3f m, silhouettes %s", o.track.moschini.voxel_m,
                 std::string(name_of(kSilhouetteMethods, o.track.silhouettes)).c_str());
  }
  std::fprintf(out, ", init %s, %d runs\n",
               std::string(name_of(kInitMethods, o.track.init)).c_str(), o.repeat);
  if (moschini) print_stages(times, o.track.moschini, out);
  std::fprintf(out, "pipeline: %d frames with %d re-initializations; frames/s per run:", s.frames,
               s.reinitializations);
  for (const double f : fps) std::fprintf(out, " %.1f", f);
  std::vector<double> ratios;
  for (size_t r = 0; r < fps.size(); ++r) ratios.push_back(fps[r] / decode_fps[r]);
  std::fprintf(out,
               "\nbaseline (%s decoding alone, same threads): %.1f frames/s; tracker/baseline = "
               "%.3f (medians)\n",
               kind.c_str(), median(decode_fps), median(ratios));
  std::fprintf(out, "frames_per_s=%.1f\n", median(fps));
}

}  // namespace simcap
