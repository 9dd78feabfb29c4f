// simcap collect end to end: sharded runs give the unsharded bytes, a killed run resumes, and
// --status / --slurm say what is left and how to run it.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "collect/collection_job.h"
#include "core/atomic_file.h"
#include "tests/collect/collection_files.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {

using testing::expect_same;
using testing::run_simcap;
using testing::TempDir;
namespace fs = std::filesystem;

fs::path write_spec(const TempDir& dir, int count = 4, int frames = 2) {
  const fs::path p = dir / "spec.yaml";
  std::ofstream(p) << "count: " << count << "\nseed: 11\nframes: " << frames << "\n"
                   << "scenes: [" << SIMCAP_SOURCE_DIR << "/scenes/studio4.yaml]\n"
                   << "set: {rig.resolution: [64, 48]}\n"
                   << "motions:\n  - folder: " << SIMCAP_MOCAP_DIR << "\n"
                   << "  - {procedural: walk_path, speed: {uniform: [0.8, 1.6]}}\n"
                   << "bodies: {height: {uniform: [1.55, 1.95]}}\n"
                   << "colors: {shirt: [\"#aa2222\", [0.1, 0.5, 0.2]]}\n";
  return p;
}

TEST(CollectCli, ShardsGiveTheUnshardedBytesAndResumeAfterAKill) {
  TempDir dir;
  const fs::path spec = write_spec(dir);
  const std::string s = spec.string();
  std::string out;
  ASSERT_EQ(run_simcap("collect " + s + " -o " + (dir / "one").string() + " -q", &out), 0) << out;
  EXPECT_NE(out.find("4 sequences: 4 rendered"), std::string::npos) << out;
  for (const char* shard : {"1/2", "0/2"}) {
    ASSERT_EQ(
        run_simcap("collect " + s + " -o " + (dir / "two").string() + " -q --shard " + shard, &out),
        0)
        << out;
    EXPECT_NE(out.find("2 sequences: 2 rendered"), std::string::npos) << out;
  }
  expect_same(dir / "one", dir / "two");
  const auto index = nlohmann::json::parse(read_text(dir / "one" / "index.json"));
  ASSERT_EQ(index.size(), 4u);
  EXPECT_EQ(index[3]["status"], "done");
  EXPECT_EQ(index[3]["frames"], 2);
  EXPECT_EQ(index[0]["parameters"]["actors[0].colors.shirt"], "#aa2222");
  EXPECT_EQ(index[1]["parameters"]["actors[0].colors.shirt"], "[0.1, 0.5, 0.2]");

  // A kill: sequence 2 is half rendered in its staging folder (a frame missing, a stray
  // temporary file), sequence 3 not started.
  const fs::path three = dir / "three";
  fs::create_directories(three / ".staging");
  fs::copy(dir / "one", three, fs::copy_options::recursive);
  fs::remove_all(three / "seq_000003");
  fs::rename(three / "seq_000002", three / ".staging" / "seq_000002");
  fs::remove(three / ".staging" / "seq_000002" / "sequence.json");
  for (const auto& cam : {"cam00", "cam01"}) {
    fs::remove(three / ".staging" / "seq_000002" / cam / "rgb" / "000001.png");
  }
  std::ofstream(three / ".staging" / "seq_000002" / "cam00" / "rgb" / ".000001.tmp99_0.png")
      << "half";
  ASSERT_EQ(run_simcap("collect --status " + three.string(), &out), 1) << out;
  EXPECT_NE(out.find("missing  2  2-3"), std::string::npos) << out;
  EXPECT_NE(out.find("--ids 2-3"), std::string::npos) << out;
  ASSERT_EQ(run_simcap("collect " + s + " -o " + three.string() + " -q --ids 2-3", &out), 0) << out;
  EXPECT_NE(out.find("2 sequences: 2 rendered, 0 done before"), std::string::npos) << out;
  ASSERT_EQ(run_simcap("collect " + s + " -o " + three.string() + " -q", &out), 0) << out;
  EXPECT_NE(out.find("0 rendered, 4 done before"), std::string::npos) << out;
  const auto meta = nlohmann::json::parse(read_text(three / "seq_000002" / "meta.json"));
  EXPECT_EQ(meta["timings"]["frames_resumed"], 1);
  EXPECT_FALSE(fs::exists(three / ".staging"));
  expect_same(dir / "one", three);
  ASSERT_EQ(run_simcap("collect --status " + three.string(), &out), 0) << out;
  EXPECT_NE(out.find("done     4 / 4"), std::string::npos) << out;
}

