#include "paths.h"
#include "shell.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sys/stat.h>

namespace wb {

float clampZoom(float zoom) {
    return std::isfinite(zoom) ? std::clamp(zoom, kMinZoom, kMaxZoom) : 1.0f;
}

bool shellKey(int code, View& view, bool& panelVisible) {
    switch (code) {
    case '+':
    case '=':
        view.zoom = clampZoom(view.zoom * 1.1f);
        return true;
    case '-':
        view.zoom = clampZoom(view.zoom / 1.1f);
        return true;
    case 'h':
        panelVisible = !panelVisible;
        return true;
    default:
        return false;
    }
}

bool checkWritable(const std::string& path, std::string& error) {
    struct stat st {};
    bool existed = stat(path.c_str(), &st) == 0;
    if (existed && S_ISDIR(st.st_mode)) {
        error = path + ": cannot write (it is a directory)";
        return false;
    }
    std::FILE* f = std::fopen(path.c_str(), "ab");
    if (!f) {
        error = path + ": cannot write (" + std::strerror(errno) + ")";
        return false;
    }
    std::fclose(f);
    if (!existed) std::remove(path.c_str());
    return true;
}

bool applyOptions(const ShellOptions& opts, Lab& lab, std::string& error) {
    setAssetRoot(opts.root);
    for (const auto& [name, value] : opts.labOptions)
        if (!lab.setOption(name, value, error)) {
            error = "--" + name + ": " + error;
            return false;
        }
    return true;
}

} // namespace wb
