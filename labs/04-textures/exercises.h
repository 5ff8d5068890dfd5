#pragma once
// Lab 04 - textures (§2.4, §1.5.3) as graded tasks: a sphere and a torus drawn by hand with
// their texture coordinates (task ④: no gluQuadric, the seam and the poles yours to get
// right), and the sphere-map coordinates OpenGL's GL_SPHERE_MAP texgen computes for a
// mirror (task ⑤). You write the bodies in exercises.cpp; with `e` on the lab draws your
// meshes (the reference as a ghost) and `./wb check lab04` grades them, the sphere map
// against OpenGL's own texgen.
#include "common/exercise.h"

#include <glm/glm.hpp>

#include <vector>

namespace wb::lab04 {

// A triangle mesh as the lab draws it (glDrawElements(GL_TRIANGLES)): per vertex a position,
// a UNIT outward normal and texture coordinates (s, t) in [0, 1]²; indices three per
// triangle, counter-clockwise seen from outside.
struct Mesh {
    std::vector<glm::dvec3> positions;
    std::vector<glm::dvec3> normals;
    std::vector<glm::dvec2> texCoords;
    std::vector<unsigned> indices;
};

// ③ (§2.4 task ③: a texture on a flat object; the lab's `w` and `f` keys) Which texel
// GL_NEAREST samples. A texture row has `size` texels (1..4096), texel i covering
// s in [i/size, (i+1)/size). For any s (-100..100; a flat object's coordinates may run
// past [0, 1] to repeat the image):
//   repeat = true  (GL_REPEAT): only the fraction of s counts, s - floor(s) (also for
//                  negative s: -0.25 -> 0.75), then i = floor(fraction·size);
//   repeat = false (GL_CLAMP_TO_EDGE): i = floor(s·size) clamped to 0..size-1 (s = 1 is
//                  the last texel, not one past it).
int texelIndex(double s, int size, bool repeat);

// ④ (§2.4 task ④) The sphere of `radius` (0.1..10) about the origin, poles on the y axis,
// on a grid of `slices` (3..256) around by `stacks` (2..256) from pole to pole:
//   s = longitude: 0 on +z, growing towards +x (x = sin 2πs, z = cos 2πs), 1 back on +z;
//   t = latitude from the south pole (t = 0, y = -radius) to the north pole (t = 1).
// The seam: the column s = 1 is a second copy of the column s = 0 (same positions, s = 1),
// so that no triangle runs from s ≈ 1 back to s = 0 (it would smear the whole texture
// across one slice). The poles: every triangle touching a pole spans one slice in s (give
// each pole vertex the s of its column, or of the slice's middle). Every grid cell is
// covered once: slices × stacks cells, two triangles each (one at a pole is enough).
Mesh sphereMesh(double radius, int slices, int stacks);

// ④ The torus around the y axis: the tube's centre circle of radius R in the plane y = 0,
// the tube's radius r (0 < r < R <= 10), `rings` (3..256) around the y axis by `sides`
// (3..256) around the tube:
//   s around the y axis as the sphere's longitude (0 on +z, towards +x);
//   t around the tube: 0 on the outer equator (farthest from the axis), growing upwards
//   (t = 1/4 on the top of the tube).
// Seams in s AND in t (copies of the first column and of the first row). The normal points
// from the tube's centre circle to the vertex.
Mesh torusMesh(double R, double r, int rings, int sides);

// ⑤ (§2.4 task ⑤, §1.5.3) The sphere-map coordinates OpenGL's GL_SPHERE_MAP texgen gives a
// vertex with eye-space position `eyePos` (not the eye itself) and UNIT eye-space normal n:
//   u = eyePos/|eyePos|, f = u - 2n(n·u), m = 2√(fx² + fy² + (fz + 1)²),
//   s = fx/m + ½,  t = fy/m + ½.
// Degenerate: f = (0, 0, -1) (m = 0: looking straight through the map's blind spot) has
// the whole rim of the disc as its answer - return any point (s, t) with
// (2s - 1)² + (2t - 1)² = 1, never a NaN.
glm::dvec2 sphereMap(const glm::dvec3& eyePos, const glm::dvec3& n);

// The exercise table, in task order.
struct Table {
    int (*texelIndex)(double, int, bool);
    Mesh (*sphereMesh)(double, int, int);
    Mesh (*torusMesh)(double, double, int, int);
    glm::dvec2 (*sphereMap)(const glm::dvec3&, const glm::dvec3&);
};

} // namespace wb::lab04
