#pragma once
// Triangles for the rasterizer from the tracer's scene: spheres, cylinders and cones,
// cut quadrics, boxes, convex polyhedra, rectangles, triangles and (clipped) planes,
// each tessellated finely enough for its size on the screen: n segments around a
// circle of r pixels put the chord at most r·(1 − cos(π/n)) ≈ r·π²/(2n²) off the true
// outline, so n = π·sqrt(r / maxError) keeps the outline within maxError pixels.
// No GL here; the lab uploads the arrays.
#include "lab_scenes.h"
#include "view_camera.h"

#include <vector>

namespace wb {

struct MeshBatch {
    int material = 0;          // index into Scene::materials
    std::vector<float> pos;    // x y z per vertex, three vertices per triangle
    std::vector<float> normal; // unit normal per vertex (outward / front side)
};

struct TessellationStats {
    long long triangles = 0;
    int skipped = 0;        // primitives the rasterizer cannot draw (counted, not hidden)
    double level = 1.0;     // < 1: tessellated coarser than maxErrorPixels to fit the budget
    long long standIns = 0; // primitives beyond the budget, drawn as one bounding box
    long long budget = 0;   // the triangle budget used
};

struct TessellationOptions {
    double maxErrorPixels = 0.5; // outline error bound of curved surfaces, pixels
    double gridPixels = 24.0;    // flat faces are split into cells of about this size, so
                                 // per-vertex (Gouraud) lighting samples point lights densely
    int minSegments = 8, maxSegments = 128; // around a circle
    double planeExtent = 0.0;               // half size of the square drawn for an infinite plane
                                            // (0: 40× the bounded part's radius: near the horizon)
    // At most this many triangles (each 72 bytes of vertex arrays: 3 × (position, normal)
    // floats), so any scene the tracer can load opens with bounded memory (500 k: 36 MB;
    // the SPD balls 4 need 414 k). It bounds memory, not fill: 15,000 spheres drawn over
    // one another still cost seconds per frame on a software rasterizer.
    // Over it the whole scene is tessellated coarser (down to 4 segments around a circle);
    // what still does not fit is drawn as one bounding box. Minimum 1000.
    long long maxTriangles = 500000;
};

// Tessellates every primitive for the view `cam` (its pixel size sets the level), within
// opt.maxTriangles (stats say whether it coarsened or drew stand-ins).
std::vector<MeshBatch> tessellate(const rt::Scene& scene, const ViewCamera& cam,
                                  const TessellationOptions& opt, TessellationStats* stats);

// Centre and radius of the bounded primitives (unbounded ones ignored; radius 1 if none).
void sceneBounds(const rt::Scene& scene, glm::dvec3& centre, double& radius);

} // namespace wb
