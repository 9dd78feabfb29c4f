// The body mesh: closed, outward-oriented parts; sizes; labels; weights; it encloses the skeleton.
#include <gtest/gtest.h>

#include <map>
#include <numbers>
#include <numeric>
#include <set>

#include "core/error.h"
#include "models/body_mesh.h"
#include "models/generalized_cylinder.h"
#include "models/humanoid.h"

namespace simcap {
namespace {

// Connected components of the triangle graph (triangles sharing a vertex): the mesh's parts.
std::vector<std::vector<size_t>> parts_of(const BodyMesh& mesh) {
  std::vector<size_t> root(mesh.vertices.size());
  std::iota(root.begin(), root.end(), 0);
  auto find = [&](size_t v) {
    while (root[v] != v) v = root[v] = root[root[v]];
    return v;
  };
  for (const auto& t : mesh.triangles) {
    root[find(t[1])] = find(t[0]);
    root[find(t[2])] = find(t[0]);
  }
  std::map<size_t, std::vector<size_t>> parts;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) parts[find(mesh.triangles[t][0])].push_back(t);
  std::vector<std::vector<size_t>> out;
  for (auto& [r, tris] : parts) out.push_back(std::move(tris));
  return out;
}

double signed_volume(const BodyMesh& mesh, const std::vector<size_t>& triangles) {
  double v = 0.0;
  for (size_t t : triangles) {
    const auto& tri = mesh.triangles[t];
    const Eigen::Vector3d a = mesh.vertices[tri[0]].cast<double>(),
                          b = mesh.vertices[tri[1]].cast<double>(),
                          c = mesh.vertices[tri[2]].cast<double>();
    v += a.dot(b.cross(c)) / 6.0;
  }
  return v;
}

// Generalized winding number (sum of signed solid angles / 4 pi, Van Oosterom & Strackee 1983):
// 1 inside a closed outward-oriented surface, 0 outside.
double winding_number(const BodyMesh& mesh, const std::vector<size_t>& triangles,
                      const Eigen::Vector3d& p) {
  double total = 0.0;
  for (size_t t : triangles) {
    const auto& tri = mesh.triangles[t];
    const Eigen::Vector3d a = mesh.vertices[tri[0]].cast<double>() - p,
                          b = mesh.vertices[tri[1]].cast<double>() - p,
                          c = mesh.vertices[tri[2]].cast<double>() - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    total += 2.0 * std::atan2(numerator, denominator);
  }
  return total / (4.0 * std::numbers::pi);
}

class BodyMeshTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    skeleton_ = new Skeleton(build_humanoid());
    mesh_ = new BodyMesh(build_body_mesh(*skeleton_));
  }
  static void TearDownTestSuite() {
    delete mesh_;
    delete skeleton_;
  }
  static Skeleton* skeleton_;
  static BodyMesh* mesh_;
};
Skeleton* BodyMeshTest::skeleton_ = nullptr;
BodyMesh* BodyMeshTest::mesh_ = nullptr;

TEST_F(BodyMeshTest, ArraysAgreeAndCountsAreInRange) {
  const BodyMesh& m = *mesh_;
  const size_t n = m.vertices.size();
  EXPECT_EQ(m.influence_joint.size(), n);
  EXPECT_EQ(m.influence_weight.size(), n);
  EXPECT_EQ(m.vertex_segment.size(), n);
  EXPECT_EQ(m.triangle_material.size(), m.triangles.size());
  EXPECT_GE(m.triangles.size(), 20000u);
  EXPECT_LE(m.triangles.size(), 60000u);
  for (const auto& t : m.triangles) {
    for (std::uint32_t v : t) ASSERT_LT(v, n);
    EXPECT_TRUE(t[0] != t[1] && t[1] != t[2] && t[0] != t[2]);
  }
}

TEST_F(BodyMeshTest, EveryEdgeIsSharedByTwoOppositelyOrientedTriangles) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const auto& t : mesh_->triangles) {
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  }
  int bad = 0;
  for (const auto& [edge, count] : directed) {
    const auto reverse = directed.find({edge.second, edge.first});
    if (count != 1 || reverse == directed.end() || reverse->second != 1) ++bad;
  }
  EXPECT_EQ(bad, 0);
}

