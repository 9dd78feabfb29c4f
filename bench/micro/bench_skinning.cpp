// Skinning throughput (vertices per second) of the body mesh, on 1 and 2 threads, next to a
// memcpy of the same output buffer as the memory-bandwidth baseline.
//   build/bench/micro/bench_skinning --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>
#include <oneapi/tbb/global_control.h>

#include <cstring>
#include <vector>

#include "models/body_mesh.h"
#include "models/humanoid.h"
#include "models/pose.h"

namespace simcap {
namespace {

struct Fixture {
  Fixture() : skeleton(build_humanoid()), mesh(build_body_mesh(skeleton)), skinner(skeleton, mesh) {
    Pose pose = Pose::neutral(skeleton);
    for (auto& q : pose.rotations)
      q = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 1, 0).normalized());
    joint_world = forward_kinematics(skeleton, pose);
  }
  Skeleton skeleton;
  BodyMesh mesh;
  Skinner skinner;
  std::vector<Eigen::Isometry3d> joint_world;
};

const Fixture& fixture() {
  static const Fixture f;
  return f;
}

void BM_Skin(benchmark::State& state) {
  const Fixture& f = fixture();
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism,
                              static_cast<size_t>(state.range(0)));
  std::vector<float> out(3 * f.mesh.vertices.size() + 1);
  for (auto _ : state) {
    f.skinner.skin(f.joint_world, out.data());
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(f.mesh.vertices.size()));
  state.counters["vertices"] = static_cast<double>(f.mesh.vertices.size());
}
BENCHMARK(BM_Skin)->Arg(1)->Arg(2)->ArgName("threads")->UseRealTime();

// Copying the neutral vertices into the same buffer: the floor any skinning pass pays.
void BM_CopyVertices(benchmark::State& state) {
  const Fixture& f = fixture();
  std::vector<float> out(3 * f.mesh.vertices.size() + 1);
  for (auto _ : state) {
    std::memcpy(out.data(), f.mesh.vertices.data(), 3 * sizeof(float) * f.mesh.vertices.size());
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(f.mesh.vertices.size()));
}
BENCHMARK(BM_CopyVertices)->UseRealTime();

}  // namespace
}  // namespace simcap
