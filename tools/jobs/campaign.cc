#include "tools/jobs/campaign.h"

#include <algorithm>
#include <filesystem>
#include <set>

#include "engine/core/config.h"
#include "engine/core/error.h"
#include "engine/dataset/file_io.h"
#include "tools/jobs/output_folder.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr const char* kCampaignFormat = "airis-slurm-campaign";
constexpr int kCampaignVersion = 1;

std::string Joined(const std::vector<std::string>& words, const char* sep) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : sep) + w;
  return out;
}

json RecordJson(const std::string& name, const std::string& file,
                const std::vector<CampaignDataset>& datasets) {
  json list = json::array();
  for (const CampaignDataset& d : datasets) {
    json entry = {{"entry", d.entry}, {"folder", d.folder}, {"set", d.overrides}};
    entry["seed"] = d.seed ? json(*d.seed) : json(nullptr);
    list.push_back(entry);
  }
  return {{"format", kCampaignFormat},
          {"format_version", kCampaignVersion},
          {"name", name},
          {"file", file},
          {"datasets", list}};
}

}  // namespace

std::vector<CampaignDataset> ExpandCampaign(const scenes::CampaignConfig& campaign,
                                            const CampaignSubmitOptions& options) {
  std::vector<CampaignDataset> out;
  for (const scenes::CampaignDatasetConfig& e : campaign.datasets) {
    std::vector<std::optional<std::uint64_t>> seeds;
    for (std::uint64_t s : e.CalcSeeds()) seeds.emplace_back(s);
    if (seeds.empty()) seeds.emplace_back(std::nullopt);  // the scene's own seed
    for (const scenes::CampaignVariant& variant : e.CalcVariants()) {
      for (const std::optional<std::uint64_t>& seed : seeds) {
        CampaignDataset d;
        d.entry = e.name;
        d.seed = seed;
        d.overrides = variant.overrides;
        const std::string entry = variant.folder.empty() ? e.name : e.name + "/" + variant.folder;
        d.folder = seed ? entry + "/seed-" + std::to_string(*seed) : entry;
        SlurmDatasetPlan& p = d.plan;
        p.dataset.airis = options.airis;
        p.dataset.scene = fs::absolute(e.scene).lexically_normal().string();
        p.dataset.mission = fs::absolute(e.mission).lexically_normal().string();
        DatasetOptionValues v;
        if (seed) v.seed = std::to_string(*seed);
        v.overrides = variant.overrides;
        v.cameras = Joined(e.cameras, ",");
        v.formats = Joined(e.formats, ",");
        v.streams = e.streams;
        v.stream_format = e.stream_format;
        v.min_object_area_px = std::to_string(e.min_object_area_px);
        p.dataset.options = DatasetOptionWords(v);
        p.out = (fs::path(options.out) / d.folder).string();
        p.shards = e.shards > 0 ? e.shards : options.default_shards;
        std::string variant_name = variant.folder;
        std::replace(variant_name.begin(), variant_name.end(), '/', '-');
        p.name = engine::SanitizeName(campaign.name + "-" + e.name +
                                      (variant_name.empty() ? "" : "-" + variant_name) +
                                      (seed ? "-s" + std::to_string(*seed) : ""));
        p.resources = options.resources;
        out.push_back(std::move(d));
      }
    }
  }
  return out;
}

void CheckCampaign(const std::vector<CampaignDataset>& datasets) {
  for (const CampaignDataset& d : datasets) ValidateSlurmPlan(d.plan);
  // Seeds do not change what loads; the overrides do.
  std::set<std::vector<std::string>> checked;
  for (const CampaignDataset& d : datasets) {
    std::vector<std::string> key = d.overrides;
    key.push_back(d.entry);
    if (checked.insert(key).second) CheckDatasetInputs(d.plan);
  }
}

std::string CampaignRecordPath(const std::string& out) {
  return (fs::path(out) / "campaign.json").string();
}

