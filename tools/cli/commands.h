#pragma once

#include <CLI/CLI.hpp>

namespace airis::tools {

// Each subcommand of `airis` adds itself to the app; the callback it installs sets `exit_code`.
// One function per <name>_command.cc.
void AddEnvCommand(CLI::App& app, int& exit_code);
void AddSceneCommand(CLI::App& app, int& exit_code);
void AddRunCommand(CLI::App& app, int& exit_code);
void AddBenchCommand(CLI::App& app, int& exit_code);
void AddDatasetCommand(CLI::App& app, int& exit_code);
void AddPx4Command(CLI::App& app, int& exit_code);
void AddCampaignCommand(CLI::App& app, int& exit_code);
void AddTerrainCommand(CLI::App& app, int& exit_code);

}  // namespace airis::tools
