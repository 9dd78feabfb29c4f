#include "tracker/common/track_folder.h"

#include <fcntl.h>

#include <cstdio>

#include "core/error.h"

namespace simcap::tracker {
namespace fs = std::filesystem;

namespace {

fs::path beside(const fs::path& track, const char* suffix) {
  fs::path p = track;
  p += suffix;
  return p;
}

}  // namespace

TrackFolder::TrackFolder(fs::path track) : track_(std::move(track)) {
  // "out/track/" names the folder "track", not an empty file name.
  if (!track_.has_filename()) track_ = track_.parent_path();
  if (fs::exists(track_)) {
    if (!fs::is_directory(track_)) {
      throw Error(track_.string() + ": exists and is not a folder (expected a track folder)");
    }
    if (!fs::is_empty(track_) && !fs::exists(track_ / "joints3d.csv")) {
      throw Error(track_.string() +
                  ": exists and is not a track (no joints3d.csv); choose a new or empty folder");
    }
  }
  staging_ = beside(track_, ".partial");
  fs::remove_all(staging_);
  fs::create_directories(staging_);
}

TrackFolder::~TrackFolder() {
  if (committed_) return;
  std::error_code ignored;
  fs::remove_all(staging_, ignored);
}

void TrackFolder::commit() {
  // An existing TRACK is exchanged with the staging folder in one step, so that a reader (or a
  // kill) finds the previous track or the new one, never neither; file systems without the
  // exchange get two renames through TRACK.old.
  if (fs::exists(track_) &&
      renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, track_.c_str(), RENAME_EXCHANGE) == 0) {
    committed_ = true;
    fs::remove_all(staging_);
    return;
  }
  const fs::path old = beside(track_, ".old");
  fs::remove_all(old);
  if (fs::exists(track_)) fs::rename(track_, old);
  fs::rename(staging_, track_);
  committed_ = true;
  fs::remove_all(old);
}

}  // namespace simcap::tracker