std::vector<SlurmSubmission> SubmitCampaign(const scenes::CampaignConfig& campaign,
                                            const std::string& campaign_file,
                                            const CampaignSubmitOptions& options) {
  const std::vector<CampaignDataset> datasets = ExpandCampaign(campaign, options);
  // Everything is checked before the first sbatch: a mistake in the last entry's scene should
  // not leave the first entries' jobs running.
  CheckCampaign(datasets);
  PrepareEmptyOutputFolder(options.out, "--out");
  const std::string file = fs::absolute(campaign_file).lexically_normal().string();
  std::vector<SlurmSubmission> submitted;
  std::vector<CampaignDataset> done;
  for (const CampaignDataset& d : datasets) {
    try {
      submitted.push_back(SubmitDatasetToSlurm(d.plan, {}, /*check_inputs=*/false));
    } catch (const SchedulerError& e) {
      throw SchedulerError(std::string(e.what()) + " (after " + std::to_string(done.size()) +
                           " of " + std::to_string(datasets.size()) +
                           " datasets were submitted; they are listed in " +
                           CampaignRecordPath(options.out) + ")");
    }
    done.push_back(d);
    engine::WriteFileAtomically(CampaignRecordPath(options.out),
                                RecordJson(campaign.name, file, done).dump(1) + "\n");
  }
  return submitted;
}

std::string DescribeCampaign(const std::vector<CampaignDataset>& datasets) {
  std::string text = "# " + std::to_string(datasets.size()) + " dataset(s):\n";
  for (const CampaignDataset& d : datasets) {
    text += "#   " + d.plan.out + "  shards " + std::to_string(d.plan.shards) + "  seed " +
            (d.seed ? std::to_string(*d.seed) : std::string("(the scene's)"));
    if (!d.overrides.empty()) text += " ";
    for (const std::string& o : d.overrides) text += " --set " + o;
    text += "\n";
  }
  for (const CampaignDataset& d : datasets) {
    text += "\n# ==== " + d.folder + "\n" + DescribeSlurmSubmission(d.plan, {});
  }
  return text;
}

CampaignStatus ReadCampaignStatus(const std::string& out) {
  const std::string path = CampaignRecordPath(out);
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    throw engine::ConfigError({}, "campaign status",
                              "'" + out + "' holds no campaign (" + path +
                                  " is missing; was it made with airis campaign submit?)");
  }
  const auto bytes = engine::ReadFileBytes(path);
  CampaignStatus st;
  st.out = out;
  std::vector<CampaignDatasetStatus> datasets;
  std::vector<SlurmRecord> records;
  try {
    const json j = json::parse(bytes.begin(), bytes.end());
    if (j.value("format", "") != kCampaignFormat ||
        j.value("format_version", 0) != kCampaignVersion) {
      throw engine::DatasetIoError(path + ": not an airis campaign record (format " +
                                   kCampaignFormat + " " + std::to_string(kCampaignVersion) + ")");
    }
    st.name = j.at("name").get<std::string>();
    for (const json& d : j.at("datasets")) {
      CampaignDatasetStatus s;
      s.entry = d.at("entry").get<std::string>();
      if (!d.at("seed").is_null()) s.seed = d.at("seed").get<std::uint64_t>();
      s.folder = d.at("folder").get<std::string>();
      datasets.push_back(std::move(s));
    }
  } catch (const json::exception& e) {
    throw engine::DatasetIoError(path + ": cannot be read (" + e.what() + ")");
  }
  std::vector<std::string> jobs;
  for (const CampaignDatasetStatus& d : datasets) {
    records.push_back(ReadSlurmRecord((fs::path(out) / d.folder).string(), "campaign status"));
    for (const std::string& id : RecordedJobs(records.back())) jobs.push_back(id);
  }
  // One squeue for the whole campaign, not one per dataset.
  std::optional<std::vector<SlurmJobState>> states;
  try {
    states = QuerySlurmJobs(jobs);
    st.slurm_answered = true;
  } catch (const SchedulerError& e) {
    st.slurm_error = e.what();
  }
  for (std::size_t i = 0; i < datasets.size(); ++i) {
    datasets[i].status = CalcDatasetStatus(records[i], states, st.slurm_error);
    if (datasets[i].status.merge.state == MergeState::kDone) ++st.merged;
  }
  st.datasets = std::move(datasets);
  return st;
}

json CampaignStatusJson(const CampaignStatus& st) {
  json datasets = json::array();
  for (const CampaignDatasetStatus& d : st.datasets) {
    json entry = {
        {"entry", d.entry}, {"folder", d.folder}, {"status", DatasetStatusJson(d.status)}};
    entry["seed"] = d.seed ? json(*d.seed) : json(nullptr);
    datasets.push_back(entry);
  }
  return {{"name", st.name},
          {"out", st.out},
          {"slurm", {{"answered", st.slurm_answered}, {"error", st.slurm_error}}},
          {"merged", st.merged},
          {"datasets", datasets}};
}

}  // namespace airis::tools
