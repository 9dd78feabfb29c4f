#include "models/urdf_io.h"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <cstring>
#include <functional>
#include <map>
#include <mutex>
#include <pugixml.hpp>
#include <sstream>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/literal_text.h"

namespace simcap {
namespace {

constexpr double kEffort = 1000.0;   // N m, placeholder (see urdf_io.h)
constexpr double kVelocity = 100.0;  // rad/s, placeholder

std::string number(double v) {
  return shortest_text(v);
}

std::string triple(const Eigen::Vector3d& v) {
  return number(v.x()) + " " + number(v.y()) + " " + number(v.z());
}

// XML comments may not contain "--".
std::string comment_text(std::string text) {
  for (size_t p = text.find("--"); p != std::string::npos; p = text.find("--")) text[p + 1] = ' ';
  return " " + text + " ";
}

std::string link_name(const Skeleton& skeleton, int j) {
  const Joint& joint = skeleton[j];
  if (joint.is_site) return joint.name;
  if (joint.segment.empty()) throw Error("URDF: joint '" + joint.name + "' has no segment name");
  return joint.segment;
}

// Collects urdfdom's console messages during a parse, so that they can go into the Error.
class MessageCapture : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level < console_bridge::CONSOLE_BRIDGE_LOG_WARN) return;
    if (!messages_.empty()) messages_ += "; ";
    messages_ += text;
  }
  const std::string& messages() const { return messages_; }

 private:
  std::string messages_;
};

urdf::ModelInterfaceSharedPtr parse_urdf(const std::string& text, std::string* messages) {
  // console_bridge's handler is process-wide.
  static std::mutex mutex;
  std::lock_guard lock(mutex);
  MessageCapture capture;
  console_bridge::useOutputHandler(&capture);
  urdf::ModelInterfaceSharedPtr model;
  try {
    model = urdf::parseURDF(text);
  } catch (const std::exception& e) {
    capture.log(e.what(), console_bridge::CONSOLE_BRIDGE_LOG_ERROR, "", 0);
  }
  console_bridge::restorePreviousOutputHandler();
  *messages = capture.messages();
  return model;
}

}  // namespace

std::string humanoid_urdf(const Skeleton& skeleton, const std::vector<JointLimits>& limits) {
  if (skeleton.size() == 0) throw Error("URDF: the skeleton is empty");
  for (const JointLimits& l : limits) {
    const int j = skeleton.find(l.joint);
    if (j <= 0 || skeleton[j].is_site) {
      throw Error("URDF: joint limits name '" + l.joint +
                  "', which is not a movable joint of the skeleton");
    }
  }
  pugi::xml_document doc;
  auto decl = doc.append_child(pugi::node_declaration);
  decl.append_attribute("version") = "1.0";
  decl.append_attribute("encoding") = "UTF-8";
  doc.append_child(pugi::node_comment)
      .set_value(
          comment_text(
              "simcap humanoid (H-Anim joint and segment names). Metres and radians; every frame "
              "is world-aligned in the neutral pose (+Y up, +Z the humanoid's front, +X its "
              "left). Root link '" +
              link_name(skeleton, 0) +
              "' is humanoid_root, which is free: give it a floating base. The comment before "
              "each revolute joint names the source of its limits; simcap reads them back with "
              "the limits (edit lower and upper, keep the comment, and give the file to the "
              "limits option of `simcap track` or to a scene's actors[i].limits). Effort and "
              "velocity are placeholders.")
              .c_str());
  pugi::xml_node robot = doc.append_child("robot");
  robot.append_attribute("name") = "simcap_humanoid";

  auto add_link = [&](const std::string& name) {
    robot.append_child("link").append_attribute("name") = name.c_str();
  };
  auto add_joint = [&](const std::string& name, const char* type, const std::string& parent,
                       const std::string& child, const Eigen::Vector3d& origin) {
    pugi::xml_node joint = robot.append_child("joint");
    joint.append_attribute("name") = name.c_str();
    joint.append_attribute("type") = type;
    auto o = joint.append_child("origin");
    o.append_attribute("xyz") = triple(origin).c_str();
    o.append_attribute("rpy") = "0 0 0";
    joint.append_child("parent").append_attribute("link") = parent.c_str();
    joint.append_child("child").append_attribute("link") = child.c_str();
    return joint;
  };

  for (int j = 0; j < skeleton.size(); ++j) add_link(link_name(skeleton, j));
  for (int j = 1; j < skeleton.size(); ++j) {
    const std::string parent = link_name(skeleton, skeleton[j].parent);
    const std::string child = link_name(skeleton, j);
    const Eigen::Vector3d offset = skeleton.offset(j);
    const JointLimits* l =
        skeleton[j].is_site ? nullptr : find_joint_limits(limits, skeleton[j].name);
    if (!l || l->dofs.empty()) {
      add_joint(skeleton[j].name, "fixed", parent, child, offset);
      continue;
    }
    std::string previous = parent;
    for (size_t d = 0; d < l->dofs.size(); ++d) {
      const DofLimit& dof = l->dofs[d];
      const bool last = d + 1 == l->dofs.size();
      const std::string next = last ? child : dof.name + "_link";
      if (!last) add_link(next);
      robot.append_child(pugi::node_comment)
          .set_value(comment_text(dof.name + ": " + dof.source).c_str());
      pugi::xml_node joint = add_joint(dof.name, "revolute", previous, next,
                                       d == 0 ? offset : Eigen::Vector3d::Zero());
      joint.append_child("axis").append_attribute("xyz") = triple(dof.axis).c_str();
      pugi::xml_node limit = joint.append_child("limit");
      limit.append_attribute("lower") = number(dof.lower).c_str();
      limit.append_attribute("upper") = number(dof.upper).c_str();
      limit.append_attribute("effort") = number(kEffort).c_str();
      limit.append_attribute("velocity") = number(kVelocity).c_str();
      previous = next;
    }
  }
  std::ostringstream out;
  doc.save(out, "  ", pugi::format_default, pugi::encoding_utf8);
  return out.str();
}

