#pragma once
// An 8-bit RGB(A) image in memory, top row first, and PNG I/O through stb.
#include <cstdint>
#include <string>
#include <vector>

namespace wb {

struct Image {
    int width = 0;             // pixels
    int height = 0;            // pixels
    int channels = 3;          // 3 = RGB, 4 = RGBA
    std::vector<uint8_t> data; // width*height*channels bytes, row 0 is the top row

    Image() = default;
    Image(int w, int h, int c = 3) : width(w), height(h), channels(c), data(size_t(w) * h * c, 0) {}
    uint8_t* at(int x, int y) { return &data[(size_t(y) * width + x) * channels]; }
    const uint8_t* at(int x, int y) const { return &data[(size_t(y) * width + x) * channels]; }
    bool empty() const { return data.empty(); }
};

// Writes a PNG; returns false and fills `error` (naming the file and the reason) on
// failure. Every write is checked (a full disk, /dev/full, a read-only file all fail).
// A regular file is written to a temporary file in the same directory and renamed
// over the name, so a failed write never leaves a truncated PNG under the real name;
// a device or pipe (/dev/stdout) is written in place.
bool writePng(const std::string& path, const Image& img, std::string* error = nullptr);
// Reads a PNG (or any format stb_image knows) as RGB or RGBA; `channels` 0 keeps the file's.
bool readImage(const std::string& path, Image& img, int channels, std::string* error = nullptr);

// Per-pixel absolute channel difference of two same-sized images.
struct ImageDiff {
    int maxDiff = 0;       // largest |a-b| over all channels, 0..255
    double meanDiff = 0.0; // mean |a-b| over all channels, 0..255
    bool sameSize =
        false; // false: sizes or channel counts differ, the other fields are meaningless
};
ImageDiff compareImages(const Image& a, const Image& b);

} // namespace wb
