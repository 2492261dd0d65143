#pragma once

#include <string>

namespace airis::tools {

/// Creates `path` if needed; throws ConfigError naming `option` when it exists and is not an empty
/// folder (nothing is ever overwritten) or cannot be created.
void PrepareEmptyOutputFolder(const std::string& path, const std::string& option);

}  // namespace airis::tools