void write_humanoid_urdf(const std::filesystem::path& path, const Skeleton& skeleton,
                         const std::vector<JointLimits>& limits) {
  write_text_atomic(path, humanoid_urdf(skeleton, limits));
}

std::vector<JointLimits> read_urdf_limits(const std::filesystem::path& path,
                                          const Skeleton& skeleton) {
  std::string messages;
  const std::string text = read_text(path);
  const urdf::ModelInterfaceSharedPtr model = parse_urdf(text, &messages);
  if (!model) throw_input_error(path, 0, "", "not a valid URDF: " + messages);

  // The H-Anim joint a DOF belongs to: the longest movable joint name that prefixes "<joint>_".
  auto owner = [&](const std::string& dof) {
    int best = -1;
    for (int j = 1; j < skeleton.size(); ++j) {
      const std::string& name = skeleton[j].name;
      if (skeleton[j].is_site || dof.size() <= name.size() + 1) continue;
      if (dof.compare(0, name.size(), name) == 0 && dof[name.size()] == '_' &&
          (best < 0 || name.size() > skeleton[best].name.size())) {
        best = j;
      }
    }
    return best;
  };

  // The source of each DOF: the comment "<dof>: <source>" the writer puts before its joint.
  std::map<std::string, std::string> sources;
  {
    pugi::xml_document doc;
    doc.load_string(text.c_str(), pugi::parse_default | pugi::parse_comments);
    std::string previous;
    for (const pugi::xml_node& node : doc.child("robot").children()) {
      if (node.type() == pugi::node_comment) {
        previous = node.value();
        previous.erase(0, previous.find_first_not_of(' '));
        previous.erase(previous.find_last_not_of(' ') + 1);
        continue;
      }
      const std::string name = node.attribute("name").value();
      if (std::strcmp(node.name(), "joint") == 0 && previous.starts_with(name + ": ")) {
        sources[name] = previous.substr(name.size() + 2);
      }
      previous.clear();
    }
  }
  std::map<int, JointLimits> grouped;
  const std::string file_source = "URDF " + path.string();
  // Depth-first from the root, so each H-Anim joint's DOFs arrive in chain order.
  std::function<void(const urdf::LinkConstSharedPtr&)> walk = [&](const auto& link) {
    for (const urdf::JointSharedPtr& joint : link->child_joints) {
      const std::string field = "joint '" + joint->name + "'";
      if (joint->type == urdf::Joint::REVOLUTE) {
        const int j = owner(joint->name);
        if (j < 0) {
          throw_input_error(path, 0, field,
                            "is not a degree of freedom of a joint of the simcap humanoid "
                            "(expected '<H-Anim joint>_<motion>', e.g. l_elbow_flexion)");
        }
        const Eigen::Vector3d axis(joint->axis.x, joint->axis.y, joint->axis.z);
        if (axis != Eigen::Vector3d::UnitX() && axis != Eigen::Vector3d::UnitY() &&
            axis != Eigen::Vector3d::UnitZ()) {
          throw_input_error(path, 0, field, "axis must be 1 0 0, 0 1 0 or 0 0 1");
        }
        JointLimits& entry = grouped[j];
        entry.joint = skeleton[j].name;
        const auto it = sources.find(joint->name);
        entry.dofs.push_back({joint->name, axis, joint->limits->lower, joint->limits->upper,
                              it == sources.end() ? file_source : it->second});
      } else if (joint->type != urdf::Joint::FIXED) {
        throw_input_error(path, 0, field,
                          "has a type other than revolute or fixed, which simcap cannot limit");
      }
      walk(model->getLink(joint->child_link_name));
    }
  };
  walk(model->getRoot());

  std::vector<JointLimits> out;
  for (auto& [j, entry] : grouped) out.push_back(std::move(entry));
  return out;
}

}  // namespace simcap
