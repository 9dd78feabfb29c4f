// The output folder of `simcap loop` and `simcap demo` (dataset/, track/, report/) given where
// one of its parts was expected: a common slip, answered with the path that was meant.
#pragma once

#include <filesystem>
#include <string_view>

namespace simcap {

// An Error naming `dir`/`part` when `dir` is a loop's output folder (it has `part` and no
// meta.json or joints3d.csv of its own); nothing otherwise. `part` is "dataset" or "track".
void refuse_loop_folder(const std::filesystem::path& dir, std::string_view part);

}  // namespace simcap
