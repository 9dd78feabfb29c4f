// Cleanup after a killed run: the temporary files AtomicFile leaves when its process dies before
// commit (".<name>.tmp<pid>_<n>.<ext>"), removed so that a re-run's folder holds only its own.
#pragma once

#include <filesystem>

namespace simcap {

// Whether `path` is named as such a temporary file.
bool is_temporary_file_name(const std::filesystem::path& path);

// Removes them under `folder`, recursively; a missing folder is fine.
void remove_stale_temporaries(const std::filesystem::path& folder);

}  // namespace simcap
