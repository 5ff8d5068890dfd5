#include "hemicube_view.h"

#include <algorithm>

namespace wb {

namespace {

// The cross with u to the right and v up (core's column and row directions).
glm::ivec2 unfoldedCore(int res, rad::HemicubeFace f, int col, int row) {
    const int h = res / 2, last = 2 * res - 1;
    // Top pixel (col, row) looks along s·u + t·v + n: u to the right, v up, centred.
    // A side's row 0 is its horizon: the outer edge of the cross; its last row touches
    // the top face. Columns follow the direction of s in core's layout table.
    switch (f) {
    case rad::HemicubeFace::Top: return {h + col, h + row};
    case rad::HemicubeFace::PosV: return {h + col, last - row};           // v + s·u + z·n
    case rad::HemicubeFace::NegV: return {h + (res - 1 - col), row};      // −v − s·u + z·n
    case rad::HemicubeFace::PosU: return {last - row, h + (res - 1 - col)}; // u − s·v + z·n
    default: return {row, h + col};                                        // −u + s·v + z·n
    }
}

} // namespace

glm::ivec2 unfoldedPosition(int res, rad::HemicubeFace f, int col, int row) {
    // Mirrored: as the patch sees it, looking along n with v up, right is n × v = −u.
    const glm::ivec2 p = unfoldedCore(res, f, col, row);
    return {2 * res - 1 - p.x, p.y};
}

Image unfoldHemicube(const rad::ItemBuffer& items, const std::vector<glm::vec3>& patchColour,
                     const glm::vec3& background) {
    const int res = items.resolution, size = 2 * res;
    Image img(size, size, 3);
    auto toByte = [](float x) { return uint8_t(std::clamp(x, 0.0f, 1.0f) * 255.0f + 0.5f); };
    const uint8_t bg[3] = {toByte(background.x), toByte(background.y), toByte(background.z)};
    for (size_t i = 0; i < img.data.size(); i += 3) std::copy(bg, bg + 3, &img.data[i]);
    for (int f = 0; f < rad::kHemicubeFaces; ++f) {
        const auto face = rad::HemicubeFace(f);
        const int w = rad::faceWidth(res, face), hgt = rad::faceHeight(res, face);
        const std::vector<int32_t>& ids = items.faces[size_t(f)];
        if (ids.size() != size_t(w) * size_t(hgt)) continue;
        for (int row = 0; row < hgt; ++row)
            for (int col = 0; col < w; ++col) {
                const int32_t id = ids[size_t(row) * size_t(w) + size_t(col)];
                if (id < 0 || size_t(id) >= patchColour.size()) continue;
                const glm::ivec2 p = unfoldedPosition(res, face, col, row);
                uint8_t* px = img.at(p.x, size - 1 - p.y);
                const glm::vec3& c = patchColour[size_t(id)];
                px[0] = toByte(c.x);
                px[1] = toByte(c.y);
                px[2] = toByte(c.z);
            }
    }
    return img;
}

} // namespace wb
