// `airis campaign submit CAMPAIGN.yaml --out DIR --slurm [--shards N] [resources] [--dry-run]`:
// submits one Slurm dataset (shard array + merge) per entry and seed of a campaign file;
// `airis campaign status DIR [--json]`: how far each got (docs/cluster.md, "Campaigns").
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "engine/core/error.h"
#include "scenes/campaign_file.h"
#include "tools/cli/cli_util.h"
#include "tools/cli/commands.h"
#include "tools/cli/slurm_cli.h"
#include "tools/jobs/campaign.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;

struct CampaignArgs {
  std::string file, out;
  bool slurm = false;
  int shards = 1;
  SlurmArgs slurm_args;
};

int Submit(const CampaignArgs& a) {
  const scenes::CampaignConfig campaign = scenes::LoadCampaignFile(a.file);
  CampaignSubmitOptions o;
  o.airis = CurrentExecutable();
  o.out = fs::absolute(a.out).lexically_normal().string();
  if (o.out.size() > 1 && o.out.back() == '/') o.out.pop_back();
  o.default_shards = a.shards;
  o.resources = a.slurm_args.ToResources();
  if (a.slurm_args.dry_run) {
    const std::vector<CampaignDataset> datasets = ExpandCampaign(campaign, o);
    CheckCampaign(datasets);
    std::printf("%s", DescribeCampaign(datasets).c_str());
    return 0;
  }
  const std::vector<SlurmSubmission> submitted = SubmitCampaign(campaign, a.file, o);
  const std::vector<CampaignDataset> datasets = ExpandCampaign(campaign, o);
  std::printf("campaign %s: %zu dataset(s) submitted into %s\n", campaign.name.c_str(),
              submitted.size(), o.out.c_str());
  for (std::size_t i = 0; i < submitted.size(); ++i) {
    std::printf("  %-32s array %s (shards %s), merge %s\n", datasets[i].folder.c_str(),
                submitted[i].array_job.c_str(), FormatArraySpec(submitted[i].shards).c_str(),
                submitted[i].merge_job.c_str());
  }
  std::printf("  status  airis campaign status %s\n", o.out.c_str());
  return 0;
}

// Checks the options; returns the work: read the campaign file and submit (or describe) it.
std::function<int()> CheckSubmit(const CampaignArgs& a) {
  if (!a.slurm) {
    throw engine::ConfigError({}, "--slurm",
                              "required: a campaign is submitted to Slurm (each dataset alone "
                              "runs here with airis dataset)");
  }
  if (a.shards < 1) {
    throw engine::ConfigError({}, "--shards",
                              "must be at least 1 (got " + std::to_string(a.shards) + ")");
  }
  return [a] { return Submit(a); };
}

int Status(const std::string& out, bool as_json) {
  const CampaignStatus st = ReadCampaignStatus(fs::absolute(out).lexically_normal().string());
  if (as_json) {
    std::printf("%s\n", CampaignStatusJson(st).dump(2).c_str());
    return 0;
  }
  std::printf("campaign %s in %s: %d of %zu dataset(s) merged\n", st.name.c_str(), st.out.c_str(),
              st.merged, st.datasets.size());
  if (!st.slurm_answered) {
    std::printf("  (Slurm did not answer, states are from the folders alone: %s)\n",
                st.slurm_error.c_str());
  }
  std::printf("  %-32s %-13s %-8s %8s  %s\n", "dataset", "merge", "shards", "frames",
              "failed or missing shards");
  for (const CampaignDatasetStatus& d : st.datasets) {
    int done = 0;
    for (const ShardStatus& s : d.status.shards) done += s.state == ShardState::kDone ? 1 : 0;
    std::string bad;
    for (int k : d.status.to_resubmit) bad += (bad.empty() ? "" : ",") + std::to_string(k);
    const std::string shards = std::to_string(done) + "/" + std::to_string(d.status.shard_count);
    std::printf("  %-32s %-13s %-8s %8lld  %s\n", d.folder.c_str(), Name(d.status.merge.state),
                shards.c_str(), static_cast<long long>(d.status.shard_frames),
                bad.empty() ? "-" : bad.c_str());
  }
  for (const CampaignDatasetStatus& d : st.datasets) {
    if (!d.status.resubmit.empty()) std::printf("  %s\n", d.status.resubmit.c_str());
  }
  return 0;
}

}  // namespace

void AddCampaignCommand(CLI::App& app, int& exit_code) {
  CLI::App* cmd = app.add_subcommand(
      "campaign", "many datasets (scenes x missions x seeds) from one YAML file, on Slurm");
  cmd->require_subcommand(1);
  auto a = std::make_shared<CampaignArgs>();
  CLI::App* submit = cmd->add_subcommand(
      "submit", "submit one shard array and merge job per entry and seed (docs/cluster.md)");
  submit->add_option("campaign", a->file, "campaign file (YAML)")->required()->type_name("PATH");
  submit->add_option("--out", a->out, "campaign folder: one dataset folder per entry and seed")
      ->required()
      ->type_name("DIR");
  submit->add_flag("--slurm", a->slurm, "submit to Slurm (required)");
  submit
      ->add_option("--shards", a->shards,
                   "array tasks per dataset for entries without 'shards' (default 1)")
      ->type_name("N");
  AddSlurmOptions(submit, a->slurm_args);
  SetCommandCallback(submit, exit_code, [a] { return CheckSubmit(*a); });

  auto dir = std::make_shared<std::string>();
  auto as_json = std::make_shared<bool>(false);
  CLI::App* status = cmd->add_subcommand("status", "how far each dataset of a campaign got");
  status->add_option("dir", *dir, "the --out folder of airis campaign submit")
      ->required()
      ->type_name("DIR");
  status->add_flag("--json", *as_json, "print JSON");
  SetCommandCallback(status, exit_code, [dir, as_json]() -> std::function<int()> {
    return [dir, as_json] { return Status(*dir, *as_json); };
  });
}

}  // namespace airis::tools
