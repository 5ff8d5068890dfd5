#pragma once
// Isolated outlier pixels ("speckles") in a rendered image. A pixel is an outlier when,
// in some channel, it lies more than `threshold` outside the range [min, max] of its 8
// neighbours (interior pixels only): a single pixel far brighter or darker than every
// neighbour, which no edge, shadow boundary or highlight of a surface larger than a
// pixel produces (those have at least one neighbour on their side).
#include "core/image.h"

#include <algorithm>
#include <vector>

namespace wb::test {

struct Outlier {
    int x = 0, y = 0;
    int excess = 0; // how far outside the neighbours' range, 0..255
};

inline std::vector<Outlier> isolatedOutliers(const Image& img, int threshold) {
    std::vector<Outlier> out;
    const int ch = std::min(img.channels, 3);
    for (int y = 1; y + 1 < img.height; ++y)
        for (int x = 1; x + 1 < img.width; ++x) {
            int worst = 0;
            for (int c = 0; c < ch; ++c) {
                int lo = 255, hi = 0;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        if (dx == 0 && dy == 0) continue;
                        const int v = img.at(x + dx, y + dy)[c];
                        lo = std::min(lo, v);
                        hi = std::max(hi, v);
                    }
                const int v = img.at(x, y)[c];
                worst = std::max({worst, lo - v, v - hi});
            }
            if (worst > threshold) out.push_back({x, y, worst});
        }
    return out;
}

} // namespace wb::test
