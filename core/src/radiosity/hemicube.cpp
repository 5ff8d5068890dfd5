#include "core/radiosity/hemicube.h"

#include "core/radiosity/closed_forms.h"
#include "core/raytrace/ray.h"

#include <glm/gtc/constants.hpp>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace wb::rad {

namespace {

void checkResolution(int res) {
    if (res < 2 || res > 8192 || res % 2 != 0)
        throw std::invalid_argument("hemicube: resolution " + std::to_string(res) +
                                    " must be even and in 2..8192");
}

// Point on face f at continuous face coordinates (s horizontal in −1..1, w vertical: t in
// −1..1 on the top face, z in 0..1 on the sides), in frame axes (not normalised).
glm::dvec3 facePoint(const HemicubeFrame& fr, HemicubeFace f, double s, double w) {
    switch (f) {
    case HemicubeFace::Top:
        return s * fr.u + w * fr.v + fr.n;
    case HemicubeFace::PosU:
        return fr.u - s * fr.v + w * fr.n;
    case HemicubeFace::NegU:
        return -fr.u + s * fr.v + w * fr.n;
    case HemicubeFace::PosV:
        return fr.v + s * fr.u + w * fr.n;
    case HemicubeFace::NegV:
        return -fr.v - s * fr.u + w * fr.n;
    }
    return fr.n;
}

// Vertical face coordinate of a pixel row's lower edge (row + 0 ) or centre (row + ½).
double vertical(int res, HemicubeFace f, double row) {
    const double px = 2.0 / res;
    return f == HemicubeFace::Top ? -1.0 + row * px : row * px;
}

} // namespace

HemicubeFrame hemicubeFrame(const PatchMesh& mesh, int patch) {
    const Patch& p = mesh.patches.at(static_cast<std::size_t>(patch));
    HemicubeFrame fr;
    fr.n = p.normal;
    fr.origin = rt::offsetRayOrigin(p.centre, p.normal);
    const glm::dvec3 e = mesh.vertices[static_cast<std::size_t>(p.corners[1])] -
                         mesh.vertices[static_cast<std::size_t>(p.corners[0])];
    glm::dvec3 u = e - glm::dot(e, fr.n) * fr.n; // exactly in the plane
    fr.u = glm::normalize(u);
    fr.v = glm::cross(fr.n, fr.u);
    return fr;
}

int faceWidth(int resolution, HemicubeFace) { return resolution; }
int faceHeight(int resolution, HemicubeFace f) {
    return f == HemicubeFace::Top ? resolution : resolution / 2;
}

glm::dvec3 pixelDirection(const HemicubeFrame& frame, int resolution, HemicubeFace f, int col,
                          int row) {
    const double s = -1.0 + (col + 0.5) * 2.0 / resolution;
    return facePoint(frame, f, s, vertical(resolution, f, row + 0.5));
}

void ItemBuffer::resize(int res) {
    checkResolution(res);
    resolution = res;
    for (int f = 0; f < kHemicubeFaces; ++f) {
        const auto hf = static_cast<HemicubeFace>(f);
        faces[static_cast<std::size_t>(f)].assign(
            static_cast<std::size_t>(faceWidth(res, hf)) * static_cast<std::size_t>(faceHeight(res, hf)),
            -1);
    }
}

DeltaFormFactors deltaFormFactors(int resolution, bool exactPixels) {
    checkResolution(resolution);
    DeltaFormFactors t;
    t.resolution = resolution;
    const HemicubeFrame canonical; // u = x, v = y, n = z, origin 0
    const double px = 2.0 / resolution;
    const double dA = px * px;
    const double invPi = 1.0 / glm::pi<double>();
    double sum = 0.0;
    for (int f = 0; f < kHemicubeFaces; ++f) {
        const auto hf = static_cast<HemicubeFace>(f);
        const int w = faceWidth(resolution, hf), h = faceHeight(resolution, hf);
        auto& face = t.faces[static_cast<std::size_t>(f)];
        face.resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
        for (int row = 0; row < h; ++row)
            for (int col = 0; col < w; ++col) {
                double weight;
                if (exactPixels) {
                    const double s0 = -1.0 + col * px, s1 = s0 + px;
                    const double v0 = vertical(resolution, hf, row), v1 = v0 + px;
                    const std::vector<glm::dvec3> sq = {
                        facePoint(canonical, hf, s0, v0), facePoint(canonical, hf, s1, v0),
                        facePoint(canonical, hf, s1, v1), facePoint(canonical, hf, s0, v1)};
                    weight = pointToPolygon(glm::dvec3(0.0), glm::dvec3(0, 0, 1), sq);
                } else {
                    const glm::dvec3 p = pixelDirection(canonical, resolution, hf, col, row);
                    const double d2 = glm::dot(p, p); // x² + y² + 1 (top) or s² + z² + 1
                    // Top face: cos φ_i = cos φ_j = 1/d -> ΔA/(π d⁴); sides: cos φ_i = z/d,
                    // cos φ_j = 1/d -> z ΔA/(π d⁴) (§1.15.2).
                    const double cosWeight = hf == HemicubeFace::Top ? 1.0 : p.z;
                    weight = cosWeight * dA * invPi / (d2 * d2);
                }
                face[static_cast<std::size_t>(row) * static_cast<std::size_t>(w) +
                     static_cast<std::size_t>(col)] = weight;
                sum += weight;
            }
    }
    t.sum = sum;
    return t;
}

