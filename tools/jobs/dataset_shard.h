#pragma once

#include <string>

namespace airis::tools {

/// Shard K of N of a dataset (`--shard K/N`): the run records frame indices i with
/// i % N == K - 1 of every camera.
struct ShardSpec {
  int index = 1;  ///< 1-based, as written
  int count = 1;
};

/// Parses `--shard K/N` (empty text: the whole dataset, 1/1). Throws ConfigError("--shard")
/// otherwise.
ShardSpec ParseShard(const std::string& text);

}  // namespace airis::tools
