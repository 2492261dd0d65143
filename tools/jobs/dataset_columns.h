#pragma once

#include <string>
#include <vector>

namespace airis::tools {

/// One file kind of a dataset or run folder, documented from the column lists the code writes.
struct ColumnTable {
  std::string title;     ///< e.g. "<vehicle>.imu" or "<camera>/poses.csv"
  std::string markdown;  ///< | column | type | meaning |, one row per column (x, y, z share one)
};

/// The column tables of every file a dataset holds (docs/dataset-format.md, "Columns"): the truth
/// and command streams, the stream of each non-image sensor kind (from the sensors' own column
/// lists, built with default configs), collisions.csv, mission_events.csv, the pose tables of
/// cameras and lidars and the fields of a lidar scan's PCD file. docs/dataset-format.md holds
/// them verbatim (a test checks it); `airis dataset schema` prints them.
std::vector<ColumnTable> DatasetColumnTables();

}  // namespace airis::tools
