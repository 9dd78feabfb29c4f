// Where `simcap validate` may write its report: a new folder or an earlier report, never a
// dataset's or a track's folder, whose own files a report would mix with or overwrite.
#pragma once

#include <filesystem>

namespace simcap {

// An Error naming `out` when it is a file, or a folder that holds a dataset (meta.json, gt/,
// calibration/) or a track (joints3d.csv).
void check_report_folder(const std::filesystem::path& out);

}  // namespace simcap
