#pragma once
// Meshing the surfaces into patches P_1..P_n (§1.14): each surface is cut into a grid of
// patches whose edges are at most `maxEdge` long, and patches can later be split 4-way
// (adaptive refinement, "smaller patches where the light changes fast": corners,
// under the table, shadow edges).
//
// Conventions: patch ids are indices into PatchMesh::patches (0..n−1, stable until the
// next refine); vertex ids are indices into PatchMesh::vertices. Vertices are shared
// only by patches of the SAME surface, so smoothing never averages across a corner of
// the room or between a box and the floor it stands on (no light leaks across
// surfaces). Refinement leaves T-vertices (a split patch's edge midpoints lie on the
// edge of an unsplit neighbour); they are handled, not avoided: Patch::outline lists a
// patch's corners AND every vertex lying on its edges, in order, and displayTriangles fans
// such a patch from an extra centre vertex through all of them, so the display mesh is
// conforming: Gouraud interpolation is continuous and no crack shows.
//
// Where a body stands on a surface (the Cornell box's blocks on its floor, the classroom's red
// box and table panels, the lamp's pole): by default (the labs) the grid runs on under it; a
// patch wholly inside the body (the first surface along its normal is met from behind) is
// dropped, and a patch partly inside keeps its polygon for drawing, with `area` the exposed
// area and `centre` the exposed part's centroid (8×8 samples). With MeshConfig::conforming
// (issue 19 item 10) the surface is meshed to fit the body instead: the grid cells its bottom
// edges cross, and one cell around them, are meshed as one region by a constrained Delaunay
// triangulation with the bottom edges (split at the body's own grid points) as constraints,
// angles >= 20.7° and edges <= maxEdge, pairs of triangles merged into quads where well shaped;
// the pieces inside the footprint are dropped, so no patch is part under a body. Where surfaces
// meet (a block on the floor, a wall on the floor, the faces of a block at its corners), the
// two sides are then stitched: each side's vertices on the common edge are put on the other
// side's patch edges (PatchMesh::seamVertices), so the display triangles meet vertex to vertex
// and the rasteriser leaves no pixel open between surfaces (tests/render/
// radiosity_crack_census_test.cpp counts the background pixels enclosed by patches at the
// lab's window size: 0 on every scene; 1 on the Cornell box with stitching off).
#include "core/radiosity/scene.h"

#include <array>
#include <vector>

namespace wb::rad {

struct Patch {
    std::array<int, 4> corners{-1, -1, -1, -1}; // vertex ids, counter-clockwise; [3] = -1 for a triangle
    int cornerCount = 4;                        // 3 or 4
    std::vector<int> outline; // corners plus T-vertices on the edges, counter-clockwise
    // Patches with T-vertices get one extra vertex at their centroid, the apex of their display
    // fan (so every outline vertex is a triangle corner: no T-junction, no crack); −1 otherwise.
    // Its smoothed value is the mean of the patch's outline vertices.
    int centreVertex = -1;
    int surface = 0;          // index into Scene::surfaces
    int group = -1;           // shooting group (PatchMesh::groups), −1 when not grouped
    int level = 0;            // 0 = from the initial grid, +1 per adaptive split
    double area = 0.0;        // m², of the exposed part (see above; the polygon's otherwise)
    glm::dvec3 centre{0.0};   // centroid (area-weighted) of the exposed part, on the patch
    glm::dvec3 normal{0.0};   // unit, the emitting/receiving side
    glm::dvec3 reflectivity{0.0}; // copied from the surface
    glm::dvec3 emission{0.0};     // copied from the surface
    // Corners on the surface's parameter lattice (integers, exact in double): for a quad
    // surface meshed nu × nv, u = x / (nu·kLatticeScale), v = y / (nv·kLatticeScale); for a
    // triangle meshed n per edge, the barycentric pair (x, y) / (n·kLatticeScale). Shared
    // vertices and T-vertices are found on the lattice, never by comparing positions.
    std::array<glm::dvec2, 4> lattice{};
};

// A shooting patch of progressive refinement (Cohen, Greenberg, Immel, Brock 1986 "patches and
// elements"; Cohen et al. 1988 shoot from patches and receive at elements): a block of the fine
// patches (elements) of one surface. It shoots their pooled unshot power from its centroid.
struct ShooterGroup {
    std::vector<int> members; // patch ids
    int surface = 0;
    double area = 0.0;        // Σ member areas
    glm::dvec3 centre{0.0};   // area-weighted centroid (on the surface)
    glm::dvec3 normal{0.0};   // the surface's normal
    glm::dvec3 u{1, 0, 0};    // hemicube axis: the surface's first edge, in its plane
};

// Lattice units per initial grid cell: 2^12, so up to 12 adaptive splits stay on the lattice.
constexpr double kLatticeScale = 4096.0;

struct PatchMesh {
    std::vector<glm::dvec3> vertices;
    std::vector<int> vertexSurface;         // surface each vertex belongs to
    std::vector<glm::dvec2> vertexLattice;  // its lattice coordinates on that surface
    std::vector<glm::ivec2> grid;           // per surface: nu × nv (quads) or n × n (triangles)
    std::vector<Patch> patches;
    std::vector<Surface> surfaces; // copy of the scene's surfaces (patches refer to them)
    bool closed = false;           // copy of Scene::closed
    bool conforming = false;       // copy of MeshConfig::conforming (refinement keeps stitching)
    std::vector<ShooterGroup> groups; // empty unless meshed with shooterEdge > maxEdge
    // Vertices put on a patch's edge where another surface meets it (stitching, see meshScene):
    // `vertex` lies on the outline segment from `a` to `b` at fraction t. Smoothing gives it the
    // value interpolated there (it belongs to one patch, whose own B would make a bump).
    struct SeamVertex {
        int vertex, a, b;
        double t;
    };
    std::vector<SeamVertex> seamVertices;

