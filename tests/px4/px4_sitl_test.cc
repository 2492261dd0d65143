// PX4 itself flies the example mission (scenes/px4_quad.yaml, scenes/missions/px4_square.yaml)
// through airis: a real PX4 SITL build in lockstep on TCP 4560, its airframe written by
// `airis px4 airframe`, the mission commanded over PX4's offboard UDP link. Runs when
// AIRIS_PX4_SITL_DIR points to a PX4 SITL build (its bin/px4 and etc/); skips, saying so,
// otherwise (CI cannot download PX4; docs/px4.md says how to build one outside the repository).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "engine/mission/mission.h"
#include "scenes/mission_file.h"
#include "tests/fixtures/temp_dir.h"
#include "tools/jobs/autopilots.h"
#include "tools/jobs/px4_job.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;

constexpr int kAirframeId = 22001;

// A PX4 SITL process (instance 0) in its own working folder, stopped at the end.
class Px4Process {
 public:
  Px4Process(const fs::path& build, const fs::path& work, const std::string& airframe) {
    // PX4 reads its airframes from the etc/ it is given: a copy with ours added.
    fs::copy(build / "etc", work / "etc", fs::copy_options::recursive);
    const fs::path file =
        work / "etc/init.d-posix/airframes" / (std::to_string(kAirframeId) + "_airis_drone1");
    std::ofstream(file) << airframe;
    fs::create_directories(work / "rootfs");
    log_ = work / "px4.log";
    pid_ = ::fork();
    if (pid_ == 0) {
      (void)!::chdir((work / "rootfs").c_str());
      const int out = ::open(log_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      ::dup2(out, 1);
      ::dup2(out, 2);
      ::setenv("PX4_SYS_AUTOSTART", std::to_string(kAirframeId).c_str(), 1);
      const std::string px4 = (build / "bin/px4").string();
      const std::string etc = (work / "etc").string();
      ::execl(px4.c_str(), px4.c_str(), "-d", "-i", "0", etc.c_str(), nullptr);
      ::_exit(127);
    }
  }
  ~Px4Process() {
    if (pid_ > 0) {
      ::kill(pid_, SIGTERM);
      int status = 0;
      for (int i = 0; i < 50 && ::waitpid(pid_, &status, WNOHANG) == 0; ++i) ::usleep(100'000);
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, &status, 0);
    }
  }
  std::string LogTail() const {
    std::ifstream in(log_);
    std::stringstream s;
    s << in.rdbuf();
    const std::string text = s.str();
    return text.size() > 4000 ? text.substr(text.size() - 4000) : text;
  }

 private:
  pid_t pid_ = -1;
  fs::path log_;
};

TEST(Px4SitlTest, Px4FliesTheExampleSquareMissionToTheEnd) {
  const char* dir = std::getenv("AIRIS_PX4_SITL_DIR");
  if (!dir || !*dir) {
    GTEST_SKIP() << "AIRIS_PX4_SITL_DIR is not set: no PX4 SITL build to fly with (set it to a "
                    "PX4 build folder holding bin/px4 and etc/; docs/px4.md)";
  }
  const fs::path build(dir);
  ASSERT_TRUE(fs::exists(build / "bin/px4")) << build << " has no bin/px4";

  const SceneSource source{"scenes/px4_quad.yaml", "", std::nullopt};
  const std::string airframe = WritePx4AirframeFor(source, "drone1", {kAirframeId, "", 0, 0});
  const fs::path work = airis::testing::MakeTempFolder("px4");
  Px4Process px4(build, work, airframe);

  SimulationJob job(source);
  const std::vector<AttachedAutopilot> attached =
      AttachAutopilots(job, [](const std::string& l) { std::fprintf(stderr, "%s\n", l.c_str()); });
  ASSERT_EQ(attached.size(), 1u);
  const engine::Mission mission = scenes::LoadMissionFile("scenes/missions/px4_square.yaml");
  std::vector<engine::Vec3> path;
  MissionFlight flight;
  flight.until_ns = engine::SecondsToNs(300.0, "until");
  flight.callbacks.after_tick = [&](engine::TimeNs now_ns) {
    if (now_ns % 10'000'000 == 0) path.push_back(job.world().vehicle(0).state().p_W);
  };
  MissionOutcome outcome;
  try {
    outcome = job.FlyMission(mission, flight);
  } catch (const std::exception& e) {
    FAIL() << e.what() << "\nPX4's log:\n" << px4.LogTail();
  }
  ASSERT_TRUE(outcome.succeeded()) << outcome.failure << "\nPX4's log:\n" << px4.LogTail();
  EXPECT_EQ(outcome.steps_done, 6);

  // Took off to 10 m, passed each corner within 1 m, came down, and PX4 disarmed.
  double top = 0.0;
  for (const engine::Vec3& p : path) top = std::max(top, -p.z());
  EXPECT_NEAR(top, 10.0, 1.0);
  double worst_corner = 0.0;
  for (const engine::Vec3& corner : {engine::Vec3(20, 0, -10), engine::Vec3(20, 20, -10),
                                     engine::Vec3(0, 20, -10), engine::Vec3(0, 0, -10)}) {
    double nearest = 1e9;
    for (const engine::Vec3& p : path) nearest = std::min(nearest, (p - corner).norm());
    EXPECT_LT(nearest, 1.0) << "corner " << corner.transpose();
    worst_corner = std::max(worst_corner, nearest);
  }
  std::fprintf(stderr,
               "PX4 flew %d steps: %.1f s simulated in %.1f s wall (%.1fx real time), top %.2f m, "
               "corners within %.2f m, %lld lockstep exchanges\n",
               outcome.steps_done, outcome.simulated_s, job.wall_s(),
               outcome.simulated_s / job.wall_s(), top, worst_corner,
               static_cast<long long>(attached[0].px4->stats().lockstep_steps));
  EXPECT_LT(-job.world().vehicle(0).state().p_W.z(), 0.3);
  const engine::mavlink::Px4LinkStats& stats = attached[0].px4->stats();
  EXPECT_FALSE(stats.armed);
  EXPECT_EQ(stats.timeouts, 0);
  EXPECT_GT(stats.lockstep_steps, 1000);
}

}  // namespace
}  // namespace airis::tools
