// The actors of a dataset as its ground truth and masks name them: the names scene.yaml lists,
// the "<actor>/" prefix of every actor's joints after the first, and the mask label of each.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/joint_track.h"

namespace simcap {

// The actors' names in scene order (DATASET/scene.yaml actors[].name; a missing name is
// actor<i>, as the scene loader fills it in). Empty when the dataset has no scene.yaml.
std::vector<std::string> read_dataset_actors(const std::filesystem::path& dataset);

// The index of `name` among `actors`; an empty name is the first actor. A name that is not
// there is an Error naming `what` (e.g. "--actor") and listing the actors.
int find_actor(const std::vector<std::string>& actors, const std::string& name,
               const std::string& what);

// How the ground-truth tables (gt/joints3d.csv, joints2d.csv, angles.csv, joints3d_h36m17.csv)
// name actor `index`'s joints: the first actor's unprefixed, every other one's "<name>/<joint>".
std::string actor_joint_prefix(const std::vector<std::string>& actors, int index);

// Actor `index`'s joints of a ground-truth table, under their own (unprefixed) names.
JointTrack actor_joints(const JointTrack& truth, const std::vector<std::string>& actors, int index);

// Actor `index`'s value in camNN/mask/*.png: 255 when the dataset has one actor, else index + 1.
int actor_mask_label(const std::vector<std::string>& actors, int index);

// A track records the actor it followed in TRACK/actor.txt (one line, the name), written only
// for datasets with several actors; without it a track is of the first actor.
inline constexpr const char* kTrackActorFile = "actor.txt";
// The name in TRACK/actor.txt, empty when there is no such file.
std::string read_track_actor(const std::filesystem::path& track);

}  // namespace simcap
