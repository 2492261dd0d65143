#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "engine/core/clock.h"

namespace airis::tools {

/// Runs a command body and turns the errors users can cause into one clear line on stderr and an
/// exit code (README, "Exit codes"): 2 for bad input (ConfigError, InvalidField, std::out_of_range
/// and std::invalid_argument from models), 3 when the simulation diverged (SimulationError), 4 for
/// a file that cannot be written or read (DatasetIoError: a full disk, an unwritable folder), 5
/// when an autopilot link failed (LinkError), 6 when a Slurm command failed (SchedulerError), 1 for
/// any other std::exception (no EGL display), with its message. Returns the body's exit code
/// otherwise. No stack traces, no noise.
int RunReportingErrors(const std::function<int()>& body);

/// Sets the callback of `cmd`: `prepare` checks the command line as given (every value parsed and
/// checked, ConfigError naming the option otherwise; files are not read) and returns the work to
/// do, which runs unless `--check-args` was given (then the command exits 0). Errors of either
/// become an exit code as RunReportingErrors says; empty option values are refused first. Does
/// nothing when a subcommand of `cmd` was chosen (it has its own callback).
void SetCommandCallback(CLI::App* cmd, int& exit_code,
                        std::function<std::function<int()>()> prepare);

/// `--flag-name` for the file key `flag_name`: how options are named after the keys they set
/// (docs/cli.md, "Option names").
std::string OptionForKey(const std::string& key);

/// Throws ConfigError naming the first option of `command` that was given an empty value
/// (`--seed ""`, `--out=`): an empty value never silently means "not given". Options that may be
/// given without a value (`--realtime`) are left alone.
void RefuseEmptyValues(const CLI::App& command);

/// The absolute path of the running airis binary (what Slurm job scripts run). Throws
/// std::runtime_error when /proc/self/exe cannot be read.
std::string CurrentExecutable();

/// Parses `text` as a finite double for option `--name`, or throws ConfigError naming the option.
double ParseFiniteNumber(const std::string& name, const std::string& text);

/// Writes `line` and a newline to stderr: where a job's log lines (PX4 connected, ...) go.
void PrintToStderr(const std::string& line);

/// Adds `--set KEY.PATH=VALUE` to `cmd` (repeatable, one override each; texts into `texts`): keys
/// of the scene replaced before it is validated (docs/scene-format.md, "Overrides").
void AddSceneOverrideOption(CLI::App* cmd, std::vector<std::string>& texts);

/// The options that `run` and `px4` share, with their help: `--realtime [FACTOR]`, `--until-s
/// SECONDS`, `--truth-rate-hz HZ` (default "100" already in `text`) and `--threads N` (of `run`,
/// `dataset`, `px4`; default "1" already in `text`).
void AddRealtimeOption(CLI::App* cmd, std::string& text);
void AddUntilOption(CLI::App* cmd, std::string& text);
void AddTruthRateOption(CLI::App* cmd, std::string& text);
void AddThreadsOption(CLI::App* cmd, std::string& text);

/// Parses `text` as an unsigned 64-bit seed for option `--name`, or throws ConfigError naming the
/// option.
std::uint64_t ParseSeed(const std::string& name, const std::string& text);

/// Parses `text` as a whole number from `lo` to `hi` for option `--name`, or throws ConfigError
/// naming the option.
int ParseWholeNumber(const std::string& name, const std::string& text, int lo, int hi);

/// Parses `text` as a duration in seconds for option `--name` (a finite number below 9.2e9 s, the
/// range of int64 nanoseconds), or throws ConfigError naming the option.
engine::TimeNs ParseSeconds(const std::string& name, const std::string& text);

/// Parses `--threads` (threads that step the vehicles): a whole number from 1 to 64.
int ParseThreads(const std::string& text);

}  // namespace airis::tools
