// Reader of Acclaim ASF skeletons and AMC motions (the CMU motion-capture database's own
// format), turned into the BvhClip every motion tool of simcap takes (retargeting, dumps, the
// name tables), so that an ASF/AMC trial and its BVH release move the humanoid alike.
#pragma once

#include <filesystem>
#include <string_view>

#include "models/bvh.h"

namespace simcap {

struct AsfAmcOptions {
  // The AMC file states no frame rate; CMU's trials are 120 frames/s.
  double fps = 120.0;
  // Metres per file unit; 0 takes the ASF's `:units length L` (file lengths are inches times
  // L, so a unit is 0.0254 / L m: CMU's length 0.45 gives 1/0.45 inch, as its BVH release).
  double metres_per_unit = 0.0;
};

// The clip: joint 0 "root" (position and rotation channels), then one joint per ASF bone named
// as the bone, at the bone's proximal end (its parent bone's distal end), parents first; a bone
// without children gets the end site "<bone>_End" at its distal end. A bone's rotation relative
// to its parent is C M C^-1 (Acclaim's convention), C from its `axis` angles and M from its AMC
// values (dof rotations applied in the order `dof` lists them, about fixed axes), stored as
// "Zrotation Yrotation Xrotation" channels; the root's M from `order`, its C from `orientation`.
// The rest pose has every bone along its ASF `direction`. Bad input throws Error "file:line:
// ..." for either file: missing sections, unknown keywords, bones named twice or unknown,
// hierarchy cycles, value counts that differ from a bone's dof, frames out of sequence, a
// truncated last frame.
BvhClip read_asf_amc(const std::filesystem::path& asf, const std::filesystem::path& amc,
                     const AsfAmcOptions& options = {});
BvhClip parse_asf_amc(std::string_view asf_text, const std::filesystem::path& asf_file,
                      std::string_view amc_text, const std::filesystem::path& amc_file,
                      const AsfAmcOptions& options = {});

}  // namespace simcap
