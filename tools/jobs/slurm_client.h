#pragma once

// The Slurm commands airis runs (sbatch, squeue, scancel), found in PATH like a user's shell finds
// them, and the reading of what they print. Each failure is a SchedulerError carrying the
// command's own message.

#include <stdexcept>
#include <string>
#include <vector>

#include "tools/jobs/process_run.h"

namespace airis::tools {

/// A Slurm command failed or could not be started: the message names the command line, its exit
/// status and what it printed on stderr (Slurm's own words). The CLI exits 5 (README, "Exit
/// codes").
class SchedulerError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A job or array task as squeue shows it.
struct SlurmJobState {
  std::string job;        ///< "123" for a job, "123_4" for task 4 of array job 123
  std::string array_job;  ///< "123" (for a job that is no array task: the job itself)
  int array_task = -1;    ///< 4, or -1 for a job that is no array task
  std::string state;      ///< PENDING, RUNNING, COMPLETING, COMPLETED, FAILED, CANCELLED, ...
  std::string reason;  ///< why it waits or ended: None, Dependency, DependencyNeverSatisfied, ...
  /// True while Slurm may still run it: PENDING, RUNNING, CONFIGURING, COMPLETING, REQUEUED,
  /// RESIZING, SUSPENDED and the other states of a job that has not ended.
  bool active() const;
};

/// The squeue format of QuerySlurmJobs: `%i|%T|%r` per line.
inline constexpr const char* kSqueueFormat = "%i|%T|%r";

/// Reads squeue's lines in kSqueueFormat. Throws SchedulerError naming the line it cannot read.
std::vector<SlurmJobState> ParseSqueueOutput(const std::string& text);

/// Runs `sbatch_command` (an sbatch command line with --parsable) and returns the new job's id.
/// Throws SchedulerError when sbatch fails or prints no job id.
std::string SubmitSlurmJob(const std::vector<std::string>& sbatch_command);

/// The jobs and array tasks of `jobs` (job ids or ARRAY_TASK ids) that slurmctld still knows
/// (pending, running, and those finished within its MinJobAge, 300 s by default), one entry per
/// array task. Jobs it has forgotten are left out. Throws SchedulerError when squeue cannot be run
/// or cannot reach slurmctld.
std::vector<SlurmJobState> QuerySlurmJobs(const std::vector<std::string>& jobs);

/// scancel of `jobs`. Throws SchedulerError when scancel fails.
void CancelSlurmJobs(const std::vector<std::string>& jobs);

/// "sbatch --parsable ... (exit 1): sbatch: error: ..." for a failed command.
std::string DescribeFailure(const std::vector<std::string>& command, const ProcessResult& r);

}  // namespace airis::tools
