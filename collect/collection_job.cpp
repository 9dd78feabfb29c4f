#include "collect/collection_job.h"

#include <sys/resource.h>
#include <unistd.h>

#include <oneapi/tbb/info.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <set>

#include "core/atomic_file.h"
#include "core/csv.h"
#include "core/error.h"
#include "core/progress.h"
#include "sim/render_job.h"

namespace simcap {
namespace fs = std::filesystem;
namespace {

using Json = nlohmann::ordered_json;
using Clock = std::chrono::steady_clock;

constexpr const char* kCollectionFile = "collection.json";
constexpr const char* kSequenceFile = "sequence.json";

fs::path failed_record(const fs::path& out, int id) {
  return out / "failed" / (sequence_folder(id) + ".txt");
}

bool is_done(const fs::path& out, int id) {
  return fs::is_regular_file(out / sequence_folder(id) / kSequenceFile);
}

}  // namespace

void claim_collection_output(const CollectionSpec& spec, const fs::path& out) {
  const fs::path record = out / kCollectionFile;
  if (fs::exists(record)) {
    const Json j = Json::parse(read_text(record));
    if (j.value("spec_text", "") != spec.text) {
      throw Error(out.string() + ": holds a collection of another spec (" + j.value("spec", "?") +
                  "); collect into a new folder");
    }
    return;
  }
  // Shards starting at once see each other's temporary files (hidden names) only.
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(out, ec)) {
    if (e.path().filename().string().front() != '.') {
      throw Error(out.string() + ": the folder is not empty and holds no collection");
    }
  }
  Json j;
  j["spec"] = spec.file.string();
  j["count"] = spec.count;
  j["seed"] = spec.seed;
  j["frames"] = spec.frames;
  j["spec_text"] = spec.text;
  write_text_atomic(record, j.dump(2) + "\n");
}

// A CSV cell, quoted (RFC 4180) when it holds a comma or a quote: parameter values may be
// lists ("[0.2, 0.3, 0.6]") or paths.
std::string csv_cell(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string q = "\"";
  for (char c : text) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

void write_csv_row(std::ostream& out, const std::vector<std::string>& cells) {
  for (size_t i = 0; i < cells.size(); ++i) out << (i ? "," : "") << csv_cell(cells[i]);
  out << "\n";
}

namespace {

Json sequence_record(const CollectionSequence& s, int frames, double seconds) {
  Json j;
  j["id"] = s.id;
  j["folder"] = sequence_folder(s.id);
  j["frames"] = frames;
  j["seed"] = s.seed;
  Json params = Json::object();
  for (const auto& [k, v] : s.parameters) params[k] = v;
  j["parameters"] = params;
  j["overrides"] = s.overrides;
  j["render_s"] = seconds;  // timing: the only field that differs between runs
  return j;
}

RenderOptions render_options(const CollectionSpec& spec, const CollectionSequence& s) {
  RenderOptions o;
  o.frames = spec.frames;
  o.seed = s.seed;
  o.overrides = s.overrides;
  o.quiet = true;
  return o;
}

// Renders one sequence into its staging folder and moves it into place.
int render_sequence(const CollectionSpec& spec, const fs::path& out, int id) {
  const CollectionSequence s = collection_sequence(spec, id);
  const fs::path staging = out / ".staging" / sequence_folder(id);
  RenderOptions options = render_options(spec, s);
  options.resume = fs::exists(staging / "meta.json");
  options.overwrite = !options.resume;
  const RenderSummary r = render_dataset(s.scene, staging, options);
  write_text_atomic(staging / kSequenceFile,
                    sequence_record(s, r.frames, r.seconds).dump(2) + "\n");
  std::error_code ec;
  fs::rename(staging, out / sequence_folder(id), ec);
  if (ec)
    throw Error((out / sequence_folder(id)).string() + ": cannot move into place: " + ec.message());
  fs::remove(failed_record(out, id), ec);
  return r.frames;
}

fs::path chunk_root(const fs::path& out, int id) {
  return out / ".staging" / (sequence_folder(id) + ".chunks");
}

std::string chunk_name(const CollectionUnit& u) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "frames_%06d-%06d", u.first, u.end);
  return buf;
}

