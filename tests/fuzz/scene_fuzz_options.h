#pragma once

#include "scenes/scene.h"

namespace airis::testing {

/// What the scene fuzzer loads its inputs with, and the findings test replays them with: the
/// objects may take 128 MiB (about 149,000 of them at engine::kMinBuiltObjectBytes). A few lines
/// of `repeat` can place millions of valid objects, which this machine's memory would hold but
/// the fuzzer's 2 GB (-rss_limit_mb, the sanitizers' overhead included) does not; with this limit
/// such a scene gets the error a small machine gives it (docs/fuzzing.md).
inline scenes::SceneLoadOptions FuzzSceneLoadOptions() {
  scenes::SceneLoadOptions options;
  options.memory_limit_bytes = 128ull << 20;
  return options;
}

}  // namespace airis::testing
