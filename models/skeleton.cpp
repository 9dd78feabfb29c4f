#include "models/skeleton.h"

#include "core/error.h"

namespace simcap {

int Skeleton::add(Joint joint) {
  if (find(joint.name) >= 0) throw Error("skeleton: joint '" + joint.name + "' added twice");
  if (joint.parent >= size() || (joint.parent < 0 && !joints_.empty())) {
    throw Error("skeleton: joint '" + joint.name + "' has no valid parent (the root comes first)");
  }
  joints_.push_back(std::move(joint));
  return size() - 1;
}

int Skeleton::find(std::string_view name) const {
  for (int i = 0; i < size(); ++i) {
    if (joints_[i].name == name) return i;
  }
  return -1;
}

int Skeleton::require(std::string_view name) const {
  const int i = find(name);
  if (i < 0) throw Error("skeleton has no joint '" + std::string(name) + "'");
  return i;
}

Eigen::Vector3d Skeleton::offset(int i) const {
  const int p = joints_[i].parent;
  return p < 0 ? Eigen::Vector3d::Zero() : Eigen::Vector3d(joints_[i].center - joints_[p].center);
}

std::vector<int> Skeleton::children(int i) const {
  std::vector<int> out;
  for (int j = i + 1; j < size(); ++j) {
    if (joints_[j].parent == i) out.push_back(j);
  }
  return out;
}

bool Skeleton::is_descendant(int descendant, int ancestor) const {
  for (int j = descendant; j >= 0; j = joints_[j].parent) {
    if (j == ancestor) return true;
  }
  return false;
}

}  // namespace simcap