// The range `chunk` of a sequence split into `chunks`.
CollectionUnit unit_of(int id, int frames, int chunk, int chunks) {
  const auto at = [&](int c) {
    return static_cast<int>(static_cast<long long>(c) * frames / chunks);
  };
  return {id, at(chunk), at(chunk + 1), chunk, chunks};
}

// A name no other process uses at the same time, on any node of a cluster.
std::string process_name() {
  char host[256] = {};
  gethostname(host, sizeof host - 1);
  return std::string(host) + "." + std::to_string(getpid());
}

void link_or_copy(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  fs::create_directories(to.parent_path());
  fs::create_hard_link(from, to, ec);
  if (ec) fs::copy_file(from, to, fs::copy_options::overwrite_existing);
}

// Assembles the complete frame ranges of sequence `u.id` into one dataset and moves it into
// place: the first range's folder whole, the others' camera images (resume rewrites the fixed
// files and meta.json, renders the backgrounds and computes the ground truth of every frame).
void finalise_sequence(const CollectionSpec& spec, const fs::path& out, const CollectionUnit& u) {
  const CollectionSequence s = collection_sequence(spec, u.id);
  const fs::path root = chunk_root(out, u.id);
  const fs::path assembly = root / ("assembly." + process_name());
  fs::remove_all(assembly);
  double seconds = 0;
  for (int c = 0; c < u.chunks; ++c) {
    const fs::path chunk = root / chunk_name(unit_of(u.id, spec.frames, c, u.chunks));
    const Json meta = Json::parse(read_text(chunk / "meta.json"));
    seconds += meta.at("timings").at("total_s").get<double>();
    for (const auto& camera : meta.at("cameras")) {
      for (const auto& e : fs::recursive_directory_iterator(chunk / camera.get<std::string>())) {
        if (e.is_regular_file()) {
          link_or_copy(e.path(), assembly / e.path().lexically_relative(chunk));
        }
      }
    }
    if (c == 0) {
      for (const auto& e : fs::directory_iterator(chunk)) {
        if (e.is_regular_file()) link_or_copy(e.path(), assembly / e.path().filename());
      }
    }
  }
  RenderOptions options = render_options(spec, s);
  options.resume = true;
  const RenderSummary r = render_dataset(s.scene, assembly, options);
  write_text_atomic(assembly / kSequenceFile,
                    sequence_record(s, r.frames, seconds + r.seconds).dump(2) + "\n");
  std::error_code ec;
  fs::rename(assembly, out / sequence_folder(u.id), ec);
  if (ec && !is_done(out, u.id)) {
    throw Error((out / sequence_folder(u.id)).string() +
                ": cannot move into place: " + ec.message());
  }
  fs::remove_all(root, ec);  // the ranges, and copies of processes that lost a race or died
  fs::remove(failed_record(out, u.id), ec);
}

// Renders the images of one frame range, and finalises its sequence when it completes the
// last range. Returns the frames rendered.
int render_chunk(const CollectionSpec& spec, const fs::path& out, const CollectionUnit& u) {
  const fs::path root = chunk_root(out, u.id);
  const fs::path done = root / chunk_name(u);
  int frames = 0;
  if (!fs::is_directory(done)) {
    const fs::path part = root / (chunk_name(u) + ".part");
    RenderOptions options = render_options(spec, collection_sequence(spec, u.id));
    options.image_frames = RenderOptions::FrameRange{u.first, u.end};
    options.resume = fs::exists(part / "meta.json");
    options.overwrite = !options.resume;
    frames = render_dataset(collection_sequence(spec, u.id).scene, part, options).frames;
    std::error_code ec;
    fs::rename(part, done, ec);
    if (ec) throw Error(done.string() + ": cannot move into place: " + ec.message());
  }
  for (int c = 0; c < u.chunks; ++c) {
    if (!fs::is_directory(root / chunk_name(unit_of(u.id, spec.frames, c, u.chunks)))) {
      return frames;
    }
  }
  finalise_sequence(spec, out, u);
  return frames;
}

}  // namespace

