#include "paths.h"
#include "shell.h"

#include "core/file_read.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

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
    // The rule every output follows (core/file_read.h): nothing that is not a regular
    // file (a FIFO blocked this check forever in fopen), links followed to their file.
    std::string target;
    if (!checkOutputFile(path, target, error)) return false;
    struct stat st {};
    const bool existed = ::stat(target.c_str(), &st) == 0;
    // A regular file (or a new one): opening it cannot block.
    const int fd =
        ::open(target.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_NONBLOCK | O_CLOEXEC, 0666);
    if (fd < 0) {
        error = escapeForMessage(path, 4096) + ": cannot write (" + std::strerror(errno) + ")";
        return false;
    }
    ::close(fd);
    if (!existed) ::unlink(target.c_str());
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
