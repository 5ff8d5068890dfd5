#pragma once
// Lab 04's exercise mode in the window (issue 18): with `e` on the sphere and torus are your
// meshes (exercises.cpp: positions, normals, texture coordinates), textured and lit as the
// lab draws its own, with the reference's mesh over them as a ghost wireframe; the mirror
// object gets its texture coordinates from your sphere-map formula instead of GL's texgen.
#include "common/exercise_mode.h"
#include "exercises.h"

#include <optional>

namespace wb {

// Draws your sphere (torus = false: radius, slices, stacks = a, n, m) or torus (R, r, rings,
// sides = a, b, n, m) with the current texture and lighting, then the reference's as a
// ghost wireframe. False (nothing drawn) when your function is not callable.
bool drawExerciseMesh(const ex::ExerciseMode& mode, bool torus, double a, double b, int n, int m);

// Your sphere or torus (arguments as above) when on and callable, with every index in range;
// nullopt otherwise. A student handout has no meshes of its own and draws these instead.
std::optional<lab04::Mesh> exerciseMesh(const ex::ExerciseMode& mode, bool torus, double a,
                                        double b, int n, int m);

// Whether the mirror is to use your sphere map (04.spheremap callable).
bool exerciseSphereMapReady(const ex::ExerciseMode& mode);
// Draws the mesh arrays (float xyz positions and normals, indices) with texture coordinates
// from your sphereMap of each vertex's eye-space position and normal under the current
// modelview (what GL_SPHERE_MAP texgen would compute); texgen must be off.
void drawWithExerciseSphereMap(const ex::ExerciseMode& mode, const float* positions,
                               const float* normals, size_t vertices, const unsigned* indices,
                               size_t count);

} // namespace wb
