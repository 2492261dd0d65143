#include "tools/jobs/dataset_merge.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <string_view>

#include "engine/core/error.h"
#include "engine/dataset/contact_sheet.h"
#include "engine/dataset/csv_reader.h"
#include "engine/dataset/file_io.h"
#include "engine/dataset/tartanair.h"
#include "tools/jobs/output_folder.h"
#include "tools/jobs/realtime_pacer.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;
using engine::DatasetIoError;
using nlohmann::json;

struct Shard {
  fs::path dir;
  json manifest;
  int index = 0;  // 1-based
};

json ReadJson(const fs::path& path) {
  const auto bytes = engine::ReadFileBytes(path);
  try {
    return json::parse(bytes.begin(), bytes.end());
  } catch (const json::exception& e) {
    throw DatasetIoError(path.string() + ": not valid JSON (" + e.what() + ")");
  }
}

// The manifest without what differs between the shards of one dataset: the shard entry, frame
// and scan counts, depth pixels clipped, the simulated time (the shards after the first stop
// after the mission's last capture) and the paths the scene and mission were given by (their
// content hashes must agree; shards made on machines with different checkouts merge).
json Common(json m) {
  m.erase("shard");
  m["counts"].erase("frames");
  m["counts"].erase("scans");
  m["counts"].erase("simulated_time_s");
  m["scene"].erase("file");
  if (m["mission"].is_object()) m["mission"].erase("file");  // null: PX4 flown from outside
  for (json& c : m["cameras"]) {
    c.erase("frames");
    if (c.contains("depth_png")) c["depth_png"].erase("clipped_pixels");
  }
  for (json& l : m["lidars"]) l.erase("scans");
  return m;
}

std::vector<Shard> ReadShards(const std::vector<fs::path>& dirs) {
  if (dirs.empty()) throw engine::ConfigError({}, {}, "no shard folders given");
  std::vector<Shard> shards;
  for (const fs::path& dir : dirs) {
    if (!fs::exists(dir / "manifest.json")) {
      throw engine::ConfigError(
          {}, {}, "'" + dir.string() + "' is not a dataset folder (no manifest.json)");
    }
    Shard s{dir, ReadJson(dir / "manifest.json")};
    if (s.manifest.value("format", "") != "airis-dataset") {
      throw engine::ConfigError({}, {},
                                dir.string() + "/manifest.json: not an airis dataset manifest");
    }
    if (!s.manifest.contains("shard")) {
      // One folder of a whole dataset is the one shard of one (what `--slurm 1` and a campaign's
      // one-task datasets merge); among others it is a mistake.
      if (dirs.size() != 1) {
        throw engine::ConfigError(
            {}, {}, "'" + dir.string() + "' is not a shard (it was made without --shard K/N)");
      }
      s.manifest["shard"] = {{"index", 1}, {"count", 1}};
    }
    s.index = s.manifest["shard"]["index"].get<int>();
    const int count = s.manifest["shard"]["count"].get<int>();
    if (!s.manifest.value("complete", false)) {
      throw engine::ConfigError({}, {},
                                "shard " + std::to_string(s.index) + "/" + std::to_string(count) +
                                    " in '" + dir.string() +
                                    "' is incomplete: finish it with --resume before merging");
    }
    shards.push_back(std::move(s));
  }
  std::sort(shards.begin(), shards.end(),
            [](const Shard& a, const Shard& b) { return a.index < b.index; });
  const int count = shards.front().manifest["shard"]["count"].get<int>();
  const json common = Common(shards.front().manifest);
  for (std::size_t i = 0; i < shards.size(); ++i) {
    const Shard& s = shards[i];
    if (s.manifest["shard"]["count"].get<int>() != count) {
      throw engine::ConfigError({}, {},
                                "'" + s.dir.string() + "' is a shard of " +
                                    s.manifest["shard"]["count"].dump() + ", '" +
                                    shards.front().dir.string() + "' of " + std::to_string(count));
    }
    if (i > 0 && s.index == shards[i - 1].index) {
      throw engine::ConfigError({}, {},
                                "shard " + std::to_string(s.index) + " given twice: '" +
                                    shards[i - 1].dir.string() + "' and '" + s.dir.string() + "'");
    }
    const json mine = Common(s.manifest);
    for (const auto& [key, value] : common.items()) {
      if (mine[key] != value) {
        throw engine::ConfigError(
            {}, {},
            "'" + s.dir.string() + "' is not a shard of the same dataset as '" +
                shards.front().dir.string() + "': its manifest differs in '" + key + "'");
      }
    }
  }
  if (static_cast<int>(shards.size()) != count) {
    std::string missing;
    std::set<int> have;
    for (const Shard& s : shards) have.insert(s.index);
    for (int k = 1; k <= count; ++k) {
      if (!have.count(k)) missing += (missing.empty() ? "" : ", ") + std::to_string(k);
    }
    throw engine::ConfigError({}, {},
                              "shard(s) " + missing + " of " + std::to_string(count) + " missing");
  }
  return shards;
}

