// The tracker families `simcap track --method` can run: each one's name, what it needs from a
// dataset and how it runs. A dataset a family cannot use is refused before anything is written.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "tracker/common/dataset.h"
#include "tracker/common/track_summary.h"
#include "tracker/track_options.h"

namespace simcap::tracker {

// What a family reads from a dataset, given its options.
struct DatasetNeeds {
  int min_cameras = 1;
  bool colour = false;        // camNN/rgb/
  bool depth = false;         // camNN/depth/
  bool ground_truth = false;  // gt/joints3d.csv
};

struct TrackerFamily {
  TrackMethod method;
  std::string_view summary;  // one line, for --help and for refusals
  DatasetNeeds (*needs)(const TrackOptions&);
  // Whether it tracks any actor of a several-person dataset (--actor), not only the first.
  bool any_actor;
  TrackSummary (*run)(const std::filesystem::path& dataset, const std::filesystem::path& out,
                      const TrackOptions&);
};

// Every family (TrackMethod::automatic is none: it stands for one of them).
std::span<const TrackerFamily> tracker_families();
const TrackerFamily& tracker_family(TrackMethod method);

// `method`, or for TrackMethod::automatic the family that suits the dataset: moschini with two
// cameras or more, monocular with one.
TrackMethod resolve_method(TrackMethod method, const Dataset& dataset);

// Empty when `dataset` has all that `needs` asks for, else what it lacks ("1 camera, needs at
// least 2"; "no gt/joints3d.csv").
std::string missing_for(const DatasetNeeds& needs, const Dataset& dataset);

// Runs options.method (resolved) over `dataset` into `out` after checking that the dataset
// suits it; a dataset that does not is an Error saying what it lacks and which methods would
// take it.
TrackSummary track_dataset(const std::filesystem::path& dataset, const std::filesystem::path& out,
                           const TrackOptions& options);

}  // namespace simcap::tracker
