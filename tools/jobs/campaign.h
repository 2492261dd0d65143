#pragma once

// `airis campaign submit|status`: the datasets of a campaign file (scenes/campaign_file.h), one
// per entry and seed, each submitted to Slurm as its own job array and merge job
// (docs/cluster.md, "Campaigns").

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "scenes/campaign_file.h"
#include "tools/jobs/dataset_status.h"
#include "tools/jobs/slurm_scripts.h"
#include "tools/jobs/slurm_submission.h"

namespace airis::tools {

/// What the command line adds to a campaign file.
struct CampaignSubmitOptions {
  std::string airis;  ///< the airis binary the nodes run, absolute
  std::string out;    ///< the campaign's folder, absolute: one dataset folder per entry and seed
  int default_shards = 1;  ///< array tasks of an entry without `shards`
  SlurmResources resources;
};

/// One dataset of a campaign.
struct CampaignDataset {
  std::string entry;                   ///< the entry's name
  std::optional<std::uint64_t> seed;   ///< its seed; none = the scene's own
  std::vector<std::string> overrides;  ///< its scene overrides (`set:`), "KEY=VALUE", sorted
  /// Relative to the campaign's folder: ENTRY[/VARIANT]/seed-S, or ENTRY[/VARIANT] without seeds
  /// (VARIANT: scenes::CampaignVariant::folder).
  std::string folder;
  SlurmDatasetPlan plan;  ///< what SubmitDatasetToSlurm submits
};

/// The datasets of `campaign`: per entry in file order, per combination of its `set:` values
/// (CalcVariants' order), per seed in its order. Pure: reads and writes nothing.
std::vector<CampaignDataset> ExpandCampaign(const scenes::CampaignConfig& campaign,
                                            const CampaignSubmitOptions& options);

/// Throws ConfigError unless every dataset's plan can be submitted (ValidateSlurmPlan) and each
/// entry's scene (with each combination of its overrides) and mission load (CheckDatasetInputs,
/// once per entry and combination, not per seed).
void CheckCampaign(const std::vector<CampaignDataset>& datasets);

/// DIR/campaign.json: the campaign's name, file and datasets (entry, seed, overrides, folder).
std::string CampaignRecordPath(const std::string& out);

/// Submits every dataset of `campaign` into `options.out` (empty or absent): CheckCampaign, then
/// SubmitDatasetToSlurm for each dataset, recording in
/// DIR/campaign.json what has been submitted after each one, so that a submission that stops
/// half-way (sbatch refuses: a site's job limit) leaves a record of the datasets it did submit.
/// Throws as SubmitDatasetToSlurm does; a SchedulerError then says how many were submitted.
std::vector<SlurmSubmission> SubmitCampaign(const scenes::CampaignConfig& campaign,
                                            const std::string& campaign_file,
                                            const CampaignSubmitOptions& options);

/// What --dry-run prints: a table of the datasets (folder, seed, shards) and, for each, its
/// scripts and sbatch command lines.
std::string DescribeCampaign(const std::vector<CampaignDataset>& datasets);

/// One dataset's line of `airis campaign status`.
struct CampaignDatasetStatus {
  std::string entry;
  std::optional<std::uint64_t> seed;
  std::string folder;    ///< relative to the campaign's folder
  DatasetStatus status;  ///< CalcDatasetStatus of its folder
};

/// The status of every dataset of a campaign.
struct CampaignStatus {
  std::string name;
  std::string out;
  bool slurm_answered = false;  ///< squeue answered (once, for every job of the campaign)
  std::string slurm_error;
  std::vector<CampaignDatasetStatus> datasets;
  int merged = 0;  ///< datasets whose merge is done
};

/// Reads DIR/campaign.json and each dataset's record and shard folders; asks squeue once. Throws
/// ConfigError when DIR holds no campaign, DatasetIoError for unreadable files.
CampaignStatus ReadCampaignStatus(const std::string& out);

/// As `airis campaign status --json` prints it.
nlohmann::json CampaignStatusJson(const CampaignStatus& status);

}  // namespace airis::tools
