#include "models/bvh_export.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/atomic_file.h"
#include "core/error.h"

namespace simcap {
namespace {

void append(std::string& out, const char* format, double a, double b, double c) {
  char buf[160];
  std::snprintf(buf, sizeof buf, format, a, b, c);
  out += buf;
}

}  // namespace

Eigen::Vector3d zyx_degrees(const Eigen::Quaterniond& q) {
  const Eigen::Matrix3d R = q.normalized().toRotationMatrix();
  const double b = std::asin(std::clamp(-R(2, 0), -1.0, 1.0));
  double a, c;
  if (std::hypot(R(0, 0), R(1, 0)) < 1e-12) {  // gimbal lock: only a - c (or a + c) is defined
    a = std::atan2(-R(0, 1), R(1, 1));
    c = 0;
  } else {
    a = std::atan2(R(1, 0), R(0, 0));
    c = std::atan2(R(2, 1), R(2, 2));
  }
  return Eigen::Vector3d(a, b, c) * (180.0 / std::numbers::pi);
}

namespace {

class Writer {
 public:
  Writer(const Skeleton& skeleton, double unit) : s_(skeleton), unit_(unit) {}

  std::string hierarchy() {
    out_ = "HIERARCHY\nROOT " + s_[0].name + "\n{\n\tOFFSET 0 0 0\n";
    out_ += "\tCHANNELS 6 Xposition Yposition Zposition Zrotation Yrotation Xrotation\n";
    order_.push_back(0);
    children(0, 1);
    out_ += "}\n";
    return out_;
  }
  // Joints with channels, in the order their values appear in a frame.
  const std::vector<int>& order() const { return order_; }

 private:
  void children(int j, int depth) {
    const std::string indent(depth, '\t');
    const auto kids = s_.children(j);
    bool has_site = false;
    for (int k : kids) {
      const Eigen::Vector3d o = s_.offset(k) / unit_;
      if (s_[k].is_site) {
        if (!s_.children(k).empty()) {
          throw Error("BVH export: site '" + s_[k].name + "' has children");
        }
        out_ += indent + "End Site\n" + indent + "{\n" + indent;
        append(out_, "\tOFFSET %.7f %.7f %.7f\n", o.x(), o.y(), o.z());
        out_ += indent + "}\n";
        has_site = true;
        continue;
      }
      out_ += indent + "JOINT " + s_[k].name + "\n" + indent + "{\n" + indent;
      append(out_, "\tOFFSET %.7f %.7f %.7f\n", o.x(), o.y(), o.z());
      out_ += indent + "\tCHANNELS 3 Zrotation Yrotation Xrotation\n";
      order_.push_back(k);
      children(k, depth + 1);
      out_ += indent + "}\n";
    }
    if (kids.empty() && !has_site) {
      out_ += indent + "End Site\n" + indent + "{\n" + indent + "\tOFFSET 0 0 0\n" + indent + "}\n";
    }
  }

  const Skeleton& s_;
  double unit_;
  std::string out_;
  std::vector<int> order_;
};

}  // namespace

std::string format_bvh(const Skeleton& skeleton, const Motion& motion,
                       const BvhWriteOptions& options) {
  if (skeleton.size() == 0) throw Error("BVH export: the skeleton is empty");
  if (motion.frames.empty()) throw Error("BVH export: the motion has no frames");
  if (!(motion.fps > 0)) throw Error("BVH export: the motion's frame rate is not positive");
  if (!(options.metres_per_unit > 0)) throw Error("BVH export: metres per unit must be positive");
  Writer writer(skeleton, options.metres_per_unit);
  std::string out = writer.hierarchy();
  char buf[160];
  std::snprintf(buf, sizeof buf, "MOTION\nFrames: %zu\nFrame Time: %.9g\n", motion.frames.size(),
                1.0 / motion.fps);
  out += buf;
  for (size_t f = 0; f < motion.frames.size(); ++f) {
    const Pose& pose = motion.frames[f];
    if (static_cast<int>(pose.rotations.size()) != skeleton.size()) {
      throw Error("BVH export: frame " + std::to_string(f) + " has " +
                  std::to_string(pose.rotations.size()) + " rotations, the skeleton " +
                  std::to_string(skeleton.size()) + " joints");
    }
    const Eigen::Vector3d p = pose.root_position / options.metres_per_unit;
    append(out, "%.7f %.7f %.7f", p.x(), p.y(), p.z());
    for (int j : writer.order()) {
      const Eigen::Vector3d e = zyx_degrees(pose.rotations[j]);
      append(out, " %.6f %.6f %.6f", e.x(), e.y(), e.z());
    }
    out += '\n';
  }
  return out;
}

void write_bvh(const std::filesystem::path& path, const Skeleton& skeleton, const Motion& motion,
               const BvhWriteOptions& options) {
  write_text_atomic(path, format_bvh(skeleton, motion, options));
}

}  // namespace simcap
