#pragma once

#include <string>
#include <vector>

namespace airis::tools {

/// The folders of a Slurm submission inside the dataset folder it makes (docs/cluster.md): the
/// shards and the scripts. A dataset never writes them (scenes/scene_loader.cc reserves the names).
inline const std::vector<std::string> kSubmissionFolders = {"shards", "slurm"};

/// Creates `path` if needed; throws ConfigError naming `option` when it exists and is not an empty
/// folder (nothing is ever overwritten), DatasetIoError when it cannot be created (an unwritable
/// place: exit code 4, README "Exit codes"). Entries named in `allowed` may be
/// there (a merge into the folder of a Slurm submission: kSubmissionFolders).
void PrepareEmptyOutputFolder(const std::string& path, const std::string& option,
                              const std::vector<std::string>& allowed = {});

}  // namespace airis::tools
