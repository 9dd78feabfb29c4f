#include "tracker/registry.h"

#include "tracker/track_export.h"

#include <array>

#include "core/atomic_file.h"
#include "core/dataset_actors.h"
#include "core/error.h"
#include "core/track_source.h"
#include "tracker/common/track_folder.h"

namespace simcap::tracker {
namespace fs = std::filesystem;

namespace {

TrackSummary run_moschini_family(const fs::path& dataset, const fs::path& out,
                                 const TrackOptions& o) {
  MoschiniOptions m = o.moschini;
  m.init = o.init;
  m.silhouettes = o.silhouettes;
  m.inspect = o.inspect;
  m.oracle = o.oracle;
  m.max_frames = o.max_frames;
  m.quiet = o.quiet;
  m.actor = o.actor;
  return track_moschini(dataset, out, m);
}

TrackSummary run_sik_family(const fs::path& dataset, const fs::path& out, const TrackOptions& o) {
  SikTrackOptions s = o.sik;
  s.init = o.init;
  s.silhouettes = o.silhouettes;
  s.seed = o.seed;
  s.max_frames = o.max_frames;
  s.quiet = o.quiet;
  return track_sik(dataset, out, s);
}

TrackSummary run_monocular_family(const fs::path& dataset, const fs::path& out,
                                  const TrackOptions& o) {
  MonocularOptions m = o.monocular;
  m.init = o.init;
  m.silhouettes = o.silhouettes;
  m.tracker.filter.seed = o.seed;
  m.inspect = o.inspect;
  m.oracle = o.oracle;
  m.max_frames = o.max_frames;
  m.quiet = o.quiet;
  return track_monocular(dataset, out, m);
}

TrackSummary run_triangulate_family(const fs::path& dataset, const fs::path& out,
                                    const TrackOptions& o) {
  TriangulateOptions t = o.triangulate;
  t.init = o.init;
  t.actor = o.actor;
  t.max_frames = o.max_frames;
  t.quiet = o.quiet;
  return track_triangulate(dataset, out, t);
}

constexpr std::array kFamilies{
    TrackerFamily{TrackMethod::moschini,
                  "multi-camera: visual hull, centerline, articulated ICP (Moschini 2009)",
                  [](const TrackOptions& o) {
                    // A hull needs two views to bound depth; subtracted silhouettes need the
                    // colour frames.
                    DatasetNeeds n;
                    n.min_cameras = 2;
                    n.colour = o.silhouettes != SilhouetteMethod::gt;
                    return n;
                  },
                  true, run_moschini_family},
    TrackerFamily{TrackMethod::sik,
                  "sequential inverse kinematics on end-effectors, from the ground truth or "
                  "tracked in the images (Unzueta 2009)",
                  [](const TrackOptions& o) {
                    // From pixels: colour frames (CFOF), depth maps for depth, two views to
                    // triangulate; the ground truth for gt effectors or the first frame's parts.
                    DatasetNeeds n;
                    const EffectorSource e = o.sik.effectors;
                    n.ground_truth = e == EffectorSource::gt || o.init == InitMethod::gt;
                    n.colour = e != EffectorSource::gt;
                    n.depth = e == EffectorSource::depth;
                    n.min_cameras = e == EffectorSource::multiview ? 2 : 1;
                    if (e == EffectorSource::multiview) {
                      n.option = "--effectors multiview";
                      n.instead = "--effectors depth or mono (one camera)";
                    } else if (e == EffectorSource::depth) {
                      n.option = "--effectors depth";
                      n.instead = "--effectors mono or multiview (colour only)";
                    }
                    return n;
                  },
                  false, run_sik_family},
    TrackerFamily{TrackMethod::monocular,
                  "one camera: render-and-compare particle filter (Gomez Jauregui 2011)",
                  [](const TrackOptions& o) {
                    // The colour classes come from the colour frames; --init gt sizes and poses
                    // the body from the first frame's ground truth.
                    DatasetNeeds n;
                    n.colour = true;
                    n.ground_truth = o.init == InitMethod::gt || o.oracle;
                    return n;
                  },
                  false, run_monocular_family},
    TrackerFamily{TrackMethod::triangulate,
                  "a 2D detector's keypoints in every camera (--detections), triangulated: "
                  "weighted DLT, camera exclusion, left/right swap repair",
                  [](const TrackOptions& o) {
                    // Two views to triangulate; the frame list from the colour frames the
                    // detector ran on; --init gt finds the actor among several people.
                    DatasetNeeds n;
                    n.min_cameras = 2;
                    n.colour = true;
                    n.ground_truth = o.init == InitMethod::gt;
                    return n;
                  },
                  true, run_triangulate_family},
};

std::string method_name(TrackMethod m) {
  return std::string(name_of(kTrackMethods, m));
}

}  // namespace

std::span<const TrackerFamily> tracker_families() {
  return kFamilies;
}

TrackMethod resolve_method(TrackMethod method, int cameras) {
  if (method != TrackMethod::automatic) return method;
  return cameras >= 2 ? TrackMethod::moschini : TrackMethod::monocular;
}

TrackMethod resolve_method(TrackMethod method, const Dataset& dataset) {
  return resolve_method(method, dataset.camera_count());
}

const TrackerFamily& tracker_family(TrackMethod method) {
  for (const TrackerFamily& f : kFamilies) {
    if (f.method == method) return f;
  }
  throw Error("--method: no tracker family '" + method_name(method) + "'");
}

namespace {

std::string missing_cameras(const DatasetNeeds& needs, int cameras) {
  if (cameras >= needs.min_cameras) return {};
  return std::to_string(cameras) + (cameras == 1 ? " camera" : " cameras") + ", needs at least " +
         std::to_string(needs.min_cameras);
}

// Throws when `missing` finds something the method (resolved) lacks, saying what, for which
// option, and which settings of the method or other methods do without it.
template <typename Missing>
void refuse_missing(const std::string& where, const TrackOptions& options, Missing missing) {
  const TrackerFamily& family = tracker_family(options.method);
  const DatasetNeeds needs = family.needs(options);
  const std::string lack = missing(needs);
  if (lack.empty()) return;
  std::string others;
  if (!needs.instead.empty())
    others = "--method " + method_name(options.method) + " " + std::string(needs.instead);
  for (const TrackerFamily& f : kFamilies) {
    TrackOptions alternative = options;
    alternative.method = f.method;
    if (f.method != options.method && missing(f.needs(alternative)).empty()) {
      others += (others.empty() ? "" : ", ") + ("--method " + method_name(f.method));
    }
  }
  throw Error(where + ": " + lack + " for --method " + method_name(options.method) +
              (needs.option.empty() ? "" : " " + std::string(needs.option)) + " (" +
              std::string(family.summary) + "); " +
              (others.empty() ? std::string("no tracker takes this dataset")
                              : "use " + others + " instead"));
}

void refuse_actor(const TrackOptions& options, const std::vector<std::string>& actors, int actor) {
  if (actor != 0 && !tracker_family(options.method).any_actor) {
    throw Error("--actor " + options.actor + ": --method " + method_name(options.method) +
                " tracks only the first actor (" + actors.front() +
                "); --method moschini tracks any");
  }
}

}  // namespace

std::string missing_for(const DatasetNeeds& needs, const Dataset& dataset) {
  if (std::string lack = missing_cameras(needs, dataset.camera_count()); !lack.empty()) {
    return lack;
  }
  for (const auto& [wanted, kind] : {std::pair{needs.colour, "rgb"}, {needs.depth, "depth"}}) {
    if (!wanted) continue;
    for (const Camera& cam : dataset.cameras()) {
      if (!fs::is_directory(dataset.root() / cam.name / kind)) {
        return "no " + cam.name + "/" + kind + " images";
      }
    }
  }
  if (needs.ground_truth && !fs::is_regular_file(dataset.ground_truth_path())) {
    return "no gt/joints3d.csv";
  }
  return {};
}

void check_shape(const TrackOptions& given, const DatasetShape& shape, const std::string& where) {
  TrackOptions options = given;
  options.method = resolve_method(given.method, shape.cameras);
  refuse_actor(options, shape.actors, find_actor(shape.actors, options.actor, "--actor"));
  refuse_missing(where, options,
                 [&](const DatasetNeeds& n) { return missing_cameras(n, shape.cameras); });
}

void check_dataset(const TrackOptions& options, const fs::path& dataset) {
  const Dataset chosen(dataset, options.actor);
  refuse_actor(options, chosen.actors(), chosen.actor());
  refuse_missing(dataset.string(), options,
                 [&](const DatasetNeeds& n) { return missing_for(n, chosen); });
}

TrackSummary track_dataset(const fs::path& dataset, const fs::path& out,
                           const TrackOptions& given) {
  TrackOptions options = given;
  options.method = resolve_method(given.method, Dataset(dataset));
  const TrackerFamily& family = tracker_family(options.method);
  check_dataset(options, dataset);
  const Dataset chosen(dataset, options.actor);
  TrackFolder folder(out);
  TrackSummary summary = family.run(dataset, folder.path(), options);
  export_track_motion(folder.path(), chosen.fps(), options.exports);
  if (chosen.actors().size() > 1) {
    write_text_atomic(folder.path() / kTrackActorFile, chosen.actors()[chosen.actor()] + "\n");
  }
  write_text_atomic(folder.path() / kTrackDatasetFile, dataset_fingerprint(dataset) + "\n");
  folder.commit();
  summary.track = out;
  return summary;
}

}  // namespace simcap::tracker
