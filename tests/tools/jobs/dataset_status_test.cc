// `airis dataset status` and `--only-shards` from shard folders written by hand: frames counted
// from the manifests and checksum lists, Slurm's states read from squeue's text, and the checks
// that keep a resubmission from leaving a merge that can never run.
#include "tools/jobs/dataset_status.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "engine/core/error.h"
#include "engine/dataset/file_io.h"
#include "tests/fixtures/temp_dir.h"
#include "tools/jobs/shard_progress.h"
#include "tools/jobs/slurm_client.h"
#include "tools/jobs/slurm_submission.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;

void Write(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

// A shard folder that finished with `frames` frames.
void CompleteShard(const fs::path& dir, int frames) {
  Write(dir / "manifest.json",
        R"({"format": "airis-dataset", "complete": true, "counts": {"frames": )" +
            std::to_string(frames) + "}}");
}

// A shard folder stopped by SIGTERM after writing frames 0, 3 (two planes each) of camera front
// and frame 0 of camera down; the journal's last line is torn.
void InterruptedShard(const fs::path& dir) {
  Write(dir / "manifest.json",
        R"({"format": "airis-dataset", "complete": false, "interrupted_by_signal": 15})");
  Write(dir / "checksums.journal",
        "front/rgb/000000.png,10,aa\nfront/depth/000000.png,10,bb\nfront/rgb/000003.png,10,cc\n"
        "tartanair/front/image_left/000000_left.png,10,dd\ndown/rgb/000000.png,10,ee\n"
        "front/depth/000006.png,1");
}

SlurmRecord Record(const fs::path& out) {
  SlurmRecord r;
  r.plan.dataset = {"/opt/airis", "/data/city.yaml", "/data/survey.yaml", {"--seed", "7"}};
  r.plan.out = out.string();
  r.plan.shards = 3;
  r.submissions.push_back({"100", {1, 2, 3}, "101", {}});
  return r;
}

TEST(ShardProgressTest, CountsFramesFromTheManifestOrTheJournal) {
  const fs::path dir = airis::testing::MakeTempFolder("progress");
  EXPECT_FALSE(ReadShardProgress((dir / "absent").string()).started);
  CompleteShard(dir / "done", 40);
  const ShardProgress done = ReadShardProgress((dir / "done").string());
  EXPECT_TRUE(done.started && done.complete);
  EXPECT_EQ(done.frames, 40);
  InterruptedShard(dir / "stopped");
  const ShardProgress stopped = ReadShardProgress((dir / "stopped").string());
  EXPECT_TRUE(stopped.started);
  EXPECT_FALSE(stopped.complete);
  // front 000000 (two planes, one frame), front 000003, down 000000; not the TartanAir copy, not
  // the torn line.
  EXPECT_EQ(stopped.frames, 3);
  EXPECT_EQ(stopped.interrupted_by_signal, 15);
  Write(dir / "bad" / "manifest.json", "{\"format\": \"something-else\"}");
  EXPECT_THROW(ReadShardProgress((dir / "bad").string()), engine::DatasetIoError);
}

TEST(SqueueTest, ReadsOneLinePerTaskAndRefusesOtherText) {
  const auto jobs = ParseSqueueOutput(
      "100_2|RUNNING|None\n100_3|PENDING|Resources\n101|PENDING|Dependency\n"
      "100_1|COMPLETED|None\n");
  ASSERT_EQ(jobs.size(), 4u);
  EXPECT_EQ(jobs[0].job, "100_2");
  EXPECT_EQ(jobs[0].array_job, "100");
  EXPECT_EQ(jobs[0].array_task, 2);
  EXPECT_TRUE(jobs[0].active());
  EXPECT_EQ(jobs[2].array_task, -1);
  EXPECT_EQ(jobs[2].reason, "Dependency");
  EXPECT_FALSE(jobs[3].active());
  EXPECT_THROW(ParseSqueueOutput("JOBID STATE\n"), SchedulerError);
  // A pending array squeue did not split (it was run without --array).
  EXPECT_THROW(ParseSqueueOutput("100_[1-3]|PENDING|None\n"), SchedulerError);
}

TEST(DatasetStatusTest, ShardsFromTheirFoldersAndSlurmsStates) {
  const fs::path out = airis::testing::MakeTempFolder("status");
  CompleteShard(out / "shards/1", 40);
  InterruptedShard(out / "shards/2");
  // shard 3 never started
  const auto jobs = ParseSqueueOutput(
      "100_1|COMPLETED|None\n100_2|CANCELLED|None\n100_3|FAILED|NonZeroExitCode\n"
      "101|CANCELLED|DependencyNeverSatisfied\n");
  const DatasetStatus st = CalcDatasetStatus(Record(out), jobs);
  ASSERT_EQ(st.shards.size(), 3u);
  EXPECT_EQ(st.shards[0].state, ShardState::kDone);
  EXPECT_EQ(st.shards[0].frames, 40);
  EXPECT_EQ(st.shards[0].job, "100_1");
  EXPECT_EQ(st.shards[1].state, ShardState::kFailed);
  EXPECT_EQ(st.shards[1].frames, 3);
  EXPECT_EQ(st.shards[1].slurm_state, "CANCELLED");
  EXPECT_EQ(st.shards[1].log, (out / "slurm/logs/shard-100_2.out").string());
  EXPECT_EQ(st.shards[2].state, ShardState::kMissing);
  EXPECT_EQ(st.shard_frames, 43);
  EXPECT_EQ(st.merge.state, MergeState::kFailed);
  EXPECT_EQ(st.merge.slurm_reason, "DependencyNeverSatisfied");
  EXPECT_EQ(st.to_resubmit, (std::vector<int>{2, 3}));
  EXPECT_EQ(st.resubmit, "/opt/airis dataset /data/city.yaml --mission /data/survey.yaml --out " +
                             out.string() + " --seed 7 --slurm 3 --only-shards 2,3");

  const nlohmann::json j = DatasetStatusJson(st);
  EXPECT_EQ(j["shards"][1]["state"], "failed");
  EXPECT_EQ(j["shards"][1]["frames"], 3);
  EXPECT_EQ(j["shards"][1]["interrupted_by_signal"], 15);
  EXPECT_EQ(j["merge"]["state"], "failed");
  EXPECT_EQ(j["to_resubmit"], nlohmann::json::array({2, 3}));
}

TEST(DatasetStatusTest, RunningAndWaitingWhileTheArrayRuns) {
  const fs::path out = airis::testing::MakeTempFolder("status_running");
  InterruptedShard(out / "shards/1");  // a running shard has an incomplete manifest too
  const auto jobs = ParseSqueueOutput(
      "100_1|RUNNING|None\n100_2|PENDING|Priority\n100_3|PENDING|Priority\n"
      "101|PENDING|Dependency\n");
  const DatasetStatus st = CalcDatasetStatus(Record(out), jobs);
  EXPECT_EQ(st.shards[0].state, ShardState::kRunning);
  EXPECT_EQ(st.shards[1].state, ShardState::kPending);
  EXPECT_EQ(st.merge.state, MergeState::kWaiting);
  EXPECT_TRUE(st.to_resubmit.empty());
  EXPECT_TRUE(st.resubmit.empty());
}

TEST(DatasetStatusTest, WithoutSlurmTheFoldersAloneSayDoneIncompleteOrMissing) {
  const fs::path out = airis::testing::MakeTempFolder("status_offline");
  CompleteShard(out / "shards/1", 40);
  InterruptedShard(out / "shards/2");
  const DatasetStatus st = CalcDatasetStatus(Record(out), std::nullopt, "squeue: not found");
  EXPECT_FALSE(st.slurm_answered);
  EXPECT_EQ(st.slurm_error, "squeue: not found");
  EXPECT_EQ(st.shards[0].state, ShardState::kDone);
  EXPECT_EQ(st.shards[1].state, ShardState::kIncomplete);
  EXPECT_EQ(st.shards[2].state, ShardState::kMissing);
  EXPECT_EQ(st.merge.state, MergeState::kUnknown);
  EXPECT_TRUE(st.to_resubmit.empty());  // unknowable without Slurm: a task may still run
}

TEST(DatasetStatusTest, MergedWhenTheFolderHoldsTheCompleteDataset) {
  const fs::path out = airis::testing::MakeTempFolder("status_merged");
  for (int k = 1; k <= 3; ++k) CompleteShard(out / "shards" / std::to_string(k), 40);
  CompleteShard(out, 120);
  const DatasetStatus st = CalcDatasetStatus(Record(out), std::vector<SlurmJobState>{});
  EXPECT_EQ(st.merge.state, MergeState::kDone);
  EXPECT_EQ(st.merge.frames, 120);
  // Slurm forgot the jobs (MinJobAge): the folders still say done.
  EXPECT_EQ(st.shards[2].state, ShardState::kDone);
}

std::string ResubmitError(const SlurmRecord& r, const std::vector<int>& shards,
                          const std::string& squeue) {
  try {
    PlanResubmission(r, shards, ParseSqueueOutput(squeue));
  } catch (const engine::ConfigError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ResubmitTest, AFailedShardRunsAgainAndTheNewMergeWaitsForQueuedOnes) {
  const fs::path out = airis::testing::MakeTempFolder("resubmit");
  CompleteShard(out / "shards/1", 40);
  InterruptedShard(out / "shards/2");
  InterruptedShard(out / "shards/3");  // still running
  const ResubmitPlan p = PlanResubmission(
      Record(out), {2},
      ParseSqueueOutput("100_1|COMPLETED|None\n100_2|FAILED|NonZeroExitCode\n"
                        "100_3|RUNNING|None\n101|PENDING|DependencyNeverSatisfied\n"));
  EXPECT_EQ(p.shards, (std::vector<int>{2}));
  EXPECT_EQ(p.merge_after, (std::vector<std::string>{"100_3"}));
  EXPECT_EQ(p.cancel, (std::vector<std::string>{"101"}));  // it could never run
}

TEST(ResubmitTest, RefusesWhatWouldLeaveTheMergeWaitingForEver) {
  const fs::path out = airis::testing::MakeTempFolder("resubmit_refused");
  CompleteShard(out / "shards/1", 40);
  InterruptedShard(out / "shards/2");
  const SlurmRecord r = Record(out);
  const std::string ended = "100_1|COMPLETED|None\n100_2|FAILED|None\n100_3|FAILED|None\n";
  EXPECT_NE(ResubmitError(r, {4}, ended).find("--only-shards: shard 4 is out of range (1 to 3)"),
            std::string::npos);
  EXPECT_NE(ResubmitError(r, {2, 2}, ended).find("shard 2 is given twice"), std::string::npos);
  EXPECT_NE(ResubmitError(r, {1}, ended).find("shard 1 is complete (40 frames)"),
            std::string::npos);
  EXPECT_NE(ResubmitError(r, {2}, ended)
                .find("shard(s) 3 are neither complete nor queued, so the merge could never run: "
                      "resubmit them too (--only-shards 2,3)"),
            std::string::npos)
      << ResubmitError(r, {2}, ended);
  EXPECT_NE(ResubmitError(r, {2}, "100_2|RUNNING|None\n100_3|RUNNING|None\n")
                .find("shard 2 is still RUNNING as job 100_2: wait for it, or scancel 100_2"),
            std::string::npos);
  EXPECT_NE(ResubmitError(r, {2, 3}, ended + "101|RUNNING|None\n")
                .find("the merge job 101 is RUNNING: wait for it to end"),
            std::string::npos);
  CompleteShard(out, 120);
  EXPECT_NE(ResubmitError(r, {2, 3}, ended).find("is merged already (120 frames)"),
            std::string::npos);
}

TEST(SlurmRecordTest, RoundTripsThroughTheFile) {
  const fs::path out = airis::testing::MakeTempFolder("record");
  SlurmRecord r = Record(out);
  r.plan.name = "camp-survey-s7";
  r.plan.resources.partition = "gpu";
  r.plan.resources.sbatch_args = {"--qos=low"};
  r.submissions.push_back({"130", {2}, "131", {"100_3"}});
  Write(SlurmRecordPath(out.string()), SlurmRecordJson(r).dump());
  const SlurmRecord back = ReadSlurmRecord(out.string(), "status");
  EXPECT_EQ(SlurmRecordJson(back), SlurmRecordJson(r));
  EXPECT_EQ(RecordedJobs(back), (std::vector<std::string>{"100", "101", "130", "131"}));
  try {
    ReadSlurmRecord((out / "elsewhere").string(), "status");
    ADD_FAILURE() << "a folder without a record was read";
  } catch (const engine::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("holds no Slurm submission"), std::string::npos);
  }
}

}  // namespace
}  // namespace airis::tools
