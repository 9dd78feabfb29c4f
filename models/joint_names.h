// The joint-name tables by which rigged meshes' bones become H-Anim joints: Mixamo's rig
// (mixamorig:Hips, LeftUpLeg, ...), the glTF humanoid roles of VRM 1.0 (hips, leftUpperLeg,
// ...) and H-Anim itself; the tables are listed in models/joint_names.md.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/name_table.h"

namespace simcap {

enum class JointNaming { automatic, hanim, mixamo, vrm };
inline constexpr NameTable<JointNaming, 4> kJointNamings{{{"auto", JointNaming::automatic},
                                                          {"hanim", JointNaming::hanim},
                                                          {"mixamo", JointNaming::mixamo},
                                                          {"vrm", JointNaming::vrm}}};

// (name in the file, H-Anim joint or site) pairs of a table; empty for hanim (names are kept)
// and automatic.
const std::vector<std::pair<std::string, std::string>>& joint_name_table(JointNaming naming);

// The H-Anim joint a bone called `name` is under `naming`, or "" when the table has none.
// Mixamo names are matched after any "prefix:" (mixamorig:Hips, mixamorig1:Hips); hanim keeps
// every name.
std::string hanim_joint_name(JointNaming naming, std::string_view name);

// The name a table gives H-Anim joint `hanim` ("mixamorig:" prefixed for mixamo), or `hanim`
// itself when the table has none (for exports that other tools should recognize).
std::string joint_name_in(JointNaming naming, const std::string& hanim);

// The naming (mixamo, vrm or hanim) under which the most of `names` map to the joints every
// body needs (imported_body.h); automatic is resolved here. Ties go to the earlier table.
JointNaming detect_joint_naming(const std::vector<std::string>& names);

// The tables as Markdown (models/joint_names.md, written by `simcap model joint-names`).
std::string joint_names_markdown();

}  // namespace simcap