TEST_F(BodyMeshTest, PartsAreClosedSpheresWithPositiveVolume) {
  const auto parts = parts_of(*mesh_);
  EXPECT_EQ(parts.size(), 10u);  // torso, head, 2 shoulder caps, 2 arms, 2 legs, 2 shoes
  for (const auto& part : parts) {
    std::set<std::uint32_t> vertices;
    std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (size_t t : part) {
      const auto& tri = mesh_->triangles[t];
      for (int k = 0; k < 3; ++k) {
        vertices.insert(tri[k]);
        edges.insert(std::minmax(tri[k], tri[(k + 1) % 3]));
      }
    }
    // Euler characteristic V - E + F = 2: each part is a topological sphere.
    EXPECT_EQ(static_cast<long>(vertices.size()) - static_cast<long>(edges.size()) +
                  static_cast<long>(part.size()),
              2);
    EXPECT_GT(signed_volume(*mesh_, part), 1e-4);  // > 0.1 litre, outward normals
  }
}

TEST_F(BodyMeshTest, EnclosesEveryJointAndBoneMidpoint) {
  const auto parts = parts_of(*mesh_);
  const Skeleton& s = *skeleton_;
  auto inside = [&](const Eigen::Vector3d& p) {
    for (const auto& part : parts) {
      if (winding_number(*mesh_, part, p) > 0.5) return true;
    }
    return false;
  };
  for (int j = 0; j < s.size(); ++j) {
    if (s[j].is_site) continue;
    EXPECT_TRUE(inside(s[j].center)) << s[j].name;
    if (j > 0) {
      EXPECT_TRUE(inside(0.5 * (s[j].center + s[s[j].parent].center))) << s[j].name;
    }
  }
  EXPECT_FALSE(inside({0.0, 1.0, 0.5}));  // in front of the body
  EXPECT_FALSE(inside({0.0, 0.2, 0.0}));  // between the shins
}

TEST_F(BodyMeshTest, WeightsArePartitionsOfUnity) {
  const BodyMesh& m = *mesh_;
  for (size_t i = 0; i < m.vertices.size(); ++i) {
    float sum = 0.0f;
    for (int k = 0; k < 4; ++k) {
      EXPECT_GE(m.influence_weight[i][k], 0.0f);
      ASSERT_LT(m.influence_joint[i][k], skeleton_->size());
      if (m.influence_weight[i][k] > 0) {
        EXPECT_FALSE((*skeleton_)[m.influence_joint[i][k]].is_site);
      }
      sum += m.influence_weight[i][k];
    }
    EXPECT_NEAR(sum, 1.0f, 1e-6f) << "vertex " << i;
  }
}

TEST_F(BodyMeshTest, SegmentLabelsCoverEveryMeshedJoint) {
  const Skeleton& s = *skeleton_;
  std::set<int> labels(mesh_->vertex_segment.begin(), mesh_->vertex_segment.end());
  for (int j : labels) {
    ASSERT_LT(j, s.size());
    EXPECT_FALSE(s[j].is_site) << s[j].name;
  }
  // Every joint with a segment of its own is meshed; humanoid_root's segment (the sacrum) lies
  // inside the pelvis and shares its surface.
  for (int j = 1; j < s.size(); ++j) {
    if (!s[j].is_site) {
      EXPECT_TRUE(labels.count(j)) << s[j].name;
    }
  }
  EXPECT_FALSE(labels.count(0));
}

TEST_F(BodyMeshTest, LabelsAndRegionsSitWhereTheAnatomyIs) {
  const Skeleton& s = *skeleton_;
  const BodyMesh& m = *mesh_;
  const double wrist_y = s[s.require("l_radiocarpal")].center.y();
  const double knee_y = s[s.require("l_knee")].center.y();
  for (size_t i = 0; i < m.vertices.size(); ++i) {
    const std::string& name = s[m.vertex_segment[i]].name;
    const Eigen::Vector3f& v = m.vertices[i];
    if (name == "l_radiocarpal") {
      EXPECT_LT(v.y(), wrist_y + 1e-4);
      EXPECT_GT(v.x(), 0.0f);
    }
    if (name == "r_knee") {
      EXPECT_LT(v.y(), knee_y + 1e-4);
      EXPECT_LT(v.x(), 0.0f);
    }
  }
  std::set<MaterialRegion> regions;
  for (size_t t = 0; t < m.triangles.size(); ++t) {
    const MaterialRegion r = m.triangle_material[t];
    regions.insert(r);
    float y = 0.0f;
    for (std::uint32_t v : m.triangles[t]) y = std::max(y, m.vertices[v].y());
    if (r == MaterialRegion::hair) {
      EXPECT_GT(y, 0.85f * 1.75f);
    }
    if (r == MaterialRegion::shoes) {
      EXPECT_LT(y, 0.1f * 1.75f);
    }
  }
  EXPECT_EQ(regions.size(), static_cast<size_t>(kMaterialRegionCount));
}

