// Every `airis` command line that README.md and docs/*.md show, parsed with --check-args
// (docs/cli.md) by RunAirisCommandLine, all that the binary's main() calls: the commands, options
// and values a reader copies must be accepted. Lines of ```sh blocks must be complete; an inline
// `airis ...` may leave out what a command requires (it names one option in a sentence) but nothing
// it names may be refused. Synopses are read as a reader would: [optional] parts included, the
// first of a|b alternatives, `...` dropped, and each CAPITALISED placeholder given a sample value
// of its option's type.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "tools/cli/airis_app.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;

struct Shown {
  std::string where;  // file:line
  std::string line;   // the command line after the program's name
  bool complete;      // from a ```sh block
};

std::string Read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// "build/airis", "/opt/airis/build/airis", "airis": the program a shell runs.
bool IsAiris(const std::string& word) { return word == "airis" || word.ends_with("/airis"); }

// The words after the program of a shell line that runs airis ("time", "exec" and comments
// skipped); empty when it runs something else.
std::string AirisArguments(std::string line) {
  line = std::regex_replace(line, std::regex(R"(\s+#\s.*$)"), "");
  // What a pipe or a redirection does with the output is the shell's.
  line = std::regex_replace(line, std::regex(R"(\s+(\||>|>>|2>|&&|;)\s.*$)"), "");
  std::istringstream in(line);
  std::string word;
  while (in >> word) {
    if (word == "time" || word == "exec") continue;
    if (!IsAiris(word)) return "";
    std::string rest;
    std::getline(in, rest);
    return rest;
  }
  return "";
}

std::vector<Shown> CommandLinesOf(const fs::path& file) {
  std::vector<Shown> shown;
  std::istringstream in(Read(file));
  std::string line, joined;
  bool in_sh = false;
  int number = 0, first = 0;
  const std::string name = fs::path(file).filename().string();
  while (std::getline(in, line)) {
    ++number;
    const std::string trimmed = line.substr(std::min(line.find_first_not_of(' '), line.size()));
    if (trimmed.starts_with("```")) {
      in_sh = !in_sh && trimmed == "```sh";
      continue;
    }
    if (in_sh) {
      if (joined.empty()) first = number;
      joined += line;
      if (!joined.empty() && joined.back() == '\\') {
        joined.pop_back();
        continue;
      }
      const std::string args = AirisArguments(joined);
      if (!args.empty()) shown.push_back({name + ":" + std::to_string(first), args, true});
      joined.clear();
      continue;
    }
    static const std::regex kInline(R"(`((?:[\w./-]*/)?airis) ([^`]+)`)");
    for (auto it = std::sregex_iterator(line.begin(), line.end(), kInline);
         it != std::sregex_iterator(); ++it) {
      shown.push_back({name + ":" + std::to_string(number), (*it)[2].str(), false});
    }
  }
  return shown;
}

// A sample value for a placeholder after `option` (or a positional when empty).
std::string SampleFor(const std::string& option) {
  static const std::map<std::string, std::string> kSamples = {
      {"--seed", "7"},
      {"--until-s", "5"},
      {"--truth-rate-hz", "50"},
      {"--threads", "2"},
      {"--encode-threads", "2"},
      {"--shard", "1/2"},
      {"--slurm", "2"},
      {"--shards", "2"},
      {"--only-shards", "2"},
      {"--cpus-per-task", "2"},
      {"--count", "10"},
      {"--resting", "2"},
      {"--id", "22001"},
      {"--min-object-area-px", "16"},
      {"--latitude-deg", "47.6"},
      {"--longitude-deg", "-122.1"},
      {"--altitude-m", "120"},
      {"--pixel-m", "20"},
      {"--date-decimal-year", "2026.5"},
      {"--realtime", "1"},
      {"--pose", "0,0,-20,0,-30"},
      {"--set", "scene.lighting.fog_distance_m=300"},
      {"--cameras", "front"},
      {"--formats", "npy"},
      {"--time", "02:00:00"},
      {"--mem", "4G"},
      {"--sbatch-arg", "--account=lab"},
  };
  const auto it = kSamples.find(option);
  return it != kSamples.end() ? it->second : "x";  // a path or a name: not read by --check-args
}