// Puts the file `from` at `to`: a hard link where both are on one file system (the shards of a
// Slurm submission inside the merged folder: no second copy of every frame, and no frame I/O),
// otherwise a copy. Shard files are never changed in place (a resumed shard renames a new file
// over an old one), so the merged dataset cannot change under a link.
void CopyNew(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  fs::create_directories(to.parent_path(), ec);
  if (fs::exists(to))
    throw DatasetIoError(to.string() + " comes from two shards (" + from.string() + ")");
  fs::create_hard_link(from, to, ec);
  if (!ec) return;
  ec.clear();
  if (!fs::copy_file(from, to, ec))
    throw DatasetIoError("cannot copy " + from.string() + ": " + ec.message());
}

// Copies every file under shard/`sub` except those `keep_out` names, failing on a file two shards
// hold.
void CopyTree(const std::vector<Shard>& shards, const fs::path& sub, const fs::path& out,
              const std::set<std::string>& keep_out) {
  for (const Shard& s : shards) {
    if (!fs::is_directory(s.dir / sub)) continue;
    for (const auto& e : fs::recursive_directory_iterator(s.dir / sub)) {
      if (!e.is_regular_file() || keep_out.count(e.path().filename().string())) continue;
      CopyNew(e.path(), out / sub / fs::relative(e.path(), s.dir / sub));
    }
  }
}

// The first shard's file `rel` whose bytes differ from the first shard's (each file read once);
// empty when every shard holds the same.
fs::path FirstDifferent(const std::vector<Shard>& shards, const fs::path& rel) {
  const auto first = engine::ReadFileBytes(shards.front().dir / rel);
  for (std::size_t i = 1; i < shards.size(); ++i) {
    if (engine::ReadFileBytes(shards[i].dir / rel) != first) return shards[i].dir / rel;
  }
  return {};
}

// Rows of one CSV from every shard in time order (first column, integer ns). A row several shards
// hold (a stereo frame that each shard rendered for one eye; the events before the last capture,
// which every shard logged) is written as often as the one shard holding it most often has it: a
// row that one shard logged twice at one time stays twice. The headers must agree. A file every
// shard wrote alike is that file, linked.
void JoinCsv(const std::vector<Shard>& shards, const fs::path& rel, const fs::path& out) {
  if (FirstDifferent(shards, rel).empty()) {
    CopyNew(shards.front().dir / rel, out / rel);
    return;
  }
  std::vector<engine::CsvText> parts;
  for (const Shard& s : shards) {
    parts.push_back(engine::ReadCsvText(s.dir / rel));
    if (parts.back().header != parts.front().header) {
      throw DatasetIoError(parts.back().path.string() + ": header differs from " +
                           parts.front().path.string());
    }
  }
  struct Row {
    std::int64_t time_ns;
    std::size_t shard;
    const std::string* text;
  };
  std::vector<Row> rows;  // in shard order, stable within a shard
  for (std::size_t s = 0; s < parts.size(); ++s) {
    for (std::size_t r = 0; r < parts[s].rows.size(); ++r)
      rows.push_back({parts[s].Integer(r, 0), s, &parts[s].rows[r]});
  }
  std::stable_sort(rows.begin(), rows.end(),
                   [](const Row& a, const Row& b) { return a.time_ns < b.time_ns; });
  std::vector<std::string> joined;
  std::map<std::pair<std::size_t, std::string_view>, int> held;  // within one time: shard, row
  std::map<std::string_view, int> written;                       // within one time: row
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (i > 0 && rows[i].time_ns != rows[i - 1].time_ns) {
      held.clear();
      written.clear();
    }
    const std::string_view text = *rows[i].text;
    if (++held[{rows[i].shard, text}] > written[text]) {
      ++written[text];
      joined.push_back(*rows[i].text);
    }
  }
  engine::WriteFileAtomically(out / rel, engine::JoinCsvText(parts.front().header, joined));
}

