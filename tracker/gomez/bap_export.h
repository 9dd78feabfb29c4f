// Any motion of simcap's humanoid as MPEG-4 BAPs (models/mpeg4_bap.h): each pose read as the
// monocular body's angles (Table 2-1 for trunk, neck and arms; hips, knees, ankles; the root).
#pragma once

#include <string>
#include <vector>

#include "models/motion.h"
#include "models/mpeg4_bap.h"
#include "models/skeleton.h"

namespace simcap::tracker::gomez {

// One BAP frame per pose, numbered `numbers[k]` (one per pose): the full body's DOFs
// (gomez/body_dofs.h, root translation free) decomposed from each pose, each angle's representation
// the one within the joint limits or nearest the previous frame's. Rotations of joints the body has
// no DOF for (clavicles, the spine above vl5, toes) are not written. `skeleton` has
// build_humanoid's names.
BapFile bap_from_motion(const Skeleton& skeleton, const Motion& motion,
                        const std::vector<int>& numbers, const std::string& name);

}  // namespace simcap::tracker::gomez