// SCENE, DIR, N, K/N, SCENE.yaml, KEY=VALUE, SHARD_DIR, K,
bool IsPlaceholder(const std::string& word) {
  return std::regex_match(word, std::regex(R"([A-Z][A-Z0-9_]*([./,=-][A-Za-z0-9_]*)*)"));
}

// The synopsis as one runnable line: optional parts in, first alternatives, placeholders filled.
std::vector<std::string> Runnable(std::string line) {
  line = std::regex_replace(line, std::regex(R"(\\\|)"), "|");
  // Quoted words are one argument, left as written: set aside while the synopsis is read.
  std::vector<std::string> quoted;
  const std::regex quote(R"re('([^']*)'|"([^"]*)")re");
  for (std::smatch m; std::regex_search(line, m, quote);) {
    quoted.push_back(m[1].matched ? m[1].str() : m[2].str());
    line =
        m.prefix().str() + "\x01" + std::to_string(quoted.size() - 1) + "\x01" + m.suffix().str();
  }
  // Innermost [groups] first: " | " inside keeps its first alternative.
  const std::regex group(R"(\[([^\[\]]*)\])");
  for (std::smatch m; std::regex_search(line, m, group);) {
    std::string inside = m[1].str();
    const std::size_t bar = inside.find(" | ");
    if (bar != std::string::npos) inside = inside.substr(0, bar);
    line = m.prefix().str() + inside + m.suffix().str();
  }
  std::vector<std::string> words;
  std::istringstream in(line);
  for (std::string word; in >> word;) {
    if (word == "..." || word == "|") continue;
    if (word.ends_with("...")) word.resize(word.size() - 3);
    const bool was_quoted = word.front() == '\x01';
    if (was_quoted) word = quoted[std::stoul(word.substr(1))];
    if (word.find('$') != std::string::npos) {  // a shell variable of a job script
      const bool value = !words.empty() && words.back().rfind("--", 0) == 0;
      if (value) words.push_back(SampleFor(words.back()));
      continue;
    }
    if (was_quoted) {
      words.push_back(word);
      continue;
    }
    if (word.find('|') != std::string::npos && word.rfind("--", 0) != 0) {
      word = word.substr(0, word.find('|'));
    }
    const std::size_t eq = word.find('=');
    if (word.rfind("--", 0) == 0 && eq != std::string::npos && IsPlaceholder(word.substr(eq + 1))) {
      word = word.substr(0, eq + 1) + SampleFor(word.substr(0, eq));
    } else if (IsPlaceholder(word)) {
      word = SampleFor(!words.empty() && words.back().rfind("--", 0) == 0 ? words.back() : "");
    }
    if (!word.empty()) words.push_back(word);
  }
  return words;
}

TEST(DocsCommandLinesTest, EveryCommandLineShownIsAccepted) {
  std::vector<fs::path> files = {fs::path(AIRIS_SOURCE_DIR) / "README.md"};
  for (const auto& e : fs::directory_iterator(fs::path(AIRIS_SOURCE_DIR) / "docs")) {
    if (e.path().extension() == ".md") files.push_back(e.path());
  }
  std::size_t complete = 0, inline_lines = 0;
  for (const fs::path& file : files) {
    for (const Shown& s : CommandLinesOf(file)) {
      std::vector<std::string> args = Runnable(s.line);
      args.insert(args.begin(), "--check-args");
      std::string as_run;
      for (const std::string& a : args) as_run += " " + a;
      ::testing::internal::CaptureStdout();
      ::testing::internal::CaptureStderr();
      const int exit_code = RunAirisCommandLine(args);
      ::testing::internal::GetCapturedStdout();
      const std::string err = ::testing::internal::GetCapturedStderr();
      (s.complete ? complete : inline_lines)++;
      const bool partial_ok =
          !s.complete && exit_code == 2 && err.find("required") != std::string::npos;
      EXPECT_TRUE(exit_code == 0 || partial_ok)
          << s.where << ": airis " << s.line << "\n  run as: airis" << as_run << "\n  " << err;
    }
  }
  // The pages show dozens of each; a parser that found none would prove nothing.
  EXPECT_GE(complete, 10u);
  EXPECT_GE(inline_lines, 50u);
}

}  // namespace
}  // namespace airis::tools
