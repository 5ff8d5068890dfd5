#include "core/file_read.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace wb {

namespace {

std::string sizeText(std::size_t bytes) {
    if (bytes >= (std::size_t(1) << 20) && bytes % (std::size_t(1) << 20) == 0)
        return std::to_string(bytes >> 20) + " MB";
    return std::to_string(bytes) + " bytes";
}

// Why `st` is not a regular file, or nullptr.
const char* notRegular(const struct stat& st) {
    if (S_ISREG(st.st_mode)) return nullptr;
    if (S_ISDIR(st.st_mode)) return "is a directory, not a file";
    if (S_ISFIFO(st.st_mode)) return "is a FIFO (named pipe), not a regular file";
    if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)) return "is a device, not a regular file";
    if (S_ISSOCK(st.st_mode)) return "is a socket, not a regular file";
    return "is not a regular file";
}

// Closes the descriptor on every path out of readRegularFile.
struct Fd {
    int fd = -1;
    ~Fd() {
        if (fd >= 0) ::close(fd);
    }
};

} // namespace

bool readRegularFile(const std::string& path, std::size_t maxBytes, std::string& out,
                     std::string& error) {
    out.clear();
    if (path.find('\0') != std::string::npos) {
        error = escapeForMessage(path, 200) + ": the path contains a NUL byte";
        return false;
    }
    // 1. stat first: a FIFO is refused before open() could block on it.
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        error = path + ": cannot open the file (" + std::strerror(errno) + ")";
        return false;
    }
    if (const char* why = notRegular(st)) {
        error = path + ": " + why;
        return false;
    }
    // 2. O_NONBLOCK: should the path have become a FIFO since, open() returns at once.
    Fd f;
    f.fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (f.fd < 0) {
        error = path + ": cannot open the file (" + std::strerror(errno) + ")";
        return false;
    }
    if (::fstat(f.fd, &st) != 0) {
        error = path + ": cannot stat the file (" + std::strerror(errno) + ")";
        return false;
    }
    if (const char* why = notRegular(st)) {
        error = path + ": " + why;
        return false;
    }
    if (st.st_size < 0 || std::size_t(st.st_size) > maxBytes) {
        error = path + ": file larger than " + sizeText(maxBytes) + " (the limit for this file)";
        return false;
    }
    // 3. Read at most maxBytes + 1: a file that grows while read is still caught. Once
    //    the size fstat gave is in, more is looked for through a small buffer: doubling
    //    the string first (to read 0 bytes at the end) copied and zeroed the whole file
    //    again, 16 -> 5 ms of an 18 MB OBJ (docs/bench/obj_load.md).
    out.resize(std::size_t(st.st_size));
    // One read(2), retried on EINTR; on failure -1 with `error` set and `out` cleared.
    auto readSome = [&](char* dst, std::size_t cap) -> ssize_t {
        for (;;) {
            const ssize_t n = ::read(f.fd, dst, cap);
            if (n >= 0) return n;
            if (errno == EINTR) continue;
            error = path + ": read error (" + std::strerror(errno) + ")";
            out.clear();
            return -1;
        }
    };
    std::size_t have = 0;
    for (;;) {
        if (have == out.size()) {
            if (have > maxBytes) break;
            char more[4096];
            const ssize_t n = readSome(more, std::min(sizeof more, maxBytes + 1 - have));
            if (n < 0) return false;
            if (n == 0) break;
            out.append(more, std::size_t(n));
            have += std::size_t(n);
            continue;
        }
        const ssize_t n = readSome(&out[have], out.size() - have);
        if (n < 0) return false;
        if (n == 0) break;
        have += std::size_t(n);
    }
    out.resize(have);
    if (have > maxBytes) {
        error = path + ": file larger than " + sizeText(maxBytes) + " (the limit for this file)";
        out.clear();
        return false;
    }
    return true;
}

std::string escapeForMessage(const std::string& bytes, std::size_t maxChars) {
    std::string s;
    const std::size_t n = std::min(bytes.size(), maxChars);
    for (std::size_t i = 0; i < n; ++i) {
        const unsigned char c = static_cast<unsigned char>(bytes[i]);
        if (c >= 0x20 && c < 0x7f && c != '\\') {
            s += char(c);
        } else {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\x%02x", unsigned(c));
            s += buf;
        }
    }
    if (bytes.size() > maxChars) s += "...";
    return s;
}

} // namespace wb
