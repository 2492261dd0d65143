#pragma once

// The options that say how a dataset is written, shared by `airis dataset` and `airis px4
// --dataset` (docs/dataset-format.md): --cameras, --formats, --encode-threads, --stream-format,
// --min-object-area-px.

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/dataset/dataset_writer.h"
#include "tools/jobs/dataset_session.h"

namespace airis::tools {

/// The dataset options as given on the command line.
struct DatasetWriteArgs {
  std::string cameras;  ///< a,b
  std::string formats;  ///< npy,normals,tartanair
  int encode_threads = 2;
  std::int64_t min_object_area_px = 16;
  std::string stream_format = "npy";
};

/// Adds --cameras, --formats, --encode-threads, --stream-format and --min-object-area-px to `cmd`.
void AddDatasetWriteOptions(CLI::App* cmd, DatasetWriteArgs& args);

/// "a,b" as {"a", "b"} (empty items dropped).
std::vector<std::string> SplitList(const std::string& text);

/// --formats: the extra outputs. Throws ConfigError("--formats") for an unknown one.
engine::DatasetOutputs ParseFormats(const std::string& text);

/// --stream-format. Throws ConfigError("--stream-format") unless csv or npy.
engine::StreamFormat ParseStreamFormat(const std::string& text);

/// The options of `args` for a dataset written into `out`. Throws ConfigError naming the option.
DatasetWriteOptions ParseDatasetWriteArgs(const DatasetWriteArgs& args, const std::string& out);

}  // namespace airis::tools
