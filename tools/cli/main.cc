// The `airis` command line: one subcommand per job (DESIGN.md, "Main commands"; docs/cli.md).
#include <string>
#include <vector>

#include "tools/cli/airis_app.h"

int main(int argc, char** argv) {
  return airis::tools::RunAirisCommandLine(std::vector<std::string>(argv + 1, argv + argc));
}
