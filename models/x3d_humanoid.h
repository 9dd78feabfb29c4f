// Reader of H-Anim humanoids in X3D's XML encoding (X3D 3.3/4.0, H-Anim 1.1/2.0): the joint
// tree with its centres and the skin (IndexedFaceSet on the humanoid's skinCoord) with weights.
#pragma once

#include <filesystem>
#include <string_view>

#include "models/imported_body.h"
#include "models/motion.h"

namespace simcap {

// Reads the one HAnimHumanoid of an X3D file in its default pose (joints without translation,
// rotation or scale; the humanoid in metres, +Y up, facing +Z as H-Anim prescribes). DEF/USE are
// followed. Joints come from the DEF'd HAnimJoint tree (nesting gives the parents), their skin
// from skinCoordIndex/skinCoordWeight; skin polygons are fanned into triangles (ccw="false"
// flips them). HAnimSites named like simcap's end sites (skull_tip, l_hand_tip, l_toe_tip, ...;
// also H-Anim's skull_vertex and l/r_dactylion, with or without "_pt") become end sites.
// Then finish_imported_body() completes it. Malformed input throws Error "file:line: what was
// expected": XML errors, a missing or second humanoid, joints without names or with duplicate
// names, bad numbers, indices out of range, fewer weights than indices, a USE without its DEF.
// More weights than indices (the shipped JoeSkin.x3d's l_elbow) keep the first ones and say so
// in the notes.
Body read_x3d_humanoid(const std::filesystem::path& path);
// The same from text in memory; `file` is used in messages only.
Body parse_x3d_humanoid(std::string_view text, const std::filesystem::path& file);

// The first HAnimMotion of an X3D file (X3D 4.0) as a motion of `skeleton`: `joints` names
// skeleton joints (or IGNORED), `channels` gives per joint a count and that many of
// Xposition, Yposition, Zposition (the joint's translation: for humanoid_root, its
// displacement from its centre) and Xrotation, Yrotation, Zrotation (degrees, composed in the
// order listed, as BVH does), `values` holds them frame after frame, frameDuration is 1 / fps.
// Throws Error "file:line: ..." for a missing HAnimMotion, a joint the skeleton lacks, a
// channel count that does not match the joints, values that are not a whole number of frames,
// or a frame duration that is not positive.
Motion read_x3d_motion(const std::filesystem::path& path, const Skeleton& skeleton);
Motion parse_x3d_motion(std::string_view text, const std::filesystem::path& file,
                        const Skeleton& skeleton);

}  // namespace simcap