std::string sequence_folder(int id) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "seq_%06d", id);
  return buf;
}

int chunks_per_sequence(int count, int frames, int shards) {
  if (count >= shards) return 1;
  return std::min(frames, (shards + count - 1) / count);
}

std::vector<CollectionUnit> shard_units(int count, int frames, int shard, int shards) {
  if (shards < 1 || shard < 0 || shard >= shards) {
    throw Error("--shard: expected K/N with 0 <= K < N, got " + std::to_string(shard) + "/" +
                std::to_string(shards));
  }
  const int chunks = chunks_per_sequence(count, frames, shards);
  std::vector<CollectionUnit> units;
  for (long long u = shard; u < static_cast<long long>(count) * chunks; u += shards) {
    units.push_back(
        unit_of(static_cast<int>(u / chunks), frames, static_cast<int>(u % chunks), chunks));
  }
  return units;
}

std::vector<int> shards_holding(const std::vector<int>& ids, int count, int frames, int shards) {
  const int chunks = chunks_per_sequence(count, frames, shards);
  std::set<int> held;
  for (int id : ids) {
    for (int c = 0; c < chunks; ++c) {
      held.insert(static_cast<int>((static_cast<long long>(id) * chunks + c) % shards));
    }
  }
  return {held.begin(), held.end()};
}

CollectSummary run_collection(const CollectionSpec& spec, const fs::path& out,
                              const CollectOptions& options) {
  const auto start = Clock::now();
  std::vector<CollectionUnit> units =
      shard_units(spec.count, spec.frames, options.shard, options.shards);
  if (!options.ids.empty()) {
    for (int id : options.ids) {
      if (id < 0 || id >= spec.count) {
        throw Error("--ids: " + std::to_string(id) + " is not a sequence of the collection (0-" +
                    std::to_string(spec.count - 1) + ")");
      }
    }
    const std::set<int> wanted(options.ids.begin(), options.ids.end());
    std::erase_if(units, [&](const CollectionUnit& u) { return !wanted.count(u.id); });
  }
  claim_collection_output(spec, out);
  CollectSummary summary;
  summary.chunks = chunks_per_sequence(spec.count, spec.frames, options.shards);
  summary.selected = static_cast<int>(units.size());
  Progress progress("collect", summary.selected, options.quiet,
                    summary.chunks > 1 ? "frame ranges" : "sequences");
  for (const CollectionUnit& u : units) {
    if (is_done(out, u.id)) {
      ++summary.skipped;
    } else {
      try {
        summary.frames +=
            u.chunks > 1 ? render_chunk(spec, out, u) : render_sequence(spec, out, u.id);
        ++summary.rendered;
      } catch (const std::exception& e) {
        // A finaliser that lost a race to another process may fail once that one is done.
        if (is_done(out, u.id)) {
          ++summary.rendered;
        } else {
          ++summary.failed;
          write_text_atomic(failed_record(out, u.id), std::string(e.what()) + "\n");
          if (!options.quiet) {
            std::fprintf(stderr, "collect: %s failed: %s\n", sequence_folder(u.id).c_str(),
                         e.what());
          }
        }
      }
    }
    progress.advance();
  }
  progress.finish();
  std::error_code ec;
  fs::remove(out / ".staging", ec);  // only when empty: other shards may be working in it
  summary.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  write_collection_index(spec, out);
  return summary;
}