TEST(BodyMesh, FollowsHeightAndGirth) {
  for (double H : {1.5, 1.95}) {
    const Skeleton s = build_humanoid({.height = H, .proportions = {}});
    const BodyMesh m = build_body_mesh(s);
    Eigen::Vector3f lo = m.vertices[0], hi = m.vertices[0];
    for (const auto& v : m.vertices) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    EXPECT_NEAR(hi.y(), H, 1e-4 * H);                  // the head top is the skull_tip site
    EXPECT_NEAR(lo.y(), 0.0, 1e-4);                    // soles on the floor
    EXPECT_NEAR(hi.x() - lo.x(), 0.28 * H, 0.04 * H);  // hands hang at the sides
  }
  const Skeleton s = build_humanoid();
  const BodyMesh slim = build_body_mesh(s, {.girth = 0.9}),
                 broad = build_body_mesh(s, {.girth = 1.2});
  ASSERT_EQ(slim.vertices.size(), broad.vertices.size());
  // Width at chest height, arms included: the skeleton is the same, the sections grow.
  float slim_width = 0.0f, broad_width = 0.0f;
  for (size_t i = 0; i < slim.vertices.size(); ++i) {
    if (slim.vertices[i].y() < 1.0f || slim.vertices[i].y() > 1.3f) continue;
    slim_width = std::max(slim_width, slim.vertices[i].x());
    broad_width = std::max(broad_width, broad.vertices[i].x());
  }
  EXPECT_GT(broad_width, slim_width + 0.005f);
  EXPECT_THROW(build_body_mesh(s, {.girth = 0.1}), Error);
}

// Small feet and narrow shoulders, within the scene keys' ranges, still make closed parts: the
// end caps of the shoe and of the shoulder leave room for the sections between them.
TEST(BodyMesh, SmallFeetAndNarrowShouldersAreMeshed) {
  for (const auto& [foot, spacing] :
       {std::pair{0.12, 0.8}, {0.05, 0.8}, {0.152, 0.3}, {0.152, 0.05}}) {
    BodyProportions p;
    p.foot_length = foot;
    p.shoulder_joint_spacing = spacing;
    const BodyMesh m = build_body_mesh(build_humanoid({.height = 1.75, .proportions = p}));
    EXPECT_EQ(parts_of(m).size(), 10u) << foot << " " << spacing;
    for (const auto& part : parts_of(m)) EXPECT_GT(signed_volume(m, part), 0.0);
  }
}

TEST(BodyMesh, IsDeterministic) {
  const Skeleton s = build_humanoid();
  const BodyMesh a = build_body_mesh(s), b = build_body_mesh(s);
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  for (size_t i = 0; i < a.vertices.size(); ++i) ASSERT_EQ(a.vertices[i], b.vertices[i]);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.vertex_segment, b.vertex_segment);
}

// A straight tube of constant elliptical section with half-ellipsoid ends has the volume
// pi a b (L - c0 - c1) + 2/3 pi a b (c0 + c1); the mesh's polygons fall short by O(1/n^2).
TEST(GeneralizedCylinder, EnclosesTheAnalyticVolume) {
  TubeSpec spec;
  spec.axis = {{0, 0, 0}, {0, 0.3, 0.0}, {0, 1.0, 0}};
  const double a = 0.1, b = 0.05, c0 = 0.1, c1 = 0.2;
  spec.start_cap = c0;
  spec.end_cap = c1;
  spec.sections = {{c0, a, b, Eigen::Vector3d::Zero(), 2.0},
                   {1.0 - c1, a, b, Eigen::Vector3d::Zero(), 2.0}};
  spec.segments = 96;
  spec.cap_rings = 48;
  spec.ring_spacing = 0.01;
  const TubeSurface tube = build_tube(spec);
  double volume = 0.0;
  for (const auto& t : tube.triangles) {
    volume += tube.vertices[t[0]].dot(tube.vertices[t[1]].cross(tube.vertices[t[2]])) / 6.0;
  }
  const double expected =
      std::numbers::pi * a * b * (1.0 - c0 - c1) + 2.0 / 3.0 * std::numbers::pi * a * b * (c0 + c1);
  EXPECT_NEAR(volume, expected, 0.002 * expected);
  EXPECT_LT(volume, expected);  // inscribed polygons

  TubeSpec bad = spec;
  bad.sections.front().s = 0.05;  // not where the cap ends
  EXPECT_THROW(build_tube(bad), Error);
  bad = spec;
  bad.axis.resize(1);
  EXPECT_THROW(build_tube(bad), Error);
}

TEST(BodyMesh, NamesEveryRegion) {
  EXPECT_EQ(material_region_name(MaterialRegion::skin), "skin");
  EXPECT_EQ(material_region_name(MaterialRegion::hair), "hair");
}

}  // namespace
}  // namespace simcap