// A camera's or lidar's poses.csv from every shard, in the order of its `index_column` (frame,
// scan); returns those indices.
std::vector<std::int64_t> JoinPoses(const std::vector<Shard>& shards, const fs::path& rel,
                                    const fs::path& out, const std::string& index_column) {
  std::vector<engine::CsvText> parts;
  std::vector<std::pair<std::int64_t, const std::string*>> rows;
  parts.reserve(shards.size());
  for (const Shard& s : shards) parts.push_back(engine::ReadCsvText(s.dir / rel));
  for (const auto& p : parts) {
    if (p.header != parts.front().header)
      throw DatasetIoError(p.path.string() + ": header differs");
    const std::size_t frame = p.Column(index_column);
    for (std::size_t r = 0; r < p.rows.size(); ++r)
      rows.emplace_back(p.Integer(r, frame), &p.rows[r]);
  }
  std::sort(rows.begin(), rows.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> joined;
  std::vector<std::int64_t> frames;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (i > 0 && rows[i].first == rows[i - 1].first) {
      throw DatasetIoError(rel.string() + ": " + index_column + " " +
                           std::to_string(rows[i].first) + " is in two shards");
    }
    joined.push_back(*rows[i].second);
    frames.push_back(rows[i].first);
  }
  engine::WriteFileAtomically(out / rel, engine::JoinCsvText(parts.front().header, joined));
  return frames;
}

// checksums.csv from every shard's: the union of their frame files, sorted by path.
void JoinChecksums(const std::vector<Shard>& shards, const fs::path& out) {
  std::map<std::string, std::string> rows;  // path -> whole line
  for (const Shard& s : shards) {
    const auto bytes = engine::ReadFileBytes(s.dir / "checksums.csv");
    const std::string text(bytes.begin(), bytes.end());
    std::size_t start = text.find('\n') + 1;  // after the header
    while (start < text.size()) {
      const std::size_t end = text.find('\n', start);
      const std::string line = text.substr(start, end - start);
      const std::string path = line.substr(0, line.find(','));
      if (!rows.emplace(path, line).second) {
        throw DatasetIoError(path + " comes from two shards (" + s.dir.string() + ")");
      }
      start = end == std::string::npos ? text.size() : end + 1;
    }
  }
  std::string text = "path,bytes,sha256\n";
  for (const auto& [path, line] : rows) text += line + "\n";
  engine::WriteFileAtomically(out / "checksums.csv", text);
}

// One COCO file from the shards': images by id, annotations in frame order numbered from 1 again.
void JoinCoco(const std::vector<Shard>& shards, const fs::path& rel, const fs::path& out) {
  json merged;
  std::vector<json> images;
  std::vector<std::pair<std::int64_t, json>> annotations;
  for (const Shard& s : shards) {
    json coco = ReadJson(s.dir / rel);
    for (json& im : coco["images"]) images.push_back(std::move(im));
    for (json& a : coco["annotations"])
      annotations.emplace_back(a["image_id"].get<std::int64_t>(), std::move(a));
    if (merged.is_null()) {
      merged["info"] = coco["info"];
      merged["categories"] = coco["categories"];
    }
  }
  std::sort(images.begin(), images.end(), [](const json& a, const json& b) {
    return a["id"].get<std::int64_t>() < b["id"].get<std::int64_t>();
  });
  std::stable_sort(annotations.begin(), annotations.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  merged["images"] = images;
  json& anns = merged["annotations"] = json::array();
  std::int64_t id = 1;
  for (auto& [image, a] : annotations) {
    a["id"] = id++;
    anns.push_back(std::move(a));
  }
  engine::WriteFileAtomically(out / rel, merged.dump(1));
}

// The preview palette of labels.json (its colours are the palette's, for the classes it lists).
engine::SegmentationPalette ReadPalette(const fs::path& labels) {
  engine::SegmentationPalette palette = engine::CalcSegmentationPalette({});
  const json doc = ReadJson(labels);  // held: a range-for over a temporary's member would dangle
  for (const json& c : doc["classes"]) {
    auto& rgb = palette[c["id"].get<std::uint8_t>()];
    for (std::size_t i = 0; i < 3; ++i) rgb[i] = c["color"][i].get<std::uint8_t>();
  }
  return palette;
}

bool Has(const json& camera, const char* output) {
  const json& outputs = camera["outputs"];
  return std::find(outputs.begin(), outputs.end(), output) != outputs.end();
}

}  // namespace

