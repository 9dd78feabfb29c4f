#include "core/track_source.h"

#include <cstdint>
#include <cstdio>
#include <fstream>

#include "core/atomic_file.h"
#include "core/error.h"

namespace simcap {
namespace fs = std::filesystem;

namespace {

// FNV-1a: a fingerprint against mix-ups, not against tampering; stable across compilers, which
// std::hash is not.
void fnv1a(std::uint64_t& h, const std::string& bytes) {
  for (const unsigned char c : bytes) {
    h ^= c;
    h *= 0x100000001b3ULL;
  }
}

std::string file_bytes(const fs::path& path) {
  if (!fs::is_regular_file(path)) return {};
  return read_text(path);
}

}  // namespace

std::string dataset_fingerprint(const fs::path& dataset) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const char* file : {"scene.yaml", "calibration/opencv.yaml"}) {
    // The name and length too, so that bytes moved from one file to the other change it.
    const std::string bytes = file_bytes(dataset / file);
    fnv1a(h, std::string(file) + ":" + std::to_string(bytes.size()) + ":");
    fnv1a(h, bytes);
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

void check_track_source(const fs::path& dataset, const fs::path& track) {
  const fs::path recorded_file = track / kTrackDatasetFile;
  if (!fs::is_regular_file(recorded_file)) return;
  std::ifstream in(recorded_file);
  std::string recorded;
  std::getline(in, recorded);
  if (recorded.size() != 16 ||
      recorded.find_first_not_of("0123456789abcdef") != std::string::npos) {
    throw_input_error(recorded_file, 1, "",
                      "'" + recorded + "'; expected the 16 hex digits simcap track writes");
  }
  const std::string actual = dataset_fingerprint(dataset);
  if (recorded != actual) {
    throw_input_error(recorded_file, 1, "",
                      "the track was made from another dataset (fingerprint " + recorded + "; " +
                          dataset.string() + " is " + actual +
                          ": its scene.yaml or calibration differ); give the dataset it was "
                          "tracked on, or track this one");
  }
}

}  // namespace simcap