void write_collection_index(const CollectionSpec& spec, const fs::path& out) {
  std::vector<CollectionSequence> sequences;
  std::vector<std::string> keys;
  for (int id = 0; id < spec.count; ++id) {
    sequences.push_back(collection_sequence(spec, id));
    for (const auto& [k, v] : sequences.back().parameters) {
      if (std::find(keys.begin(), keys.end(), k) == keys.end()) keys.push_back(k);
    }
  }
  std::vector<std::string> header = {"id", "folder", "status", "frames", "seed", "render_s"};
  header.insert(header.end(), keys.begin(), keys.end());
  CsvWriter csv(out / "index.csv", header);
  Json index = Json::array();
  for (const CollectionSequence& s : sequences) {
    const fs::path record = out / sequence_folder(s.id) / kSequenceFile;
    Json j;
    if (fs::exists(record)) {
      j = Json::parse(read_text(record));
      j.erase("overrides");
      j["status"] = "done";
    } else {
      j = sequence_record(s, 0, 0);
      j.erase("overrides");
      j["frames"] = nullptr;
      j["render_s"] = nullptr;
      j["status"] = fs::exists(failed_record(out, s.id)) ? "failed" : "missing";
    }
    std::vector<std::string> row = {std::to_string(s.id),
                                    sequence_folder(s.id),
                                    j["status"],
                                    j["frames"].is_null() ? "" : j["frames"].dump(),
                                    std::to_string(s.seed),
                                    j["render_s"].is_null() ? "" : j["render_s"].dump()};
    for (const auto& k : keys) {
      row.push_back(j["parameters"].contains(k) ? j["parameters"][k].get<std::string>() : "");
    }
    write_csv_row(csv.out(), row);
    index.push_back(j);
  }
  csv.commit();
  write_text_atomic(out / "index.json", index.dump(2) + "\n");
}

CollectionStatus collection_status(const fs::path& out) {
  const fs::path record = out / kCollectionFile;
  if (!fs::is_regular_file(record)) {
    throw Error(out.string() + ": no collection here (no " + kCollectionFile + ")");
  }
  const Json j = Json::parse(read_text(record));
  CollectionStatus status;
  status.spec = j.at("spec").get<std::string>();
  const CollectionSpec spec = load_collection(status.spec);
  if (spec.text != j.value("spec_text", "")) {
    throw Error(status.spec.string() + ": the spec changed since " + out.string() +
                " was collected from it");
  }
  status.count = spec.count;
  status.frames = spec.frames;
  for (int id = 0; id < spec.count; ++id) {
    if (is_done(out, id)) {
      status.done.push_back(id);
    } else if (fs::exists(failed_record(out, id))) {
      status.failed.push_back(id);
    } else {
      status.missing.push_back(id);
    }
  }
  write_collection_index(spec, out);
  return status;
}

std::string id_ranges(const std::vector<int>& ids) {
  std::string text;
  for (size_t i = 0; i < ids.size();) {
    size_t j = i;
    while (j + 1 < ids.size() && ids[j + 1] == ids[j] + 1) ++j;
    text += (text.empty() ? "" : ",") + std::to_string(ids[i]);
    if (j > i) text += "-" + std::to_string(ids[j]);
    i = j + 1;
  }
  return text;
}

std::vector<int> parse_id_ranges(const std::string& text, const std::string& what) {
  std::vector<int> ids;
  size_t pos = 0;
  while (pos <= text.size()) {
    const size_t comma = std::min(text.find(',', pos), text.size());
    const std::string item = text.substr(pos, comma - pos);
    int a = 0, b = 0;
    char dash = 0, extra = 0;
    const int n = std::sscanf(item.c_str(), "%d%c%d%c", &a, &dash, &b, &extra);
    if (n == 1 && item.find_first_not_of("0123456789") == std::string::npos) {
      b = a;
    } else if (!(n == 3 && dash == '-' && a <= b && a >= 0 &&
                 item.find_first_not_of("0123456789-") == std::string::npos)) {
      throw Error(what + ": expected ids such as 0-3,7, got '" + item + "'");
    }
    for (int i = a; i <= b; ++i) ids.push_back(i);
    pos = comma + 1;
  }
  return ids;
}

FrameCost measure_frame_cost(const CollectionSpec& spec, const fs::path& out) {
  const fs::path probe = out / ".staging" / "cost_probe";
  fs::remove_all(probe);
  const CollectionSequence s = collection_sequence(spec, 0);
  RenderOptions options = render_options(spec, s);
  options.frames = std::min(spec.frames, 3);
  const RenderSummary r = render_dataset(s.scene, probe, options);
  fs::remove_all(probe);
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  FrameCost cost;
  cost.seconds_per_frame = r.seconds / r.frames;
  cost.peak_mib = static_cast<double>(usage.ru_maxrss) / 1024.0;
  cost.threads = tbb::info::default_concurrency();
  return cost;
}

}  // namespace simcap