MergeSummary MergeDatasetShards(const std::vector<fs::path>& dirs, const fs::path& out) {
  const auto wall_start = std::chrono::steady_clock::now();
  const std::vector<Shard> shards = ReadShards(dirs);
  // A merge that stopped half-way (a full disk) is marked in its manifest: running it again
  // starts that folder afresh. Any other non-empty folder is refused; nothing is overwritten.
  std::error_code ec;
  if (fs::is_regular_file(out / "manifest.json", ec) &&
      ReadJson(out / "manifest.json").value("merge_in_progress", false)) {
    for (const auto& e : fs::directory_iterator(out)) {
      const std::string name = e.path().filename().string();
      if (std::find(kSubmissionFolders.begin(), kSubmissionFolders.end(), name) ==
          kSubmissionFolders.end())
        fs::remove_all(e.path());
    }
  }
  // The folder of a Slurm submission holds its shards and scripts: the merged dataset goes beside
  // them (docs/cluster.md).
  PrepareEmptyOutputFolder(out.string(), "--out", kSubmissionFolders);
  engine::WriteFileAtomically(
      out / "manifest.json",
      json({{"format", "airis-dataset"}, {"complete", false}, {"merge_in_progress", true}})
          .dump(1));
  const json& first = shards.front().manifest;
  json manifest = first;
  manifest.erase("shard");
  MergeSummary summary;
  summary.shards = static_cast<int>(shards.size());

  CopyNew(shards.front().dir / "labels.json", out / "labels.json");
  for (const auto& e : fs::directory_iterator(shards.front().dir)) {
    if (e.is_regular_file() && e.path().extension() == ".csv" &&
        e.path().filename() != "checksums.csv")
      JoinCsv(shards, e.path().filename(), out);
  }
  JoinChecksums(shards, out);
  // Binary streams: every shard flew the same flight and logged the same samples, checked; the
  // first shard's file is linked (or copied) into place.
  for (const auto& e : fs::directory_iterator(shards.front().dir)) {
    if (!e.is_regular_file() || e.path().extension() != ".npy") continue;
    if (const fs::path other = FirstDifferent(shards, e.path().filename()); !other.empty()) {
      throw DatasetIoError(other.string() + " differs from " + e.path().string() +
                           ": the shards did not log the same flight");
    }
    CopyNew(e.path(), out / e.path().filename());
  }
  CopyTree(shards, "tartanair", out, {"pose_left.txt", "pose_right.txt"});
  bool preview = false;
  for (std::size_t c = 0; c < first["cameras"].size(); ++c) {
    const json& camera = first["cameras"][c];
    const std::string name = camera["name"].get<std::string>();
    CopyTree(shards, name, out, {"poses.csv", "coco_instances.json"});
    const std::vector<std::int64_t> frames =
        JoinPoses(shards, fs::path(name) / "poses.csv", out, "frame");
    if (fs::exists(shards.front().dir / name / "coco_instances.json")) {
      JoinCoco(shards, fs::path(name) / "coco_instances.json", out);
    }
    if (camera.contains("tartanair")) {
      const engine::TartanAirSlot slot{camera["tartanair"]["trajectory"].get<std::string>(),
                                       camera["tartanair"]["side"].get<std::string>()};
      engine::WriteTartanAirPoses(out / name / "poses.csv", engine::TartanAirPosePath(out, slot));
    }
    manifest["cameras"][c]["frames"] = static_cast<std::int64_t>(frames.size());
    if (camera.contains("depth_png")) {
      std::int64_t clipped = 0;
      for (const Shard& s : shards) {
        clipped += s.manifest["cameras"][c]["depth_png"]["clipped_pixels"].get<std::int64_t>();
      }
      manifest["cameras"][c]["depth_png"]["clipped_pixels"] = clipped;
    }
    summary.frames += static_cast<std::int64_t>(frames.size());
    if (!preview && !frames.empty() && Has(camera, "rgb") && Has(camera, "depth_png") &&
        Has(camera, "segmentation")) {
      engine::WriteContactSheet(out / name, frames, camera["near_m"].get<float>(),
                                camera["depth_png"]["unit_m"].get<double>(),
                                ReadPalette(out / "labels.json"), out / "preview.png");
      preview = true;
    }
  }
  // Lidars: scan files copied, poses joined in scan order.
  std::int64_t scans = 0;
  for (std::size_t l = 0; l < first.value("lidars", json::array()).size(); ++l) {
    const std::string name = first["lidars"][l]["name"].get<std::string>();
    CopyTree(shards, name, out, {"poses.csv"});
    const auto indices = JoinPoses(shards, fs::path(name) / "poses.csv", out, "scan");
    manifest["lidars"][l]["scans"] = static_cast<std::int64_t>(indices.size());
    scans += static_cast<std::int64_t>(indices.size());
  }
  if (manifest["counts"].contains("scans")) manifest["counts"]["scans"] = scans;
  summary.scans = scans;
  manifest["counts"]["frames"] = summary.frames;
  engine::WriteFileAtomically(out / "manifest.json", manifest.dump(1));
  summary.wall_s = WallSecondsSince(wall_start);
  return summary;
}

}  // namespace airis::tools
