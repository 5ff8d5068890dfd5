#include "core/image.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>

// The implementations come from Debian's libstb.so.
#include <stb_image.h>
#include <stb_image_write.h>

namespace wb {

bool writePng(const std::string& path, const Image& img, std::string* error) {
    if (img.width <= 0 || img.height <= 0 || img.data.size() != size_t(img.width) * img.height * img.channels) {
        if (error) *error = path + ": refusing to write an empty or inconsistent image";
        return false;
    }
    errno = 0;
    int ok = stbi_write_png(path.c_str(), img.width, img.height, img.channels, img.data.data(),
                            img.width * img.channels);
    if (!ok) {
        if (error)
            *error = path + ": cannot write PNG" + (errno ? std::string(" (") + std::strerror(errno) + ")" : "");
        return false;
    }
    return true;
}

bool readImage(const std::string& path, Image& img, int channels, std::string* error) {
    int w = 0, h = 0, c = 0;
    unsigned char* pixels = stbi_load(path.c_str(), &w, &h, &c, channels);
    if (!pixels) {
        if (error) *error = path + ": cannot read image (" + stbi_failure_reason() + ")";
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
    if (a.width != b.width || a.height != b.height || a.channels != b.channels || a.empty()) return d;
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
