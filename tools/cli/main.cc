// The `airis` command line: one subcommand per job (DESIGN.md, "Main commands").
#include <CLI/CLI.hpp>

#include "tools/cli/commands.h"
#include "tools/jobs/version.h"

int main(int argc, char** argv) {
  CLI::App app{"airis: a simulator for aerial robots (physics, sensors, rendering, datasets)"};
  app.set_version_flag("--version", std::string("airis ") + airis::tools::kVersion);
  app.require_subcommand(1);
  int exit_code = 0;
  airis::tools::AddEnvCommand(app, exit_code);
  airis::tools::AddSceneCommand(app, exit_code);
  airis::tools::AddRunCommand(app, exit_code);
  airis::tools::AddDatasetCommand(app, exit_code);
  airis::tools::AddPx4Command(app, exit_code);
  airis::tools::AddCampaignCommand(app, exit_code);
  airis::tools::AddBenchCommand(app, exit_code);
  CLI11_PARSE(app, argc, argv);
  return exit_code;
}
