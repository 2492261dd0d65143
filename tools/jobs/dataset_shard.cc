#include "tools/jobs/dataset_shard.h"

#include <cstdio>

#include "engine/core/error.h"

namespace airis::tools {

ShardSpec ParseShard(const std::string& text) {
  ShardSpec s;
  char slash = 0, rest = 0;
  if (text.empty()) return s;
  if (std::sscanf(text.c_str(), "%d %c %d %c", &s.index, &slash, &s.count, &rest) != 3 ||
      slash != '/' || s.count < 1 || s.index < 1 || s.index > s.count) {
    throw engine::ConfigError({}, "--shard",
                              "expected K/N with 1 <= K <= N, e.g. 2/8 (got '" + text + "')");
  }
  return s;
}

}  // namespace airis::tools
