#include "tools/cli/airis_app.h"

#include <cstdio>
#include <iostream>
#include <memory>

#include "engine/core/config.h"
#include "tools/cli/commands.h"
#include "tools/jobs/version.h"

namespace airis::tools {
namespace {

// The subcommands of `app`, by name.
std::vector<std::string> CommandNames(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    names.push_back(sub->get_name());
  }
  return names;
}

const CLI::App* FindCommand(const CLI::App& app, const std::string& name) {
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    if (sub->get_name() == name) return sub;
  }
  return nullptr;
}

std::string JoinNames(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// "unknown command 'fly' (did you mean 'px4'?); the commands of airis: env, scene, ...".
std::string UnknownIn(const CLI::App& at, const std::string& path, const std::string& word) {
  const std::vector<std::string> names = CommandNames(at);
  const std::optional<std::string> closest = engine::ClosestMatch(word, names);
  return "unknown command '" + word + "'" +
         (closest ? " (did you mean '" + *closest + "'?)" : std::string()) + "; the commands of " +
         path + ": " + JoinNames(names);
}

// `airis help [COMMAND...]`: the help of the command named, as `--help` prints it.
int PrintHelp(const CLI::App& app, const std::vector<std::string>& words) {
  const CLI::App* at = &app;
  std::string path = app.get_name();
  for (const std::string& word : words) {
    const CLI::App* sub = FindCommand(*at, word);
    if (sub == nullptr || sub->get_name() == "help") {
      std::fprintf(stderr, "error: %s\n", UnknownIn(*at, path, word).c_str());
      return 2;
    }
    path += " " + word;
    at = sub;
  }
  // Not help(): from the app, it prints the help of the command selected, `help` itself.
  std::cout << at->get_formatter()->make_help(at, path, CLI::AppFormatMode::Normal);
  return 0;
}

// Adds --check-args to `cmd` and every command below it.
void AddCheckArgs(CLI::App& cmd) {
  cmd.add_flag("--check-args")
      ->description(
          "check the command line (commands, options and their values) and exit: 0 when valid, 2 "
          "with the error otherwise; runs nothing, reads no file");
  for (CLI::App* sub : cmd.get_subcommands([](const CLI::App*) { return true; })) {
    AddCheckArgs(*sub);
  }
}

}  // namespace

void AddAirisCommands(CLI::App& app, int& exit_code) {
  app.name("airis");
  app.set_version_flag("--version", std::string("airis ") + kVersion);
  app.require_subcommand(1);
  AddEnvCommand(app, exit_code);
  AddSceneCommand(app, exit_code);
  AddRunCommand(app, exit_code);
  AddDatasetCommand(app, exit_code);
  AddPx4Command(app, exit_code);
  AddCampaignCommand(app, exit_code);
  AddTerrainCommand(app, exit_code);
  AddBenchCommand(app, exit_code);
  AddCheckArgs(app);
  auto words = std::make_shared<std::vector<std::string>>();
  CLI::App* help = app.add_subcommand("help", "print the help of airis or of a command");
  help->add_option("command", *words, "a command and its subcommands, e.g. help dataset merge")
      ->type_name("COMMAND...");
  help->callback([&app, words, &exit_code] { exit_code = PrintHelp(app, *words); });
}

int ExitCodeForParseError(const CLI::App& app, const CLI::ParseError& e) {
  if (e.get_exit_code() == 0) {  // --help, --help-all, --version
    return app.exit(e);
  }
  std::fprintf(stderr, "error: %s\n(airis help COMMAND prints a command's usage)\n", e.what());
  return 2;
}

std::string UnknownCommandError(const CLI::App& app, const std::vector<std::string>& args) {
  const CLI::App* at = &app;
  std::string path = app.get_name();
  for (const std::string& arg : args) {
    if (CommandNames(*at).empty()) return "";
    const bool needed = at->get_require_subcommand_min() > 0;
    if (!arg.empty() && arg[0] == '-') {
      const std::string name = arg.substr(0, arg.find('='));
      if (name == "-h" || name == "--help" || name == "--help-all" || name == "--version" ||
          !needed) {
        return "";
      }
      if (at->get_option_no_throw(name) != nullptr) continue;
      return "unknown option '" + arg + "' before a command; the commands of " + path + ": " +
             JoinNames(CommandNames(*at));
    }
    const CLI::App* sub = FindCommand(*at, arg);
    if (sub == nullptr) return needed ? UnknownIn(*at, path, arg) : "";
    path += " " + arg;
    at = sub;
  }
  if (at->get_require_subcommand_min() == 0) return "";
  return path + ": a command is required: " + JoinNames(CommandNames(*at));
}

int RunAirisCommandLine(const std::vector<std::string>& args) {
  CLI::App app{"airis: a simulator for aerial robots (physics, sensors, rendering, datasets)"};
  int exit_code = 0;
  AddAirisCommands(app, exit_code);
  const std::string unknown = UnknownCommandError(app, args);
  if (!unknown.empty()) {
    std::fprintf(stderr, "error: %s\n(airis help prints the usage)\n", unknown.c_str());
    return 2;
  }
  try {
    std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them last first
    app.parse(reversed);
  } catch (const CLI::ParseError& e) {
    return ExitCodeForParseError(app, e);
  }
  return exit_code;
}

}  // namespace airis::tools
