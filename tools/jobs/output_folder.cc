#include "tools/jobs/output_folder.h"

#include <filesystem>

#include "engine/core/error.h"

namespace airis::tools {

void PrepareEmptyOutputFolder(const std::string& path, const std::string& option) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(path, ec)) {
    if (!fs::is_directory(path, ec)) {
      throw engine::ConfigError({}, option, "'" + path + "' exists and is not a folder");
    }
    if (!fs::is_empty(path, ec)) {
      throw engine::ConfigError({}, option,
                                "'" + path +
                                    "' is not empty; nothing is overwritten (choose another folder "
                                    "or remove it)");
    }
    return;
  }
  fs::create_directories(path, ec);
  if (ec) throw engine::ConfigError({}, option, "cannot create '" + path + "': " + ec.message());
}

}  // namespace airis::tools
