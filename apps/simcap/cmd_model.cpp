// simcap model info | urdf | mesh | limits: inspect the humanoid (joints, segments, lengths),
// export its kinematics and limits as URDF, its skinned body as OBJ/PLY/glTF, its limit table.
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <numbers>

#include "apps/simcap/choice_option.h"
#include "apps/simcap/commands.h"
#include "apps/simcap/number_checks.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "models/body_gltf.h"
#include "models/body_mesh.h"
#include "models/body_source.h"
#include "models/humanoid.h"
#include "models/joint_limits.h"
#include "models/joint_names.h"
#include "models/mesh_export.h"
#include "models/motion_source.h"
#include "models/pose.h"
#include "models/urdf_io.h"
#include "scenes/scene.h"

namespace simcap::cli {
namespace {

struct ModelOptions {
  std::string output;
  double height = 1.75;
  double girth = 1.0;
  std::string body;  // a body file instead of the humanoid
  JointNaming rig_names = JointNaming::hanim;
  std::string bvh;
  std::string procedural;
  double time_s = 0.0;
  std::vector<std::string> set;
};

Skeleton skeleton_of(const ModelOptions& o) {
  return build_humanoid({.height = o.height, .proportions = {}});
}

Body body_of(const ModelOptions& o) {
  if (o.body.empty()) {
    BodySource source;
    source.parameters.height = o.height;
    source.shape.girth = o.girth;
    return build_body(source);
  }
  return build_body(body_file_source(o.body));
}

int info(const ModelOptions& o) {
  const Body body = body_of(o);
  const Skeleton& s = body.skeleton;
  const auto& limits = humanoid_joint_limits();
  if (o.body.empty()) {
    std::printf(
        "simcap humanoid, height %.3f m (Drillis & Contini proportions), %d joints and sites\n",
        o.height, s.size());
  } else {
    std::printf("%s: %d joints and sites\n", o.body.c_str(), s.size());
    for (const std::string& note : body.notes) std::printf("note: %s\n", note.c_str());
  }
  std::printf("%3s  %-24s %-28s %-18s %8s %8s %8s %8s  %s\n", "#", "joint", "segment", "parent",
              "x", "y", "z", "length", "DOFs");
  int dof_count = 0;
  for (int j = 0; j < s.size(); ++j) {
    const Joint& joint = s[j];
    std::string dofs = j == 0 ? "free (6)" : joint.is_site ? "site" : "fixed";
    if (const JointLimits* l = find_joint_limits(limits, joint.name)) {
      dofs.clear();
      for (const DofLimit& d : l->dofs) dofs += (dofs.empty() ? "" : " ") + d.name;
      dof_count += static_cast<int>(l->dofs.size());
    }
    std::printf("%3d  %-24s %-28s %-18s %8.4f %8.4f %8.4f %8.4f  %s\n", j, joint.name.c_str(),
                joint.is_site ? "-" : joint.segment.c_str(),
                joint.parent < 0 ? "-" : s[joint.parent].name.c_str(), joint.center.x(),
                joint.center.y(), joint.center.z(), s.offset(j).norm(), dofs.c_str());
  }
  const BodyMesh& mesh = body.mesh;
  std::map<MaterialRegion, int> per_region;
  for (MaterialRegion r : mesh.triangle_material) ++per_region[r];
  std::string regions;
  for (const auto& [r, n] : per_region) {
    regions += (regions.empty() ? "" : ", ") + std::string(material_region_name(r)) + " " +
               std::to_string(n);
  }
  std::printf(
      "limited DOFs: %d (URDF revolute joints)\nbody mesh: %zu vertices, %zu triangles (%s)\n",
      dof_count, mesh.vertices.size(), mesh.triangles.size(), regions.c_str());
  return 0;
}

int urdf(const ModelOptions& o) {
  write_humanoid_urdf(o.output, skeleton_of(o), humanoid_joint_limits());
  std::fprintf(stderr, "wrote %s (height %.3f m)\n", o.output.c_str(), o.height);
  return 0;
}

// "l_elbow_flexion=-90": a DOF of the limit table and an angle in degrees.
std::pair<const JointLimits*, std::pair<size_t, double>> parse_set(const std::string& text) {
  const size_t eq = text.find('=');
  const std::string name = text.substr(0, eq);
  double degrees = 0.0;
  try {
    if (eq == std::string::npos) throw std::invalid_argument("no '='");
    size_t used = 0;
    degrees = std::stod(text.substr(eq + 1), &used);
    if (used != text.size() - eq - 1) throw std::invalid_argument("trailing text");
  } catch (const std::exception&) {
    throw Error("--set '" + text + "': expected DOF=DEGREES, e.g. l_elbow_flexion=-90");
  }
  for (const JointLimits& l : humanoid_joint_limits()) {
    for (size_t d = 0; d < l.dofs.size(); ++d) {
      if (l.dofs[d].name == name) return {&l, {d, degrees * std::numbers::pi / 180.0}};
    }
  }
  throw Error("--set '" + text + "': no DOF '" + name +
              "' (see `simcap model info` for the DOF names)");
}

int mesh(const ModelOptions& o) {
  const Body b = body_of(o);
  const Skeleton& s = b.skeleton;
  Pose pose = Pose::neutral(s);
  if (!o.bvh.empty() || !o.procedural.empty()) {
    MotionSource source;
    source.bvh = o.bvh;
    if (!o.procedural.empty()) source.procedural.kind = o.procedural;
    const double fps = 30.0;
    const Motion motion = load_motion(source, s, fps);
    if (motion.frames.empty()) throw Error("the motion has no frames");
    const auto frame = static_cast<size_t>(std::lround(o.time_s * fps));
    if (frame >= motion.frames.size()) {
      throw Error("--time " + std::to_string(o.time_s) + " s is past the motion's end (" +
                  std::to_string(motion.duration_s()) + " s)");
    }
    pose = motion.frames[frame];
  }
  for (const std::string& text : o.set) {
    const auto [limits, value] = parse_set(text);
    const auto [dof, angle] = value;
    const DofLimit& d = limits->dofs[dof];
    if (angle < d.lower || angle > d.upper) {
      std::fprintf(stderr, "simcap model mesh: %s is outside its limits [%.1f, %.1f] deg\n",
                   text.c_str(), d.lower * 180 / std::numbers::pi,
                   d.upper * 180 / std::numbers::pi);
    }
    const int j = s.require(limits->joint);
    std::vector<double> angles = dof_angles(*limits, pose.rotations[j]);
    angles[dof] = angle;
    pose.rotations[j] = dof_rotation(*limits, angles);
  }
  const BodyMesh& body = b.mesh;
  if (std::filesystem::path(o.output).extension() == ".glb") {
    GltfBuilder gltf;
    const JointNaming naming = o.rig_names;
    add_gltf_body(gltf, "body", s, body, Actor{}.colors, pose,
                  [naming](const std::string& hanim) { return joint_name_in(naming, hanim); });
    gltf.write(o.output);
    std::fprintf(stderr, "wrote %s: %d joints, %zu vertices, %zu triangles\n", o.output.c_str(),
                 s.size(), body.vertices.size(), body.triangles.size());
    return 0;
  }
  std::vector<float> positions(3 * body.vertices.size() + 1);
  Skinner(s, body).skin(forward_kinematics(s, pose), positions.data());
  export_body_mesh(o.output, body, std::span(positions).first(3 * body.vertices.size()),
                   Actor{}.colors);
  std::fprintf(stderr, "wrote %s: %zu vertices, %zu triangles\n", o.output.c_str(),
               body.vertices.size(), body.triangles.size());
  return 0;
}

std::string limits_document() {
  return "# Joint limits of the simcap humanoid\n\n"
         "Generated by `simcap model limits` from models/assets/humanoid_limits.urdf (simcap's "
         "limits, each with its source) and models/joint_limits.cpp (the theses' tables); do "
         "not edit by hand.\n"
         "Axes are those of the joint's world-aligned neutral frame (+Y up, +Z the humanoid's "
         "front, +X its left); angles are right-handed rotations about +axis, so flexing the "
         "left elbow is a negative rotation about +X. A joint's DOFs compose outermost first in "
         "the order Z, X, Y, exactly as the URDF's chain of revolute joints "
         "(`simcap model urdf`). humanoid_root is free (6 DOF).\n\n"
         "## The limits simcap uses (URDF, inverse kinematics)\n\n" +
         joint_limits_markdown(humanoid_joint_limits()) +
         "\n## Moschini 2009, Table 5.1, in simcap axes\n\n"
         "His torso frame has X forward, Y left, Z up; his zero pose holds the arms out "
         "sideways, hence the shoulder offsets. A thesis angle t maps to sign * t + offset "
         "(`DofLimit::source_sign`, `source_offset`).\n\n" +
         joint_limits_markdown(moschini_joint_limits()) +
         "\n## Gomez Jauregui 2011, Table 2-1, in simcap axes\n\n"
         "Axes inferred from the MPEG-4 BAP names of Table 2-2 (the thesis states none).\n\n" +
         joint_limits_markdown(gomez_joint_limits());
}

// Markdown to standard output or to --output.
int print_or_write(const ModelOptions& o, const std::string& text) {
  if (o.output.empty()) {
    std::fwrite(text.data(), 1, text.size(), stdout);
  } else {
    write_text_atomic(o.output, text);
  }
  return 0;
}

int limits(const ModelOptions& o) {
  return print_or_write(o, limits_document());
}

}  // namespace

void add_model(CLI::App& app, Action& action) {
  auto* model = app.add_subcommand(
      "model", "Inspect and export the humanoid: joints, URDF limits, skinned body mesh");
  model->require_subcommand(1);
  model->footer(
      "Examples:\n"
      "  simcap model info --height 1.80\n"
      "  simcap model urdf -o body.urdf\n"
      "  simcap model mesh -o body.glb --set l_elbow_flexion=-90\n"
      "  simcap model limits -o joint_limits.md\n"
      "  simcap model info --body character.glb");
  auto o = std::make_shared<ModelOptions>();
  auto add_height = [o](CLI::App* cmd) {
    cmd->add_option("--height", o->height, "Humanoid height in metres")
        ->check(CLI::Range(0.5, 2.6))
        ->capture_default_str();
  };
  auto add_girth = [o](CLI::App* cmd) {
    cmd->add_option("--girth", o->girth, "Body girth scale (1 = average adult)")
        ->check(CLI::Range(0.5, 2.0))
        ->capture_default_str();
  };
  auto add_body = [o](CLI::App* cmd) {
    cmd->add_option("--body", o->body,
                    "A body file instead of simcap's humanoid: an H-Anim X3D humanoid (.x3d) or a "
                    "rigged mesh (.glb, .gltf, .fbx, .dae; bone names by models/joint_names.md)")
        ->check(CLI::ExistingFile)
        ->excludes(cmd->get_option("--height"))
        ->excludes(cmd->get_option("--girth"));
  };

  auto* i = model->add_subcommand(
      "info",
      "List joints and sites: segment, parent, neutral centre, bone length, DOFs; and "
      "the body mesh's size");
  add_height(i);
  add_girth(i);
  add_body(i);
  i->footer(
      "Examples:\n  simcap model info --height 1.62\n"
      "  simcap model info --body models/assets/JoeSkin.x3d");
  i->callback([&action, o] { action = [o] { return info(*o); }; });

  auto* u = model->add_subcommand(
      "urdf",
      "Write the humanoid's kinematics and joint limits as URDF (one revolute joint per "
      "DOF; check it with check_urdf)");
  u->add_option("-o,--output", o->output, "URDF file to write")->required();
  add_height(u);
  u->footer("Example:\n  simcap model urdf -o body.urdf --height 1.80 && check_urdf body.urdf");
  u->callback([&action, o] { action = [o] { return urdf(*o); }; });

  auto* m = model->add_subcommand(
      "mesh",
      "Write the skinned body mesh (neutral, or posed by a motion and/or --set) as OBJ or PLY "
      "(one part per material region), or as binary glTF with its skeleton and skin (the pose "
      "in the joints; Blender, three.js and `--body` read it back)");
  m->add_option("-o,--output", o->output, "Mesh file: .obj, .ply or .glb")->required();
  add_height(m);
  add_girth(m);
  add_body(m);
  auto* bvh = m->add_option("--bvh", o->bvh, "Pose from this BVH clip (retargeted)");
  m->add_option("--procedural", o->procedural,
                "Pose from this procedural motion (stand, tpose, walk_in_place, walk_path, "
                "arm_raise, turn)")
      ->excludes(bvh);
  add_choice(m, "--rig-names", o->rig_names,
             NameTable<JointNaming, 3>{{{"hanim", JointNaming::hanim},
                                        {"mixamo", JointNaming::mixamo},
                                        {"vrm", JointNaming::vrm}}},
             "glTF only: name the skeleton's nodes by H-Anim, Mixamo (mixamorig:LeftArm) or VRM "
             "(leftUpperArm) where the table has the joint (models/joint_names.md)");
  m->add_option("--time", o->time_s, "Time in the motion, seconds")
      ->check(non_negative_number())
      ->capture_default_str();
  m->add_option("--set", o->set,
                "Set one DOF in degrees on top of the pose, e.g. l_elbow_flexion=-90 "
                "(repeatable; names in `simcap model info`)");
  m->footer(
      "Examples:\n"
      "  simcap model mesh -o body.obj\n"
      "  simcap model mesh -o wave.glb --set l_shoulder_abduction=150 --set l_elbow_flexion=-60\n"
      "  simcap model mesh -o walk.ply --procedural walk_path --time 1.2\n"
      "  simcap model mesh --body models/assets/JoeSkin.x3d --bvh walk.bvh --time 2 -o joe.glb");
  m->callback([&action, o] { action = [o] { return mesh(*o); }; });

  auto* l = model->add_subcommand(
      "limits",
      "Print the joint-limit tables (simcap's, Moschini's, Gomez Jauregui's) with "
      "every number's source, as Markdown");
  l->add_option("-o,--output", o->output, "Write to this file instead of standard output");
  l->footer("Example:\n  simcap model limits -o models/joint_limits.md");
  l->callback([&action, o] { action = [o] { return limits(*o); }; });

  auto* n = model->add_subcommand(
      "joint-names",
      "Print the tables that map rigged meshes' bone names (Mixamo, VRM) to H-Anim joints, as "
      "Markdown");
  n->add_option("-o,--output", o->output, "Write to this file instead of standard output");
  n->footer("Example:\n  simcap model joint-names -o models/joint_names.md");
  n->callback(
      [&action, o] { action = [o] { return print_or_write(*o, joint_names_markdown()); }; });
}

}  // namespace simcap::cli
