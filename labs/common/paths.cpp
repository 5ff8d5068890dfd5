#include "paths.h"

#include <cstdlib>

#ifndef WB_DEFAULT_ROOT
#error "WB_DEFAULT_ROOT must be defined by CMake"
#endif

namespace wb {
namespace {
std::string& rootStorage() {
    static std::string root = [] {
        const char* env = std::getenv("WORKBENCH_ROOT");
        return std::string(env && *env ? env : WB_DEFAULT_ROOT);
    }();
    return root;
}
} // namespace

void setAssetRoot(const std::string& root) {
    if (!root.empty()) rootStorage() = root;
}
const std::string& assetRoot() { return rootStorage(); }
std::string assetPath(const std::string& relative) { return assetRoot() + "/" + relative; }

} // namespace wb
