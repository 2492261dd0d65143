#include "tools/jobs/dataset_columns.h"

#include "engine/dataset/pcd_file.h"
#include "engine/dataset/telemetry_recorder.h"
#include "scenes/sensor_kinds.h"
#include "tools/jobs/dataset_recorder.h"
#include "tools/jobs/scan_recorder.h"

namespace airis::tools {
namespace {

const char* TypeName(engine::LogType type) {
  switch (type) {
    case engine::LogType::kFloat32:
      return "float32";
    case engine::LogType::kFloat64:
      return "float64";
    case engine::LogType::kInt64:
      return "int64";
    case engine::LogType::kLabel:
      return "label";
  }
  return "?";
}

struct Row {
  std::string name, type, doc;
};

// A table of `rows`: a row without a doc joins the one before it.
std::string Markdown(const std::vector<Row>& rows) {
  std::string out = "| column | type | meaning |\n|---|---|---|\n";
  std::string names, type, doc;
  const auto flush = [&] {
    if (!names.empty()) out += "| " + names + " | " + type + " | " + doc + " |\n";
  };
  for (const Row& r : rows) {
    if (r.doc.empty() && !names.empty()) {
      names += ", `" + r.name + "`";
      continue;
    }
    flush();
    names = "`" + r.name + "`";
    type = r.type;
    doc = r.doc;
  }
  flush();
  return out;
}

std::string Markdown(const std::vector<engine::LogColumn>& columns) {
  std::vector<Row> rows;
  for (const engine::LogColumn& c : columns) rows.push_back({c.name, TypeName(c.type), c.doc});
  return Markdown(rows);
}

// A PCD field's type as the file's header gives it: F (float) or U (unsigned), and its bytes.
std::string PcdMarkdown() {
  std::vector<Row> rows;
  for (const engine::PcdField& f : engine::ScanPcdFields()) {
    rows.push_back({f.name, std::string(1, f.type) + std::to_string(f.size), f.doc});
  }
  return Markdown(rows);
}

}  // namespace

std::vector<ColumnTable> DatasetColumnTables() {
  std::vector<ColumnTable> out;
  out.push_back({"<vehicle>.truth", Markdown(engine::TelemetryRecorder::TruthColumns())});
  out.push_back({"<vehicle>.commands", Markdown(engine::TelemetryRecorder::CommandColumns(1))});
  for (const scenes::SensorKind& kind : scenes::SensorKinds()) {
    const auto spec = kind.make_default();
    if (!spec->ImageStreamNames(std::string(kind.name)).empty()) continue;  // cameras: images
    scenes::SensorBuildContext context{engine::RandomStream(0), nullptr};
    const std::unique_ptr<engine::Sensor> sensor = spec->Build(std::string(kind.name), context);
    std::vector<engine::LogColumn> columns;
    for (std::size_t c = 0; c < sensor->columns().size(); ++c) {
      columns.push_back(
          {sensor->columns()[c], sensor->column_type(c), {}, std::string(sensor->column_doc(c))});
    }
    out.push_back({"<vehicle>." + std::string(kind.name), Markdown(columns)});
  }
  out.push_back({"collisions.csv", Markdown(engine::TelemetryRecorder::CollisionColumns())});
  out.push_back({"mission_events.csv", Markdown(engine::TelemetryRecorder::MissionEventColumns())});
  out.push_back({"<camera>/poses.csv", Markdown(DatasetRecorder::PoseColumns())});
  out.push_back({"<vehicle>.<lidar>/poses.csv", Markdown(ScanRecorder::PoseColumns())});
  out.push_back({"<vehicle>.<lidar>/NNNNNN.pcd", PcdMarkdown()});
  return out;
}

}  // namespace airis::tools
