// The tracker families `simcap track --method` can run: each one's name, what it needs from a
// dataset and how it runs. A dataset a family cannot use is refused before anything is written.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

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
  // The family's option that asks for these (named in a refusal: "--effectors multiview"), and
  // what the family takes without them ("--effectors depth or mono").
  std::string_view option = {};
  std::string_view instead = {};
};

// What a scene fixes about the dataset it renders, known before rendering: its cameras and the
// names of its actors.
struct DatasetShape {
  int cameras = 0;
  std::vector<std::string> actors;
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
TrackMethod resolve_method(TrackMethod method, int cameras);

// Empty when `dataset` has all that `needs` asks for, else what it lacks ("1 camera, needs at
// least 2"; "no gt/joints3d.csv").
std::string missing_for(const DatasetNeeds& needs, const Dataset& dataset);

// Throws the Error track_dataset would throw for a dataset of this shape (an unknown --actor, an
// actor the method does not track, too few cameras), `where` naming it: `simcap loop` checks the
// scene before it renders.
void check_shape(const TrackOptions& options, const DatasetShape& shape, const std::string& where);

// Throws the Error track_dataset throws before it writes anything, for `options` (the method
// resolved) on `dataset`: an unknown --actor, one the method does not track, what the dataset
// lacks. `simcap bench track` checks with it too.
void check_dataset(const TrackOptions& options, const std::filesystem::path& dataset);

// Runs options.method (resolved) over `dataset` into `out` after checking that the dataset
// suits it; a dataset that does not is an Error saying what it lacks and which methods would
// take it.
TrackSummary track_dataset(const std::filesystem::path& dataset, const std::filesystem::path& out,
                           const TrackOptions& options);

}  // namespace simcap::tracker