void castItemBuffer(const PatchBvh& bvh, const HemicubeFrame& frame, int resolution,
                    ItemBuffer& out, bool parallel) {
    if (out.resolution != resolution) out.resize(resolution);
    const int half = resolution / 2;
    const int rows = resolution + 4 * half; // top rows, then each side's rows
    auto doRow = [&](int r) {
        HemicubeFace f = HemicubeFace::Top;
        int row = r;
        if (r >= resolution) {
            f = static_cast<HemicubeFace>(1 + (r - resolution) / half);
            row = (r - resolution) % half;
        }
        auto& face = out.faces[static_cast<std::size_t>(f)];
        // Neighbouring pixels of the row as one packet (issue 21): one walk of the BVH
        // for up to 8 coherent rays from the same origin, the same patch ids as one by one.
        for (int col = 0; col < resolution; col += rt::kMaxPacket) {
            const int n = std::min(rt::kMaxPacket, resolution - col);
            glm::dvec3 d[rt::kMaxPacket];
            int ids[rt::kMaxPacket];
            for (int j = 0; j < n; ++j)
                d[j] = glm::normalize(pixelDirection(frame, resolution, f, col + j, row));
            bvh.nearestPatches(frame.origin, d, n, ids);
            for (int j = 0; j < n; ++j)
                face[static_cast<std::size_t>(row) * static_cast<std::size_t>(resolution) +
                     static_cast<std::size_t>(col + j)] = ids[j];
        }
    };
    if (parallel)
        tbb::parallel_for(0, rows, doRow);
    else
        for (int r = 0; r < rows; ++r) doRow(r);
}

void accumulate(const ItemBuffer& items, const DeltaFormFactors& table, int patchCount, int self,
                std::vector<float>& out) {
    if (items.resolution != table.resolution)
        throw std::invalid_argument("hemicube accumulate: item buffer resolution " +
                                    std::to_string(items.resolution) + " but delta table " +
                                    std::to_string(table.resolution));
    // Sum in double: at 1024² a float sum of ~3 million terms would lose ~1e-4.
    std::vector<double> acc(static_cast<std::size_t>(std::max(patchCount, 0)), 0.0);
    for (int f = 0; f < kHemicubeFaces; ++f) {
        const auto& ids = items.faces[static_cast<std::size_t>(f)];
        const auto& w = table.faces[static_cast<std::size_t>(f)];
        if (ids.size() != w.size())
            throw std::invalid_argument("hemicube accumulate: face " + std::to_string(f) +
                                        " has " + std::to_string(ids.size()) +
                                        " items for " + std::to_string(w.size()) + " weights");
        for (std::size_t k = 0; k < ids.size(); ++k) {
            const std::int32_t id = ids[k];
            if (id >= 0 && id < patchCount) acc[static_cast<std::size_t>(id)] += w[k];
        }
    }
    if (self >= 0 && self < patchCount) acc[static_cast<std::size_t>(self)] = 0.0;
    out.resize(acc.size());
    for (std::size_t j = 0; j < acc.size(); ++j) out[j] = static_cast<float>(acc[j]);
}

void hemicubeRow(const PatchMesh& mesh, const PatchBvh& bvh, const DeltaFormFactors& table,
                 int i, std::vector<float>& out, bool parallel) {
    ItemBuffer items;
    castItemBuffer(bvh, hemicubeFrame(mesh, i), table.resolution, items, parallel);
    accumulate(items, table, static_cast<int>(mesh.patches.size()), i, out);
}

} // namespace wb::rad
