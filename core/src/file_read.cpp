#include "core/file_read.h"

#include "core/i18n.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace wb {

namespace {

std::string sizeText(std::size_t bytes) {
    if (bytes >= (std::size_t(1) << 20) && bytes % (std::size_t(1) << 20) == 0)
        return trf("%zu MB", bytes >> 20);
    return trf("%zu bytes", bytes);
}

// Why `st` is not a regular file, or nullptr.
const char* notRegular(const struct stat& st) {
    if (S_ISREG(st.st_mode)) return nullptr;
    if (S_ISDIR(st.st_mode)) return tr("is a directory, not a file");
    if (S_ISFIFO(st.st_mode)) return tr("is a FIFO (named pipe), not a regular file");
    if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)) return tr("is a device, not a regular file");
    if (S_ISSOCK(st.st_mode)) return tr("is a socket, not a regular file");
    return tr("is not a regular file");
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
    // The path as messages show it: a name from a file or a command line may hold escape
    // sequences or newlines (issue 20 point 16).
    const std::string shown = escapeForMessage(path, 4096);
    if (path.find('\0') != std::string::npos) {
        error = escapeForMessage(path, 200) + ": " + tr("the path contains a NUL byte");
        return false;
    }
    // 1. stat first: a FIFO is refused before open() could block on it.
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        error = shown + ": " + trf("cannot open the file (%s)", std::strerror(errno));
        return false;
    }
    if (const char* why = notRegular(st)) {
        error = shown + ": " + why;
        return false;
    }
    // 2. O_NONBLOCK: should the path have become a FIFO since, open() returns at once.
    Fd f;
    f.fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (f.fd < 0) {
        error = shown + ": " + trf("cannot open the file (%s)", std::strerror(errno));
        return false;
    }
    if (::fstat(f.fd, &st) != 0) {
        error = shown + ": " + trf("cannot stat the file (%s)", std::strerror(errno));
        return false;
    }
    if (const char* why = notRegular(st)) {
        error = shown + ": " + why;
        return false;
    }
    if (st.st_size < 0 || std::size_t(st.st_size) > maxBytes) {
        error = shown + ": " +
                trf("file larger than %s (the limit for this file)", sizeText(maxBytes).c_str());
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
            error = shown + ": " + trf("read error (%s)", std::strerror(errno));
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
        error = shown + ": " +
                trf("file larger than %s (the limit for this file)", sizeText(maxBytes).c_str());
        out.clear();
        return false;
    }
    return true;
}

bool checkOutputFile(const std::string& path, std::string& target, std::string& error) {
    const std::string shown = escapeForMessage(path, 4096);
    auto fail = [&](const std::string& why) {
        error = shown + ": " + why;
        return false;
    };
    if (path.empty()) return fail(tr("empty file name"));
    if (path.find('\0') != std::string::npos) return fail(tr("the path contains a NUL byte"));
    target = path;
    struct stat st {};
    if (::lstat(path.c_str(), &st) == 0 && S_ISLNK(st.st_mode)) {
        // Follow the link to the file it names; realpath fails on a dangling link
        // (ENOENT), a loop or a chain longer than the kernel's 40 (ELOOP).
        char* real = ::realpath(path.c_str(), nullptr);
        if (!real) {
            if (errno == ENOENT)
                return fail(tr("is a symbolic link to a file that does not exist (links are "
                               "followed, not replaced: give the target's path)"));
            if (errno == ELOOP)
                return fail(tr("is a symbolic link that loops or passes through more than "
                               "40 links"));
            return fail(
                trf("is a symbolic link that cannot be followed (%s)", std::strerror(errno)));
        }
        target = real;
        std::free(real);
    }
    if (::stat(target.c_str(), &st) == 0) {
        if (S_ISDIR(st.st_mode)) return fail(tr("cannot write (it is a directory)"));
        if (S_ISFIFO(st.st_mode))
            return fail(tr("is a FIFO (named pipe), not a regular file: not written"));
        if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode))
            return fail(tr("is a device, not a regular file: not written"));
        if (S_ISSOCK(st.st_mode)) return fail(tr("is a socket, not a regular file: not written"));
        if (!S_ISREG(st.st_mode)) return fail(tr("is not a regular file: not written"));
        return true;
    }
    if (errno != ENOENT) return fail(trf("cannot write (%s)", std::strerror(errno)));
    // A new file: its directory must exist (writability is the writer's check: root
    // writes where access() would say no, and /proc refuses even root).
    const std::size_t slash = target.rfind('/');
    const std::string dir = slash == std::string::npos ? "."
                            : slash == 0               ? "/"
                                                       : target.substr(0, slash);
    if (::stat(dir.c_str(), &st) != 0)
        return fail(trf("cannot write: the folder %s does not exist (%s)",
                        escapeForMessage(dir, 4096).c_str(), std::strerror(errno)));
    if (!S_ISDIR(st.st_mode))
        return fail(trf("cannot write: %s is not a folder", escapeForMessage(dir, 4096).c_str()));
    return true;
}

int firstNulLine(std::string_view text) {
    const void* nul = std::memchr(text.data(), '\0', text.size());
    if (!nul) return 0;
    const std::size_t at = std::size_t(static_cast<const char*>(nul) - text.data());
    int line = 1;
    for (std::size_t i = 0; i < at; ++i) {
        if (text[i] == '\n') {
            ++line;
        } else if (text[i] == '\r') {
            if (i + 1 < at && text[i + 1] == '\n') ++i;
            ++line;
        }
    }
    return line;
}

const char* nulByteMessage() {
    return tr("NUL byte in the line (a binary file?)");
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
