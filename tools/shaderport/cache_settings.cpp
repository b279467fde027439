#include "cache_settings.h"

#include <sys/stat.h>

#include <cstdlib>

#include "driver/result_cache.h"

namespace shaderport::cli {

std::optional<std::filesystem::path> CacheDirectory(const std::string& cache_dir_option) {
  if (!cache_dir_option.empty()) return std::filesystem::path(cache_dir_option);
  return driver::DefaultCacheDirectory(std::getenv("XDG_CACHE_HOME"), std::getenv("HOME"));
}

std::string ToolIdentity() {
  std::string identity = std::string("shaderport ") + SHADERPORT_VERSION;
  struct stat status {};
  if (::stat("/proc/self/exe", &status) == 0) {
    identity += " " + std::to_string(status.st_size) + " " + std::to_string(status.st_mtim.tv_sec) +
                "." + std::to_string(status.st_mtim.tv_nsec);
  }
  return identity;
}

}  // namespace shaderport::cli
