// `airis help`, unknown commands and the usage text, through the app main.cc runs.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "tools/cli/airis_app.h"

namespace airis::tools {
namespace {

struct Output {
  int exit_code = -1;
  std::string out, err;
};

Output Airis(const std::vector<std::string>& args) {
  Output r;
  ::testing::internal::CaptureStdout();
  ::testing::internal::CaptureStderr();
  r.exit_code = RunAirisCommandLine(args);
  r.out = ::testing::internal::GetCapturedStdout();
  r.err = ::testing::internal::GetCapturedStderr();
  return r;
}

TEST(HelpTest, AnUnknownCommandNamesTheClosestAndTheKnownOnes) {
  const Output r = Airis({"datset", "scenes/city.yaml"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind(
                "error: unknown command 'datset' (did you mean 'dataset'?); the commands of airis: "
                "env, scene, run, dataset, px4, campaign, terrain, bench, help\n",
                0),
            0u)
      << r.err;
  const Output fly = Airis({"fly"});
  EXPECT_EQ(fly.exit_code, 2);
  EXPECT_NE(fly.err.find("unknown command 'fly'; the commands of airis: env, scene,"),
            std::string::npos)
      << fly.err;
  const Output chek = Airis({"scene", "chek", "scenes/city.yaml"});
  EXPECT_NE(chek.err.find("unknown command 'chek' (did you mean 'check'?); the commands of airis "
                          "scene: check, stats, schema, preview"),
            std::string::npos)
      << chek.err;
}

TEST(HelpTest, AnOptionBeforeAnyCommandOrNoCommandAtAllIsNamed) {
  const Output verbose = Airis({"--verbose"});
  EXPECT_EQ(verbose.exit_code, 2);
  EXPECT_NE(verbose.err.find("error: unknown option '--verbose' before a command; the commands of "
                             "airis: env,"),
            std::string::npos)
      << verbose.err;
  const Output none = Airis({});
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_NE(none.err.find("error: airis: a command is required: env, scene,"), std::string::npos)
      << none.err;
  const Output bench = Airis({"bench"});
  EXPECT_NE(bench.err.find("airis bench: a command is required: physics, sensors, render, dataset, "
                           "world, vehicles"),
            std::string::npos)
      << bench.err;
}

TEST(HelpTest, HelpAndDashDashHelpPrintTheSameUsage) {
  const Output top = Airis({"help"});
  EXPECT_EQ(top.exit_code, 0) << top.err;
  EXPECT_NE(top.out.find("Usage: airis [OPTIONS] SUBCOMMAND"), std::string::npos) << top.out;
  EXPECT_NE(top.out.find("dataset"), std::string::npos) << top.out;
  EXPECT_EQ(Airis({"--help"}).out, top.out);

  const Output run = Airis({"help", "run"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("Usage: airis run [OPTIONS] scene"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("--until-s SECONDS"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("--truth-rate-hz HZ"), std::string::npos) << run.out;
  EXPECT_EQ(Airis({"run", "--help"}).out, run.out);

  const Output merge = Airis({"help", "dataset", "merge"});
  EXPECT_EQ(merge.exit_code, 0);
  EXPECT_NE(merge.out.find("Usage: airis dataset merge"), std::string::npos) << merge.out;
  EXPECT_EQ(Airis({"dataset", "merge", "--help"}).out, merge.out);

  const Output bad = Airis({"help", "fly"});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("unknown command 'fly'"), std::string::npos) << bad.err;
}

// Every option that takes a value, in every command, says its type (and unit) instead of CLI11's
// TEXT, INT or FLOAT.
TEST(HelpTest, EveryValueHasATypeAndUnit) {
  CLI::App app{"airis"};
  int exit_code = 0;
  AddAirisCommands(app, exit_code);
  int options = 0;
  std::function<void(const CLI::App&, const std::string&)> visit = [&](const CLI::App& cmd,
                                                                       const std::string& path) {
    for (const CLI::Option* o : cmd.get_options()) {
      if (o->get_expected_max() == 0 || o->get_name() == "--help") continue;  // a flag
      ++options;
      const std::string type = o->get_type_name();
      EXPECT_TRUE(type != "" && type.find("TEXT") == std::string::npos && type != "FLOAT" &&
                  type != "INT" && type != "UINT")
          << path << " " << o->get_name() << ": " << type;
    }
    const std::string help = cmd.help();
    EXPECT_EQ(help.find(" TEXT"), std::string::npos) << path << "\n" << help;
    for (const CLI::App* sub : cmd.get_subcommands([](const CLI::App*) { return true; })) {
      visit(*sub, path + " " + sub->get_name());
    }
  };
  visit(app, "airis");
  EXPECT_GT(options, 50);
}

}  // namespace
}  // namespace airis::tools
