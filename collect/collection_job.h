// `simcap collect` as a library call: renders the sequences of a collection (or of one shard of
// it) into OUT, each atomically, skipping those already done, and keeps OUT's index.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "collect/collection_spec.h"

namespace simcap {

struct CollectOptions {
  int shard = 0;  // this process renders the units (shard_units) of shard K of N
  int shards = 1;
  std::vector<int> ids;  // when not empty: only these ids (of this shard)
  bool quiet = false;
};

struct CollectSummary {
  int chunks = 1;    // frame ranges per sequence (chunks_per_sequence)
  int selected = 0;  // work units of this shard: sequences, or frame ranges when chunks > 1
  int rendered = 0, skipped = 0, failed = 0;
  long frames = 0;  // frames rendered by this run
  double seconds = 0;
};

// The folder of sequence `id` in OUT ("seq_000042").
std::string sequence_folder(int id);

// OUT belongs to one spec: the spec's text is recorded in OUT/collection.json on first use and
// must match afterwards, so that shards started from different specs cannot mix. Error when OUT
// holds another spec's collection or files that are not a collection's.
void claim_collection_output(const CollectionSpec& spec, const std::filesystem::path& out);

// A work unit of a shard: frames [first, end) of sequence `id`, frame range `chunk` of
// `chunks` (one unit is the whole sequence when chunks == 1).
struct CollectionUnit {
  int id = 0;
  int first = 0, end = 0;
  int chunk = 0, chunks = 1;
};

// Frame ranges per sequence for `shards` shards: 1 when there are at least as many sequences
// as shards, else ceil(shards / count) (at most `frames`), so that every shard has work.
int chunks_per_sequence(int count, int frames, int shards);

// The units of shard `shard` of `shards`: unit u = id * chunks + chunk goes to shard u % N
// (round robin, so shards get the scenes and motions in equal shares); range `chunk` of a
// sequence is frames [chunk * frames / chunks, (chunk + 1) * frames / chunks). Error when
// not 0 <= shard < shards.
std::vector<CollectionUnit> shard_units(int count, int frames, int shard, int shards);

// The shards (array tasks) that hold some unit of the sequences `ids`.
std::vector<int> shards_holding(const std::vector<int>& ids, int count, int frames, int shards);

// Renders the selected units of `spec` into `out`. A whole sequence is rendered into
// OUT/.staging/seq_NNNNNN (continued with render's resume after a kill) and renamed to
// OUT/seq_NNNNNN when complete, with its sequence.json (parameters, render seconds). A frame
// range renders its images into OUT/.staging/seq_NNNNNN.chunks/frames_A-B.part (resumable),
// renamed to frames_A-B when complete; the process that finds all ranges of a sequence complete
// assembles them (hard links) in a folder of its own there, completes the dataset with a
// resume render (backgrounds, ground truth, meta.json) and renames it to OUT/seq_NNNNNN; when
// two processes race, the second rename fails and its copy is dropped. A sequence
// whose render fails is recorded in OUT/failed/seq_NNNNNN.txt and the others go on. OUT must be
// new or hold this spec's collection (OUT/collection.json). Rewrites OUT/index.csv and
// OUT/index.json at the end. Progress (sequences, frames/s, ETA) on stderr.
CollectSummary run_collection(const CollectionSpec& spec, const std::filesystem::path& out,
                              const CollectOptions& options);

struct CollectionStatus {
  std::filesystem::path spec;  // the spec OUT was collected from
  int count = 0;
  int frames = 0;  // per sequence
  std::vector<int> done, failed, missing;
};

// Reads OUT/collection.json and what is in OUT, and rewrites the index.
CollectionStatus collection_status(const std::filesystem::path& out);

// Writes OUT/index.csv and OUT/index.json: per sequence its id, folder, status
// (done|failed|missing), frames, render seed, render seconds and resolved parameters.
void write_collection_index(const CollectionSpec& spec, const std::filesystem::path& out);

// Ids as ranges: "0-3,7,9-10".
std::string id_ranges(const std::vector<int>& ids);
// The inverse of id_ranges; Error naming `what` for malformed text.
std::vector<int> parse_id_ranges(const std::string& text, const std::string& what);

// Seconds per frame and peak memory of rendering sequence 0 (its first frames) on this machine,
// for the Slurm script's time and memory requests. Renders into a temporary folder in OUT.
struct FrameCost {
  double seconds_per_frame = 0;
  double peak_mib = 0;
  int threads = 1;
};
FrameCost measure_frame_cost(const CollectionSpec& spec, const std::filesystem::path& out);

}  // namespace simcap
