// Which dataset a track was made from: `simcap track` writes the dataset's fingerprint into
// TRACK/dataset.txt, and validate and gestures refuse a track of another dataset with it.
#pragma once

#include <filesystem>
#include <string>

namespace simcap {

// One line: the fingerprint of the dataset the track was made from.
inline constexpr const char* kTrackDatasetFile = "dataset.txt";

// 16 hex digits, FNV-1a (64 bits) over DATASET/scene.yaml and calibration/opencv.yaml: the
// same for a copy of the dataset or a byte-identical re-render, another for another scene,
// motion, seed, rig or calibration. A file that is missing counts as empty.
std::string dataset_fingerprint(const std::filesystem::path& dataset);

// An Error when TRACK/dataset.txt exists and holds another fingerprint than `dataset`'s.
// Tracks without the file (older ones, other tools', a dataset's own gt/) are not checked.
void check_track_source(const std::filesystem::path& dataset, const std::filesystem::path& track);

}  // namespace simcap
