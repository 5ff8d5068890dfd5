#include "paths.h"

#include <climits>
#include <cstdlib>
#include <sys/stat.h>
#include <unistd.h>

#ifndef WB_DEFAULT_ROOT
#error "WB_DEFAULT_ROOT must be defined by CMake"
#endif

namespace wb {
namespace {

bool isDirectory(const std::string& path) {
    struct stat st {};
    return stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

// An installed workbench (the .deb: /usr/bin/labNN, /usr/share/workbench/{assets,shaders})
// finds its files beside its executable, wherever the package was unpacked.
std::string installedRoot() {
    char self[PATH_MAX] = {};
    const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    if (n <= 0) return "";
    std::string dir(self, size_t(n));
    dir.erase(dir.rfind('/'));
    const std::string root = dir + "/" + kInstalledRootFromBin;
    return isDirectory(root + "/shaders") ? root : "";
}

std::string& rootStorage() {
    static std::string root = [] {
        const char* env = std::getenv("WORKBENCH_ROOT");
        if (env && *env) return std::string(env);
        std::string installed = installedRoot();
        return installed.empty() ? std::string(WB_DEFAULT_ROOT) : installed;
    }();
    return root;
}
} // namespace

void setAssetRoot(const std::string& root) {
    if (!root.empty()) rootStorage() = root;
}
const std::string& assetRoot() {
    return rootStorage();
}
std::string assetPath(const std::string& relative) {
    return assetRoot() + "/" + relative;
}

} // namespace wb
