#include "tools/cli/dataset_cli.h"

#include <sstream>

#include "engine/core/error.h"

namespace airis::tools {

void AddDatasetWriteOptions(CLI::App* cmd, DatasetWriteArgs& a) {
  cmd->add_option("--cameras", a.cameras, "record only these cameras (comma-separated)")
      ->type_name("NAME,...");
  cmd->add_option("--formats", a.formats,
                  "extra outputs: npy (float depth), normals, tartanair (the TartanAir layout "
                  "too); comma-separated")
      ->type_name("FORMAT,...");
  cmd->add_option("--encode-threads", a.encode_threads,
                  "image encoding threads, 1 to 64 (default 2)")
      ->type_name("N");
  cmd->add_option(
         "--stream-format", a.stream_format,
         "sensor, truth and command streams as npy (NumPy structured arrays, default) or csv")
      ->type_name("npy|csv");
  cmd->add_option("--min-object-area-px", a.min_object_area_px,
                  "instances with fewer visible pixels get no COCO annotation (default 16)")
      ->type_name("PIXELS");
}

std::vector<std::string> SplitList(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    if (!item.empty()) out.push_back(item);
  }
  return out;
}

engine::DatasetOutputs ParseFormats(const std::string& text) {
  engine::DatasetOutputs outputs;
  for (const std::string& f : SplitList(text)) {
    if (f == "npy") {
      outputs.depth_npy = true;
    } else if (f == "normals") {
      outputs.normals = true;
    } else if (f == "tartanair") {
      outputs.tartanair = true;
    } else {
      throw engine::ConfigError({}, "--formats",
                                "unknown format '" + f + "' (expected npy, normals or tartanair)");
    }
  }
  return outputs;
}

engine::StreamFormat ParseStreamFormat(const std::string& text) {
  if (text != "csv" && text != "npy") {
    throw engine::ConfigError({}, "--stream-format", "expected csv or npy (got '" + text + "')");
  }
  return text == "npy" ? engine::StreamFormat::kNpy : engine::StreamFormat::kCsv;
}

DatasetWriteOptions ParseDatasetWriteArgs(const DatasetWriteArgs& a, const std::string& out) {
  DatasetWriteOptions o;
  o.out = out;
  o.cameras = SplitList(a.cameras);
  o.outputs = ParseFormats(a.formats);
  o.workers = a.encode_threads;
  o.min_object_area_px = a.min_object_area_px;
  o.stream_format = ParseStreamFormat(a.stream_format);
  return o;
}

}  // namespace airis::tools
