#include "engine/dataset/stream_writer.h"

#include <gtest/gtest.h>

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "engine/dataset/csv_reader.h"
#include "tests/fixtures/temp_dir.h"

namespace airis::engine {
namespace {

namespace fs = std::filesystem;

// One column of every type, and rows whose values show what each type keeps.
std::vector<LogColumn> Columns() {
  return {{"reading_m_s2", LogType::kFloat32, {}, ""},
          {"latitude_deg", LogType::kFloat64, {}, ""},
          {"fix_type", LogType::kInt64, {}, ""},
          {"mode", LogType::kLabel, {"idle", "hover", "land"}, ""}};
}
const std::vector<std::vector<double>> kRows = {{0.1, 47.397742123456789, 3, 0},
                                                {-9.80665, -122.0840575, 0, 2}};
const std::vector<TimeNs> kTimes = {1'000'000, 123'456'789'012};

fs::path Write(const std::string& name, StreamFormat format) {
  const fs::path dir = airis::testing::TestTempDir() / ("stream_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  StreamWriter w(dir, "v.s", Columns(), format);
  for (std::size_t r = 0; r < kRows.size(); ++r) w.AddRow(kTimes[r], kRows[r]);
  EXPECT_EQ(w.rows(), 2);
  w.Close();
  return w.path();
}

// The shortest text that reads back as `value`, as Python's repr() prints a float.
std::string Shortest(double value) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  return std::string(buffer, end);
}

// Runs a command and returns what it printed on standard output.
std::string Output(const std::string& command) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  std::string out;
  char buffer[4096];
  while (pipe && std::fgets(buffer, sizeof buffer, pipe.get())) out += buffer;
  return out;
}

TEST(StreamWriterTest, CsvHasSecondsAndTypedText) {
  const fs::path path = Write("csv", StreamFormat::kCsv);
  EXPECT_EQ(path.filename(), "v.s.csv");
  const CsvText csv = ReadCsvText(path);
  EXPECT_EQ(csv.header, "time_ns,time_s,reading_m_s2,latitude_deg,fix_type,mode");
  ASSERT_EQ(csv.rows.size(), 2u);
  // float32 shortest, float64 shortest, a whole number, the label's text.
  EXPECT_EQ(csv.rows[0], "1000000,0.001,0.1,47.39774212345679,3,idle");
  EXPECT_EQ(csv.rows[1], "123456789012,123.456789012,-9.80665,-122.0840575,0,land");
}

// NumPy reads the .npy: field names, dtypes and every value as written, with no time_s (it is
// time_ns * 1e-9).
TEST(StreamWriterTest, NumPyReadsTheNpyAsTheSameTypedValues) {
  const fs::path path = Write("npy", StreamFormat::kNpy);
  EXPECT_EQ(path.filename(), "v.s.npy");
  const std::string out =
      Output(std::string(AIRIS_PYTHON) + " " + AIRIS_NPY_DUMP + " " + path.string() + " 2>&1");
  // The float32 columns hold the float nearest the value (Python prints it as a double).
  EXPECT_EQ(out,
            "time_ns:<i8,reading_m_s2:<f4,latitude_deg:<f8,fix_type:<i8,mode:|u1\n"
            "1000000," +
                Shortest(static_cast<float>(0.1)) +
                ",47.39774212345679,3,0\n"
                "123456789012," +
                Shortest(static_cast<float>(-9.80665)) + ",-122.0840575,0,2\n");
}

}  // namespace
}  // namespace airis::engine
