#pragma once
// Lab 01: affine maps (practical 1, lab 1). 2D: a line Λ through random points K, L,
// a polygon (the letter F, so a mirror image cannot pass for a rotation) and its
// mirror image / shadow from a light at infinity / shadow from a point light S, each
// ONE homogeneous 3×3 matrix applied to all vertices in one 3×n product. 3D: the same
// three maps for a plane Ax+By+Cz+D=0 as 4×4 matrices given to glMultMatrixd.
#include "common/lab.h"
#include "core/affine.h"

#include <glm/glm.hpp>

#include <array>
#include <memory>
#include <vector>

namespace wb {

enum class AffineMode { Mirror = 1, ShadowDirectional = 2, ShadowPoint = 3 };

// Everything the lab shows; plain data so tests can set it and read it.
struct AffineState {
    AffineMode mode = AffineMode::Mirror;
    bool view3d = false; // false: the 2D view of lab 1; true: the plane of practicals 1.2, 1.3
    unsigned seed = 1;   // K and L come from this seed (`r` adds one), reproducible
    glm::dvec2 k{0, 0}, l{1, 0};       // the two random points of the line Λ (set by reseed)
    double lightAngle = 25.0;          // degrees between 2D rays l and the normal of Λ towards it
    glm::dvec2 light{0, 0};            // 2D point light S (placed by reseed, moved by arrows)
    Plane plane{{0, 1, 0}, 0};         // 3D receiver / mirror plane A x + B y + C z + D = 0
    glm::dvec3 light3{-1.5, 9.0, 4.5}; // 3D point light S
    glm::dvec3 lightDir3{0.3, -1, -0.8}; // 3D direction of the rays of the light at infinity
};

// Puts K, L (and S) for `seed`: K, L uniform in the view, re-drawn until Λ keeps clear of
// the polygon, its mirror image stays in view and S lies on the polygon's side.
void reseed(AffineState& s, unsigned seed);

// The polygon in world coordinates (2D view) and a triangulation of it (index triples).
const std::vector<glm::dvec2>& affinePolygon();
const std::vector<std::array<int, 3>>& affinePolygonTriangles();

Line2 affineLine(const AffineState& s);          // Λ through K and L
glm::dvec2 affineLightDir(const AffineState& s); // 2D rays' direction l (unit)
glm::dmat3 affineMatrix2d(const AffineState& s); // the mode's 3×3 matrix
glm::dmat4 affineMatrix3d(const AffineState& s); // the mode's 4×4 matrix

// The 2D view: world window half-height (before zoom); x follows the aspect ratio.
constexpr double kAffineHalfHeight = 9.0;
// Pixel (x right, y down, centre of pixel at +0.5) to world coordinates of the 2D view.
glm::dvec2 affinePixelToWorld(int width, int height, float zoom, double px, double py);

// Exact colours (glColor3ub, no lighting or blending in the 2D view) so tests can find them.
constexpr std::array<unsigned char, 3> kPolygonColor{60, 110, 220};
constexpr std::array<unsigned char, 3> kImageColor{220, 60, 60};
constexpr std::array<unsigned char, 3> kShadowColor{40, 40, 40};
constexpr std::array<unsigned char, 3> kLineColor{0, 150, 0};
constexpr double kShadowLineWidth = 5.0; // pixels

std::unique_ptr<Lab> makeAffineLab();
// The lab working on `observe` (owned by the caller), so tests can set and read its state.
std::unique_ptr<Lab> makeAffineLab(AffineState* observe);

} // namespace wb