// Fewer sequences than shards: the shards split the frames of each sequence; the process that
// completes a sequence's last frame range assembles it, byte for byte the single-process one.
TEST(CollectCli, FrameRangeShardsGiveTheUnshardedBytesAndResumeAfterAKill) {
  TempDir dir;
  const std::string s = write_spec(dir, 1, 5).string();
  std::string out;
  ASSERT_EQ(run_simcap("collect " + s + " -o " + (dir / "one").string() + " -q", &out), 0) << out;
  // Three shards of one 5-frame sequence: frames [0, 1), [1, 3), [3, 5).
  const fs::path three = dir / "three";
  for (const char* shard : {"2/3", "0/3"}) {
    ASSERT_EQ(run_simcap("collect " + s + " -o " + three.string() + " -q --shard " + shard, &out),
              0)
        << out;
    EXPECT_NE(out.find("1 frame ranges: 1 rendered"), std::string::npos) << out;
  }
  const fs::path chunks = three / ".staging" / "seq_000000.chunks";
  EXPECT_TRUE(fs::is_directory(chunks / "frames_000000-000001"));
  EXPECT_TRUE(fs::is_directory(chunks / "frames_000003-000005"));
  EXPECT_FALSE(fs::exists(three / "seq_000000"));
  ASSERT_EQ(run_simcap("collect --status " + three.string(), &out), 1) << out;
  EXPECT_NE(out.find("missing  1  0"), std::string::npos) << out;
  // A kill of shard 1 after it rendered frame 1 of its range (frame 2 missing, a stray
  // temporary), and a finaliser of another process killed, leaving its assembly folder.
  const fs::path alone = dir / "alone";
  ASSERT_EQ(run_simcap("collect " + s + " -o " + alone.string() + " -q --shard 1/3", &out), 0)
      << out;
  const fs::path part = chunks / "frames_000001-000003.part";
  fs::rename(alone / ".staging" / "seq_000000.chunks" / "frames_000001-000003", part);
  for (const auto& cam : {"cam00", "cam01", "cam02", "cam03"}) {
    for (const auto& kind : {"rgb", "mask", "parts"}) {
      fs::remove(part / cam / kind / "000002.png");
    }
  }
  std::ofstream(part / "cam00" / "rgb" / ".000002.tmp7_0.png") << "half";
  fs::create_directories(chunks / "assembly.deadhost.1" / "cam00");
  ASSERT_EQ(run_simcap("collect " + s + " -o " + three.string() + " -q --shard 1/3", &out), 0)
      << out;
  const auto meta = nlohmann::json::parse(read_text(three / "seq_000000" / "meta.json"));
  EXPECT_EQ(meta["timings"]["frames_resumed"], 5);  // every image came from a range
  EXPECT_FALSE(fs::exists(three / ".staging"));
  expect_same(dir / "one", three);
}

TEST(CollectCli, RefusesAnotherSpecsOutputAndBadShards) {
  TempDir dir;
  const fs::path spec = write_spec(dir);
  std::string out;
  EXPECT_EQ(
      run_simcap("collect " + spec.string() + " -o " + (dir / "c").string() + " -q --shard 2/2",
                 &out),
      1);
  EXPECT_NE(out.find("--shard: expected K/N with 0 <= K < N"), std::string::npos) << out;
  fs::create_directories(dir / "c");
  std::ofstream(dir / "c" / "notes.txt") << "mine";
  EXPECT_EQ(
      run_simcap("collect " + spec.string() + " -o " + (dir / "c").string() + " -q --ids 0", &out),
      1);
  EXPECT_NE(out.find("not empty and holds no collection"), std::string::npos) << out;
  EXPECT_TRUE(fs::exists(dir / "c" / "notes.txt"));
}

TEST(CollectCli, SlurmScriptAsksForAnArrayWithMeasuredCost) {
  TempDir dir;
  const fs::path spec = write_spec(dir);
  const fs::path c = dir / "c";
  std::string out;
  ASSERT_EQ(run_simcap("collect " + spec.string() + " -o " + c.string() +
                           " --slurm --shards 3 --max-running 2 --cpus-per-task 4",
                       &out),
            0)
      << out;
  const std::string script = read_text(c / "slurm" / "collect.sbatch");
  EXPECT_NE(script.find("#SBATCH --array=0-2%2\n"), std::string::npos) << script;
  EXPECT_NE(script.find("#SBATCH --cpus-per-task=4\n"), std::string::npos) << script;
  EXPECT_NE(script.find("#SBATCH --output=" + c.string() + "/slurm/logs/%A_%a.out"),
            std::string::npos)
      << script;
  EXPECT_NE(script.find("--shard \"${SLURM_ARRAY_TASK_ID}/3\""), std::string::npos) << script;
  const auto plan = nlohmann::json::parse(read_text(c / "slurm" / "plan.json"));
  EXPECT_GT(plan["measured_s_per_frame"].get<double>(), 0);
  EXPECT_GE(plan["time_s"].get<long>(), 300);
  EXPECT_GE(plan["mem_mib"].get<long>(), 1024);
  EXPECT_FALSE(fs::exists(c / ".staging" / "cost_probe"));
  // Nothing rendered yet: --status names every sequence and the array tasks to re-submit.
  ASSERT_EQ(run_simcap("collect --status " + c.string(), &out), 1) << out;
  EXPECT_NE(out.find("missing  4  0-3"), std::string::npos) << out;
  EXPECT_NE(out.find("sbatch --array=0-2 " + (c / "slurm" / "collect.sbatch").string()),
            std::string::npos)
      << out;
  // More shards than sequences: tasks split frames, up to one per frame (4 x 2 here); sequence
  // 3 is frames 0-1 of units 6 and 7.
  ASSERT_EQ(
      run_simcap("collect " + spec.string() + " -o " + c.string() + " --slurm --shards 20", &out),
      0)
      << out;
  EXPECT_NE(read_text(c / "slurm" / "collect.sbatch").find("#SBATCH --array=0-7\n"),
            std::string::npos);
  ASSERT_EQ(run_simcap("collect " + spec.string() + " -o " + c.string() + " -q --ids 0-2", &out), 0)
      << out;
  ASSERT_EQ(run_simcap("collect --status " + c.string(), &out), 1) << out;
  EXPECT_NE(out.find("missing  1  3"), std::string::npos) << out;
  EXPECT_NE(out.find("sbatch --array=6-7 "), std::string::npos) << out;
}

}  // namespace
}  // namespace simcap
