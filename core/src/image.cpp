#include "core/image.h"

#include "core/file_read.h"

#include "core/i18n.h"
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

// The implementations come from Debian's libstb.so.
#include <stb_image.h>
#include <stb_image_write.h>

namespace wb {

namespace {

std::string sysError(const std::string& what) {
    return what + " (" + std::strerror(errno) + ")";
}

// write(2) until every byte is out; a short write that makes no progress is an error.
bool writeAll(int fd, const std::vector<uint8_t>& bytes) {
    size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            if (n == 0) errno = EIO;
            return false;
        }
        done += size_t(n);
    }
    return true;
}

} // namespace

bool writePng(const std::string& path, const Image& img, std::string* error) {
    auto fail = [&](const std::string& msg) {
        if (error) *error = path + ": " + msg;
        return false;
    };
    if (img.width <= 0 || img.height <= 0 || img.channels < 1 || img.channels > 4 ||
        img.data.size() != size_t(img.width) * size_t(img.height) * size_t(img.channels))
        return fail(tr("refusing to write an empty or inconsistent image"));
    if (path.empty()) return fail(tr("empty file name"));

    // 1. Encode in memory: stbi_write_png ignores fwrite's result (a full disk or a
    //    read-only /proc file "succeeds"), so the bytes are written below, every call checked.
    std::vector<uint8_t> png;
    const int encoded = stbi_write_png_to_func(
        [](void* ctx, void* data, int size) {
            auto* out = static_cast<std::vector<uint8_t>*>(ctx);
            const auto* p = static_cast<const uint8_t*>(data);
            out->insert(out->end(), p, p + size);
        },
        &png, img.width, img.height, img.channels, img.data.data(), img.width * img.channels);
    if (!encoded || png.empty()) return fail(tr("cannot encode PNG"));

    // 2. One rule for every output (core/file_read.h, issue 20 points 1 and 11): a FIFO,
    //    device, socket or directory is refused before anything is opened; a symlink is
    //    followed to the file it names, a dangling or looping one refused.
    std::string target;
    {
        std::string why;
        if (!checkOutputFile(path, target, why)) {
            if (error) *error = why;
            return false;
        }
    }
    struct stat st {};
    const bool exists = ::stat(target.c_str(), &st) == 0;

    // 3. A regular file (or a new one): write a temporary file in the same directory,
    //    flush it to the disk, then rename it over the real name. A failed or short write
    //    removes the temporary file and leaves whatever was under the real name untouched.
    const size_t slash = target.rfind('/');
    const std::string dir = slash == std::string::npos ? "."
                            : slash == 0               ? "/"
                                                       : target.substr(0, slash);
    const std::string base = slash == std::string::npos ? target : target.substr(slash + 1);
    std::string tmp = (slash == std::string::npos ? std::string() : target.substr(0, slash + 1)) +
                      "." + base + ".tmp-XXXXXX";
    std::vector<char> name(tmp.begin(), tmp.end());
    name.push_back('\0');
    const int fd = ::mkstemp(name.data());
    if (fd < 0) return fail(sysError(trf("cannot create a temporary file in %s", dir.c_str())));
    tmp = name.data();
    auto abandon = [&](const std::string& msg) {
        const int savedErrno = errno;
        ::close(fd);
        ::unlink(tmp.c_str());
        errno = savedErrno;
        return fail(sysError(msg));
    };
    // mkstemp makes the file 0600; give it the mode a plain fopen would (or the old file's).
    mode_t mode = 0;
    if (exists) {
        mode = st.st_mode & 07777;
    } else {
        const mode_t mask = ::umask(0);
        ::umask(mask);
        mode = 0666 & ~mask;
    }
    if (::fchmod(fd, mode) != 0) return abandon(trf("cannot set the mode of %s", tmp.c_str()));
    if (!writeAll(fd, png)) return abandon(tr("write failed"));
    if (::fsync(fd) != 0) return abandon(tr("write failed on flush"));
    if (::close(fd) != 0) {
        const int savedErrno = errno;
        ::unlink(tmp.c_str());
        errno = savedErrno;
        return fail(sysError(tr("write failed on close")));
    }
    if (::rename(tmp.c_str(), target.c_str()) != 0) {
        const int savedErrno = errno;
        ::unlink(tmp.c_str());
        errno = savedErrno;
        return fail(sysError(trf("cannot rename %s to the real name", tmp.c_str())));
    }
    return true;
}

bool readImage(const std::string& path, Image& img, int channels, std::string* error) {
    // Through readRegularFile (issue 12): a FIFO, device or directory is refused and the
    // file is capped, and so is the decoded size a small header may claim.
    constexpr std::size_t kMaxFileBytes = std::size_t(256)
                                          << 20;      // 16384² RGBA is 1 GiB raw; PNGs compress
    constexpr long long kMaxPixels = 16384LL * 16384; // the largest GL texture we use
    std::string bytes, err;
    if (!readRegularFile(path, kMaxFileBytes, bytes, err)) {
        if (error) *error = err;
        return false;
    }
    if (bytes.size() > std::size_t(std::numeric_limits<int>::max())) { // stb takes an int length
        if (error) *error = path + ": " + tr("file too large for the image reader");
        return false;
    }
    const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
    const int len = int(bytes.size());
    int w = 0, h = 0, c = 0;
    if (stbi_info_from_memory(data, len, &w, &h, &c) && (long long)w * h > kMaxPixels) {
        if (error) *error = path + ": " + trf("image %dx%d larger than 16384x16384 pixels", w, h);
        return false;
    }
    unsigned char* pixels = stbi_load_from_memory(data, len, &w, &h, &c, channels);
    if (!pixels) {
        if (error) *error = path + ": " + trf("cannot read image (%s)", stbi_failure_reason());
        return false;
    }
    int outC = channels ? channels : c;
    img = Image(w, h, outC);
    std::memcpy(img.data.data(), pixels, img.data.size());
    stbi_image_free(pixels);
    return true;
}

ImageDiff compareImages(const Image& a, const Image& b) {
    ImageDiff d;
    if (a.width != b.width || a.height != b.height || a.channels != b.channels || a.empty())
        return d;
    d.sameSize = true;
    double sum = 0;
    for (size_t i = 0; i < a.data.size(); ++i) {
        int diff = std::abs(int(a.data[i]) - int(b.data[i]));
        if (diff > d.maxDiff) d.maxDiff = diff;
        sum += diff;
    }
    d.meanDiff = sum / double(a.data.size());
    return d;
}

} // namespace wb
