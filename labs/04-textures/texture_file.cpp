#include "texture_file.h"

#include "core/i18n.h"
#include <stb_image.h>

namespace wb {

Image checkerboard(int width, int height, int cell) {
    Image img(width, height, 3);
    if (cell < 1) cell = 1;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const bool on = ((x / cell) + (y / cell)) % 2 == 0;
            uint8_t* p = img.at(x, y);
            p[0] = on ? 255 : 0;
            p[1] = 0;
            p[2] = on ? 255 : 0;
        }
    return img;
}

bool loadTextureImage(const std::string& path, Image& out, std::string& message) {
    Image img;
    std::string err;
    // Look at the header first: a hostile file claiming 60000×60000 must not make us allocate 10
    // GB.
    int w = 0, h = 0, c = 0;
    bool ok = true;
    if (stbi_info(path.c_str(), &w, &h, &c) &&
        (w < 1 || h < 1 || w > kMaxTextureSide || h > kMaxTextureSide)) {
        img.width = w;
        img.height = h;
    } else {
        ok = readImage(path, img, 3, &err);
    }
    if (ok && (img.width < 1 || img.height < 1 || img.width > kMaxTextureSide ||
               img.height > kMaxTextureSide)) {
        err = trf("%s: %dx%d is not a usable texture size (1..%d)", path.c_str(), img.width,
                  img.height, kMaxTextureSide);
        ok = false;
    }
    if (!ok) {
        out = checkerboard(64, 64, 8);
        message = err.empty() ? trf("%s: cannot read; using a checkerboard instead", path.c_str())
                              : trf("%s; using a checkerboard instead", err.c_str());
        return false;
    }
    out = std::move(img);
    message.clear();
    return true;
}

} // namespace wb
