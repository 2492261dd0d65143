#include "tools/jobs/output_folder.h"

#include <algorithm>
#include <filesystem>

#include "engine/core/error.h"
#include "engine/dataset/file_io.h"

namespace airis::tools {

void PrepareEmptyOutputFolder(const std::string& path, const std::string& option,
                              const std::vector<std::string>& allowed) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(path, ec)) {
    if (!fs::is_directory(path, ec)) {
      throw engine::ConfigError({}, option, "'" + path + "' exists and is not a folder");
    }
    bool empty = true;
    for (const auto& e : fs::directory_iterator(path, ec)) {
      empty = empty && std::find(allowed.begin(), allowed.end(), e.path().filename().string()) !=
                           allowed.end();
    }
    if (!empty) {
      throw engine::ConfigError({}, option,
                                "'" + path +
                                    "' is not empty; nothing is overwritten (choose another folder "
                                    "or remove it)");
    }
    return;
  }
  fs::create_directories(path, ec);
  if (ec) {
    throw engine::DatasetIoError(option + ": cannot create '" + path + "': " + ec.message());
  }
}

}  // namespace airis::tools