    std::vector<glm::dvec3> cornersOf(int patch) const; // corner positions
    double totalArea() const;
};

struct MeshConfig {
    double maxEdge = 0.1; // metres: no patch edge longer than this after meshing (> 0)
    // > maxEdge: also group the patches into shooting patches of about this edge (the fine grid
    // is the coarse one subdivided); progressive refinement then shoots per group. 0: no groups.
    double shooterEdge = 0.0;
    // Issue 19 item 10: mesh the surfaces under bodies to the bodies' footprints (constrained
    // Delaunay, see above) and stitch where surfaces meet. Off by default: on, the Cornell box's
    // worst surface against Cycles at lab 08's defaults is 1.33% (rays, short block 2) and
    // 1.38% (hemicubes, short block 1) instead of 0.74% / 0.97%, above issue 19 item 12's 1%
    // (though the grid's own hemicube figure is 1.45-1.65% at 5 of 8 edges within ±7% of the
    // default: docs/radiosity-core.md, "Conforming mesh").
    bool conforming = false;
};

// Aspect ratio of a patch: its longest edge L over its width across that edge, L²/A for a
// quad (a×b rectangle: a/b; square 1) and L²/(2A) for a triangle (right isosceles: 2;
// equilateral: 1.15). The stated bound (issue 19 item 10), checked on every scene's mesh:
//  - quads (grid cells): at most kMaxAspect (a quad surface's cells are at most 1.5 times
//    longer than wide, 2.15 for the end cells of the lamp shade's rim, a 1 cm wide trapezoid
//    with 45° ends);
//  - triangles (where a body stands on a surface, meshed by a constrained Delaunay refinement,
//    and a triangle surface's grid, similar to the surface, the scenes have none): every angle
//    at least kMinTriangleAngleDeg, so L²/(2A) <= 2 / tan(20.7°) = kMaxTriangleAspect (the
//    worst case is the isosceles triangle with two 20.7° angles at its longest edge).
double patchAspect(const PatchMesh& mesh, int patch);
constexpr double kMaxAspect = 2.5;
constexpr double kMinTriangleAngleDeg = 20.7; // asin(sqrt(0.125)) = 20.705°, floored
constexpr double kMaxTriangleAspect = 5.3;    // 2 / tan(20.705°) = 5.29

// Grid-meshes every surface. Validates the scene first (throws std::invalid_argument).
PatchMesh meshScene(const Scene& scene, const MeshConfig& config);

struct RefineConfig {
    // A patch is split when its radiosity differs from a neighbour's on the same surface by
    // more than this fraction of the largest radiosity of the non-emitting patches (max channel).
    double threshold = 0.05;
    int maxLevel = 3;          // no patch is split more than this many times
    double minEdge = 0.005;    // metres: patches with an edge shorter than this stay whole
    std::size_t maxPatches = 20000; // stop splitting at this patch count
};

// Adaptive refinement: splits (4-way, at edge midpoints) the patches whose radiosity `B`
// (one RGB value per patch) jumps against a neighbour, returning the new mesh and filling
// `parentOf` (new patch id -> old patch id) so a solver can start from the old solution.
// Children stay in their parent's shooting group.
// Outlines are recomputed (T-vertices). Returns the number of patches split.
int refineAdaptive(PatchMesh& mesh, const std::vector<glm::dvec3>& B, const RefineConfig& config,
                   std::vector<int>* parentOf = nullptr);

// Triangles (vertex ids, counter-clockwise) covering every patch along its outline, conforming
// across T-vertices; `patchOf` receives the patch id of each triangle. For GL drawing.
std::vector<std::array<int, 3>> displayTriangles(const PatchMesh& mesh,
                                                 std::vector<int>* patchOf = nullptr);

} // namespace wb::rad
