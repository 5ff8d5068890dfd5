#pragma once
// The hemicube (§1.15.2, Cohen & Greenberg 1985) on the CPU, split so that the lab can draw
// the same item buffer with OpenGL and share the rest:
//   1. HemicubeFrame: where the hemicube sits (patch centre) and its axes u, v, n;
//   2. ItemBuffer: 5 faces of patch ids (−1 = nothing), filled here by casting one ray per
//      pixel centre through PatchBvh (castItemBuffer), or by GL (lab 08);
//   3. DeltaFormFactors: the per-pixel weights ΔA/(π d⁴) on the top face and z·ΔA/(π d⁴) on
//      the sides (d² = x² + y² + 1 in hemicube units, half-edge 1), tabulated once per
//      resolution;
//   4. accumulate(): F_ij = Σ of the weights of the pixels holding j (15.21).
//
// Layout (the GL path must match it):
//   face order Top, +U, −U, +V, −V (HemicubeFace). `resolution` = pixels along a full face
//   edge, even, >= 2. Top face: resolution × resolution pixels; side faces: resolution wide,
//   resolution/2 high (the upper half of a 90° view; row 0 touches the patch's plane).
//   Pixels are stored row-major, row 0 first, rows bottom-to-top (glReadPixels order).
//   Pixel (col, row) has its centre at s = −1 + (col + ½)·2/res horizontally and
//   t = −1 + (row + ½)·2/res (top) or z = (row + ½)·2/res (sides) vertically.
//   Each face is a camera at the frame origin with a 90° square frustum; the pixel direction
//   column is the definition, the camera columns say how GL reproduces it:
//     face   looks along   up     GL right (= look × up)   pixel direction (s→col, t/z→row)
//     Top    +n            +v     −u  (!)                  s·u + t·v + n
//     +U     +u            +n     −v                       u − s·v + z·n
//     −U     −u            +n     +v                       −u + s·v + z·n
//     +V     +v            +n     +u                       v + s·u + z·n
//     −V     −v            +n     −u                       −v − s·u + z·n
//   i.e. gluLookAt(origin, origin + look, up) with glFrustum(−a, a, 0, a, a, far) on a
//   res × res/2 viewport for the sides (columns and rows as glReadPixels returns them). For the
//   top, gluLookAt(origin, origin + n, +v) with glFrustum(−a, a, −a, a, a, far) gives the
//   columns mirrored (GL's right is −u): mirror them after glReadPixels, or equivalently use
//   up = −v and mirror the rows. (The weights are symmetric, so only the ids' places differ.)
#include "core/radiosity/patch_bvh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace wb::rad {

enum class HemicubeFace { Top = 0, PosU = 1, NegU = 2, PosV = 3, NegV = 4 };
constexpr int kHemicubeFaces = 5;

struct HemicubeFrame {
    glm::dvec3 origin{0.0};       // eye: the patch centre, lifted off the surface by offsetRayOrigin
    glm::dvec3 u{1, 0, 0}, v{0, 1, 0}, n{0, 0, 1}; // right-handed orthonormal, n = patch normal
};

// The frame of a patch: origin at its centre, n its normal, u along its first edge.
HemicubeFrame hemicubeFrame(const PatchMesh& mesh, int patch);

// Width and height in pixels of face f at a resolution.
int faceWidth(int resolution, HemicubeFace f);
int faceHeight(int resolution, HemicubeFace f);

// Unnormalised direction (frame axes) through the centre of pixel (col, row) of face f.
glm::dvec3 pixelDirection(const HemicubeFrame& frame, int resolution, HemicubeFace f, int col,
                          int row);

struct ItemBuffer {
    int resolution = 0;                                   // even, >= 2
    std::array<std::vector<std::int32_t>, kHemicubeFaces> faces; // patch id or −1 per pixel
    void resize(int res);                                 // sizes the faces, fills −1
};

struct DeltaFormFactors {
    int resolution = 0;
    std::array<std::vector<double>, kHemicubeFaces> faces; // weight per pixel, same layout
    double sum = 0.0; // Σ of all weights: 1 − O(1/res²) (the midpoint rule of the hemisphere)
};

// The table for one resolution (throws std::invalid_argument unless even and in 2..8192).
// `exactPixels` = false: the course's midpoint formula; true: the exact form factor of each
// pixel square (pointToPolygon), which sums to 1 up to rounding.
DeltaFormFactors deltaFormFactors(int resolution, bool exactPixels = false);

// How castItemBuffer finds each pixel's patch; both give nearestPatch's id for the pixel's ray
// (the same ray, bit for bit), so the item buffers are identical.
//   Raster: per face, each triangle's edge planes through the eye as edge functions over the
//     pixels (a conservative filter with a relative error bound), the watertight test only
//     where two triangles compete or a pixel lies within the bound of an edge (issue 21);
//   Packets: 8 neighbouring pixels of a row traced as one BVH packet.
enum class HemicubeCast { Raster, Packets };

// The CPU item buffer: one ray per pixel centre from frame.origin, nearest front-facing patch.
// Parallel (TBB: faces for Raster, rows for Packets) when `parallel`.
void castItemBuffer(const PatchBvh& bvh, const HemicubeFrame& frame, int resolution,
                    ItemBuffer& out, bool parallel = true,
                    HemicubeCast method = HemicubeCast::Raster);

// Form-factor row from an item buffer (CPU or GL): out[j] = Σ weight(pixel) over pixels with id
// j; ids outside 0..patchCount−1 (background −1) are skipped, `self` is forced to 0. out is
// resized to patchCount. Throws std::invalid_argument if the resolutions differ.
void accumulate(const ItemBuffer& items, const DeltaFormFactors& table, int patchCount, int self,
                std::vector<float>& out);

// Convenience: frame + castItemBuffer + accumulate for patch i.
void hemicubeRow(const PatchMesh& mesh, const PatchBvh& bvh, const DeltaFormFactors& table,
                 int i, std::vector<float>& out, bool parallel = true);

} // namespace wb::rad
