#pragma once

// Runs `airis <args>` in-process through the same CLI11 setup as tools/main.cc, capturing its
// output.

#include <gtest/gtest.h>

#include <string>

#include "tools/cli/commands.h"

namespace airis::tools::testing {

struct CommandResult {
  int exit_code = -1;
  std::string out, err;
};

/// `add_command` is one of the Add*Command functions of tools/commands.h.
inline CommandResult RunAiris(void (*add_command)(CLI::App&, int&), const std::string& args) {
  CLI::App app{"airis"};
  app.require_subcommand(1);
  CommandResult r;
  add_command(app, r.exit_code);
  ::testing::internal::CaptureStdout();
  ::testing::internal::CaptureStderr();
  try {
    app.parse(args, false);
  } catch (const CLI::ParseError& e) {
    r.exit_code = app.exit(e);
  }
  r.out = ::testing::internal::GetCapturedStdout();
  r.err = ::testing::internal::GetCapturedStderr();
  return r;
}

}  // namespace airis::tools::testing
