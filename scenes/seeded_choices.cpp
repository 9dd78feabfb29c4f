// resolve_seeded_choices (scene.h): the subject and gesture corpus a render seed picks.
#include <random>

#include "scenes/scene.h"

namespace simcap {

void resolve_seeded_choices(Scene& scene) {
  for (size_t i = 0; i < scene.actors.size(); ++i) {
    Actor& a = scene.actors[i];
    if (a.motion.bvh.empty() && a.motion.procedural.kind == "gestures" &&
        a.motion.procedural.gestures.seed == 0) {
      a.motion.procedural.gestures.seed = scene.render.seed;
    }
    if (a.vary.height <= 0 && a.vary.proportions <= 0) continue;
    // One stream per actor and seed; uniform numbers taken from its bits directly, so that they
    // do not depend on the standard library's distributions.
    std::seed_seq seq{static_cast<std::uint32_t>(scene.render.seed),
                      static_cast<std::uint32_t>(scene.render.seed >> 32),
                      static_cast<std::uint32_t>(i), 0x5eedu};
    std::mt19937_64 rng(seq);
    auto uniform = [&] { return 2.0 * ((rng() >> 11) * 0x1.0p-53) - 1.0; };  // [-1, 1)
    a.body.parameters.height += a.vary.height * uniform();
    // Segment lengths and breadths vary on their own; the leg's length moves hip and knee heights
    // together, so the skeleton keeps its order from feet to head.
    BodyProportions& p = a.body.parameters.proportions;
    for (double BodyProportions::*member :
         {&BodyProportions::upper_arm, &BodyProportions::forearm, &BodyProportions::hand,
          &BodyProportions::foot_length, &BodyProportions::shoulder_width,
          &BodyProportions::hip_width}) {
      p.*member *= 1.0 + a.vary.proportions * uniform();
    }
    const double leg = 1.0 + a.vary.proportions * uniform();
    p.hip_height *= leg;
    p.knee_height *= leg;
    a.vary = {};
  }
}

}  // namespace simcap
