#pragma once

// The whole `airis` command line: every command, `airis help`, `--check-args`, and the one place
// where a command line turns into an exit code (docs/cli.md).

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace airis::tools {

/// Adds every command of `airis` to `app`, `airis help [COMMAND...]`, and `--check-args` to every
/// command; the commands' callbacks set `exit_code`.
void AddAirisCommands(CLI::App& app, int& exit_code);

/// The exit code for a command line CLI11 refused (README, "Exit codes"): 0 after printing the help
/// or version asked for, otherwise 2 after printing `error: ...` and where to find the usage.
int ExitCodeForParseError(const CLI::App& app, const CLI::ParseError& e);

/// An error for a command line whose command is unknown or missing: "unknown command 'fly' (did
/// you mean 'px4'?); the commands of airis: ...". Empty when every command named is known.
/// `args` is the command line after `airis`.
std::string UnknownCommandError(const CLI::App& app, const std::vector<std::string>& args);

/// Runs `airis` with `args` (the command line after `airis`): parses it, runs the command, prints
/// any error, and returns the exit code.
int RunAirisCommandLine(const std::vector<std::string>& args);

}  // namespace airis::tools
