#include "tests/tools/cli/airis_binary.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <sstream>

#include "tests/fixtures/temp_dir.h"

extern char** environ;

namespace airis::tools::testing {
namespace {

std::string Read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The test's environment with `more` added or replacing a variable of the same name.
std::vector<std::string> Environment(const std::vector<std::string>& more) {
  std::vector<std::string> env;
  for (char** e = environ; *e != nullptr; ++e) {
    const std::string entry(*e);
    const std::string name = entry.substr(0, entry.find('=') + 1);
    bool replaced = false;
    for (const std::string& m : more) replaced = replaced || m.rfind(name, 0) == 0;
    if (!replaced) env.push_back(entry);
  }
  env.insert(env.end(), more.begin(), more.end());
  return env;
}

std::vector<char*> Pointers(std::vector<std::string>& words) {
  std::vector<char*> p;
  for (std::string& w : words) p.push_back(w.data());
  p.push_back(nullptr);
  return p;
}

}  // namespace

AirisProcess::AirisProcess(const std::vector<std::string>& args,
                           const std::vector<std::string>& env) {
  static std::atomic<int> count{0};
  const std::string stem =
      (airis::testing::TestTempDir() / ("airis_process_" + std::to_string(count++))).string();
  out_path_ = stem + ".out";
  err_path_ = stem + ".err";
  std::vector<std::string> argv = {AIRIS_BIN};
  argv.insert(argv.end(), args.begin(), args.end());
  std::vector<std::string> envp = Environment(env);
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&files, STDOUT_FILENO, out_path_.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&files, STDERR_FILENO, err_path_.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  // The child starts with default signal dispositions, whatever the test runner set.
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t all;
  sigfillset(&all);
  posix_spawnattr_setsigdefault(&attr, &all);
  sigset_t none;
  sigemptyset(&none);
  posix_spawnattr_setsigmask(&attr, &none);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  const int rc = posix_spawn(&pid_, argv[0].c_str(), &files, &attr, Pointers(argv).data(),
                             Pointers(envp).data());
  posix_spawnattr_destroy(&attr);
  posix_spawn_file_actions_destroy(&files);
  if (rc != 0) {
    pid_ = -1;
    ADD_FAILURE() << "cannot start " << AIRIS_BIN << ": " << std::strerror(rc);
  }
}

AirisProcess::~AirisProcess() {
  if (pid_ > 0 && status_ == -1) {
    ::kill(pid_, SIGKILL);
    Wait();
  }
}

void AirisProcess::Signal(int signal) const {
  if (pid_ > 0) ::kill(pid_, signal);
}

int AirisProcess::Wait() {
  if (pid_ <= 0) return -1;
  if (status_ == -1) {
    while (::waitpid(pid_, &status_, 0) < 0 && errno == EINTR) {
    }
  }
  if (WIFSIGNALED(status_)) {
    killed_by_ = WTERMSIG(status_);
    return 128 + killed_by_;
  }
  return WEXITSTATUS(status_);
}

std::string AirisProcess::out() const { return Read(out_path_); }
std::string AirisProcess::err() const { return Read(err_path_); }

BinaryResult RunAirisBinary(const std::vector<std::string>& args,
                            const std::vector<std::string>& env) {
  AirisProcess p(args, env);
  BinaryResult r;
  r.exit_code = p.Wait();
  r.killed_by = p.killed_by();
  r.out = p.out();
  r.err = p.err();
  return r;
}

}  // namespace airis::tools::testing
