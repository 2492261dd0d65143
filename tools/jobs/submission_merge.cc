#include "tools/jobs/submission_merge.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "engine/dataset/file_io.h"
#include "tools/jobs/shard_progress.h"
#include "tools/jobs/slurm_scripts.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;

// An exclusive flock on a file, released when this goes out of scope (and by the kernel when the
// process dies, so a task killed mid-merge leaves no stale lock behind).
class FileLock {
 public:
  explicit FileLock(const std::string& path) : fd_(::open(path.c_str(), O_RDWR | O_CREAT, 0644)) {
    if (fd_ < 0) {
      throw engine::DatasetIoError("cannot create " + path + ": " + std::strerror(errno));
    }
    while ((error_ = ::flock(fd_, LOCK_EX) == 0 ? 0 : errno) == EINTR) {
    }
  }
  ~FileLock() { ::close(fd_); }  // closing the descriptor releases the lock
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

  /// 0 when held, else the errno of flock (ENOLCK, ENOSYS, EOPNOTSUPP: a file system without
  /// locks, such as Lustre mounted without -o flock).
  int error() const { return error_; }

 private:
  int fd_;
  int error_ = 0;
};

}  // namespace

std::string SubmissionMergeLockPath(const std::string& out) {
  return (fs::path(SlurmFolder(out)) / "merge.lock").string();
}

SubmissionMerge MergeSubmission(const std::string& out, int shards) {
  SubmissionMerge r;
  fs::create_directories(SlurmFolder(out));
  const FileLock lock(SubmissionMergeLockPath(out));
  if (lock.error() != 0) {
    r.outcome = SubmissionMerge::Outcome::kNoLock;
    r.lock_error = std::strerror(lock.error());
    return r;
  }
  const ShardProgress merged = ReadShardProgress(out);
  if (merged.complete && !merged.merge_in_progress) {
    r.outcome = SubmissionMerge::Outcome::kAlreadyMerged;
    r.summary.shards = shards;
    r.summary.frames = merged.frames;
    return r;
  }
  std::vector<fs::path> folders;
  for (int k = 1; k <= shards; ++k) {
    folders.emplace_back(ShardFolder(out, k));
    if (!ReadShardProgress(folders.back().string()).complete) r.unfinished.push_back(k);
  }
  if (!r.unfinished.empty()) {
    r.outcome = SubmissionMerge::Outcome::kShardsLeft;
    return r;
  }
  r.summary = MergeDatasetShards(folders, out);
  r.outcome = SubmissionMerge::Outcome::kMerged;
  return r;
}

}  // namespace airis::tools
