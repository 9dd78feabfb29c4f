// Poses to MPEG-4 BAP frames through the monocular body's DOFs (bap_export.h).
#include "tracker/gomez/bap_export.h"

#include "core/error.h"
#include "tracker/gomez/body_dofs.h"

namespace simcap::tracker::gomez {

BapFile bap_from_motion(const Skeleton& skeleton, const Motion& motion,
                        const std::vector<int>& numbers, const std::string& name) {
  if (numbers.size() != motion.frames.size()) {
    throw Error("BAP export: " + std::to_string(numbers.size()) + " frame numbers for " +
                std::to_string(motion.frames.size()) + " poses");
  }
  BapFile bap;
  bap.name = name;
  bap.fps = motion.fps;
  if (motion.frames.empty()) return bap;
  const BodyDofs dofs(skeleton, BodyKind::full, motion.frames.front());
  State x = dofs.clamp(State::Zero(dofs.size()));
  for (size_t k = 0; k < motion.frames.size(); ++k) {
    x = dofs.state_of(motion.frames[k], x);
    BapFrame f;
    f.number = numbers[k];
    for (int i = 0; i < dofs.size(); ++i) f.set(dofs[i].bap, x[i]);
    bap.frames.push_back(f);
  }
  return bap;
}

}  // namespace simcap::tracker::gomez
