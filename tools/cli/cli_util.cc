#include "tools/cli/cli_util.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "engine/core/clock.h"
#include "engine/core/error.h"
#include "engine/dataset/file_io.h"
#include "engine/mavlink/link/link.h"
#include "tools/jobs/slurm_client.h"

namespace airis::tools {

int RunReportingErrors(const std::function<int()>& body) {
  try {
    return body();
  } catch (const engine::ConfigError& e) {
    // One line per mistake found (a file's independent mistakes are reported together).
    for (const engine::ConfigError& one : e.errors())
      std::fprintf(stderr, "error: %s\n", one.what());
    if (e.truncated()) {
      std::fprintf(stderr, "note: stopped after %zu errors; fix these and run again\n",
                   e.errors().size());
    }
    return 2;
  } catch (const engine::InvalidField& e) {
    // A value a model refused before it was given a place in a file (a duration, a rate).
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  } catch (const engine::SimulationError& e) {
    std::fprintf(stderr, "simulation stopped: %s\n", e.what());
    return 3;
  } catch (const engine::DatasetIoError& e) {
    // A full disk, an unwritable folder, a damaged dataset: the files and the system's reason.
    std::fprintf(stderr, "error: %s\n", e.what());
    return 4;
  } catch (const engine::mavlink::LinkError& e) {
    // PX4 did not connect, closed its link or stopped answering; a port or device is unusable.
    std::fprintf(stderr, "autopilot link: %s\n", e.what());
    return 5;
  } catch (const SchedulerError& e) {
    // sbatch, squeue or scancel failed: the command line and Slurm's own words.
    std::fprintf(stderr, "error: %s\n", e.what());
    return 6;
  } catch (const std::out_of_range& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    // Everything else users meet (a full disk, no EGL display) carries its own clear message.
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}

void RefuseEmptyValues(const CLI::App& command) {
  for (const CLI::Option* option : command.get_options()) {
    if (option->count() == 0 || option->get_expected_min() == 0) continue;
    for (const std::string& value : option->results()) {
      if (!value.empty()) continue;
      const std::string name = option->get_name(false, true);
      throw engine::ConfigError({}, name.empty() ? option->get_name() : name,
                                "needs a value (got '')");
    }
  }
}

namespace {

// --check-args on `cmd` or a command above it.
bool CheckArgsOnly(const CLI::App* cmd) {
  for (const CLI::App* at = cmd; at != nullptr; at = at->get_parent()) {
    const CLI::Option* flag = at->get_option_no_throw("--check-args");
    if (flag != nullptr && flag->count() > 0) return true;
  }
  return false;
}

}  // namespace

void SetCommandCallback(CLI::App* cmd, int& exit_code,
                        std::function<std::function<int()>()> prepare) {
  cmd->callback([cmd, &exit_code, prepare = std::move(prepare)] {
    // A subcommand chosen (`dataset merge`) ran its own callback, which this one follows.
    if (!cmd->get_subcommands().empty()) return;
    exit_code = RunReportingErrors([&] {
      RefuseEmptyValues(*cmd);
      const std::function<int()> work = prepare();
      if (!CheckArgsOnly(cmd)) return work();
      std::printf("ok: the command line is valid\n");
      return 0;
    });
  });
}

std::string OptionForKey(const std::string& key) {
  std::string option = "--" + key;
  for (char& c : option) {
    if (c == '_') c = '-';
  }
  return option;
}

void AddSceneOverrideOption(CLI::App* cmd, std::vector<std::string>& texts) {
  cmd->add_option("--set", texts,
                  "replace a key of the scene, e.g. --set scene.lighting.sun_elevation_deg=20 "
                  "(repeatable; docs/scene-format.md, \"Overrides\")")
      ->allow_extra_args(false)
      ->type_name("KEY.PATH=YAML");
}

void AddRealtimeOption(CLI::App* cmd, std::string& text) {
  cmd->add_option("--realtime", text,
                  "pace to wall time at this factor (default as fast as possible; 1 when given "
                  "without a value; for a ground station or a person)")
      ->expected(0, 1)
      ->type_name("[FACTOR]");
}

void AddUntilOption(CLI::App* cmd, std::string& text) {
  cmd->add_option("--until-s", text, "stop after this many simulated seconds")
      ->type_name("SECONDS");
}

void AddTruthRateOption(CLI::App* cmd, std::string& text) {
  cmd->add_option("--truth-rate-hz", text,
                  "ground-truth log rate, up to the scene's physics rate (default 100)")
      ->type_name("HZ");
}

void AddThreadsOption(CLI::App* cmd, std::string& text) {
  cmd->add_option("--threads", text,
                  "threads that step the vehicles, 1 to 64 (default 1; the results do not depend "
                  "on it)")
      ->type_name("N");
}

void PrintToStderr(const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); }

std::string CurrentExecutable() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) {
    throw std::runtime_error("cannot find the airis binary (/proc/self/exe: " + ec.message() + ")");
  }
  return self.string();
}

double ParseFiniteNumber(const std::string& name, const std::string& text) {
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(value)) {
    throw engine::ConfigError({}, "--" + name, "must be a finite number (got '" + text + "')");
  }
  return value;
}

std::uint64_t ParseSeed(const std::string& name, const std::string& text) {
  std::uint64_t value = 0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || r.ec != std::errc() || r.ptr != text.data() + text.size()) {
    throw engine::ConfigError({}, "--" + name,
                              "must be a whole number from 0 to 2^64 - 1 (got '" + text + "')");
  }
  return value;
}

int ParseWholeNumber(const std::string& name, const std::string& text, int lo, int hi) {
  int value = 0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || r.ec != std::errc() || r.ptr != text.data() + text.size() || value < lo ||
      value > hi) {
    throw engine::ConfigError({}, "--" + name,
                              "must be a whole number from " + std::to_string(lo) + " to " +
                                  std::to_string(hi) + " (got '" + text + "')");
  }
  return value;
}

engine::TimeNs ParseSeconds(const std::string& name, const std::string& text) {
  try {
    return engine::SecondsToNs(ParseFiniteNumber(name, text));
  } catch (const engine::InvalidField& e) {
    throw engine::ConfigError({}, "--" + name, e.problem());
  }
}

int ParseThreads(const std::string& text) { return ParseWholeNumber("threads", text, 1, 64); }

}  // namespace airis::tools
