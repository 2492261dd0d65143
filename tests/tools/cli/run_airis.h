#pragma once

// Runs `airis <args>` in-process through the same CLI11 setup as tools/main.cc, capturing its
// output. (tests/tools/cli/exit_codes_test.cc runs the real binary.)

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "tools/cli/airis_app.h"
#include "tools/cli/commands.h"

namespace airis::tools::testing {

struct CommandResult {
  int exit_code = -1;
  std::string out, err;
};

/// `add_command` is one of the Add*Command functions of tools/commands.h.
/// `parse` runs the parser on the app (its arguments given in one of CLI11's forms).
template <class Parse>
CommandResult RunAirisParsing(void (*add_command)(CLI::App&, int&), Parse&& parse) {
  CLI::App app{"airis"};
  app.require_subcommand(1);
  CommandResult r;
  add_command(app, r.exit_code);
  ::testing::internal::CaptureStdout();
  ::testing::internal::CaptureStderr();
  try {
    parse(app);
  } catch (const CLI::ParseError& e) {
    r.exit_code = ExitCodeForParseError(app, e);
  }
  r.out = ::testing::internal::GetCapturedStdout();
  r.err = ::testing::internal::GetCapturedStderr();
  return r;
}

/// `args`: the command line after `airis`, split as a shell would (quotes group words).
inline CommandResult RunAiris(void (*add_command)(CLI::App&, int&), const std::string& args) {
  return RunAirisParsing(add_command, [&](CLI::App& app) { app.parse(args, false); });
}

/// `args`: the command line after `airis`, one argument each, as a shell passes them (an empty
/// argument, `""`, stays one; the string form drops it).
inline CommandResult RunAiris(void (*add_command)(CLI::App&, int&), std::vector<std::string> args) {
  return RunAirisParsing(add_command, [&](CLI::App& app) {
    std::reverse(args.begin(), args.end());  // CLI11 takes them last first
    app.parse(args);
  });
}

}  // namespace airis::tools::testing
