// A track folder written all or nothing: a tracker writes into a staging folder beside TRACK,
// which replaces TRACK only when the run completes, so a failed run leaves no half track behind.
#pragma once

#include <filesystem>

namespace simcap::tracker {

class TrackFolder {
 public:
  // Refuses a TRACK that exists and holds files but no joints3d.csv: it is not a track, and a
  // slip such as `-o .` must not replace a user's folder. Starts an empty staging folder.
  explicit TrackFolder(std::filesystem::path track);
  ~TrackFolder();
  TrackFolder(const TrackFolder&) = delete;
  TrackFolder& operator=(const TrackFolder&) = delete;

  // Where the run writes.
  const std::filesystem::path& path() const { return staging_; }
  // The staged folder becomes TRACK (a previous TRACK is removed).
  void commit();

 private:
  std::filesystem::path track_, staging_;
  bool committed_ = false;
};

}  // namespace simcap::tracker
