// Command-line overrides of a YAML tree ("rig.count=6", "actors[0].motion.speed=1.5",
// "occluders=[]"), applied before validation so that overridden values are checked like the file.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "scenes/yaml_field.h"

namespace simcap::yaml {

// Applies each "key.path=value" to `root` in order (the value is YAML text; missing maps on the
// path are created, list indices must exist) and records it in `origin` so that later
// validation errors inside it name the override. A malformed override throws Error naming it.
void apply_overrides(YAML::Node& root, const std::vector<std::string>& overrides, Origin& origin);

}  // namespace simcap::yaml
