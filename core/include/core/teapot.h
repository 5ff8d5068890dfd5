#pragma once
// The Utah teapot as Martin Newell drew it in 1975: 32 bicubic Bezier patches on 306
// control points (z up, standing on z = 0, 3.15 high, spout along +x). Evaluated with
// core/bezier (de Casteljau), so its normals at the lid's and the bottom's poles come
// from evalPatch's limit. The course's lab 3 asks for glutSolidTeapot, which needs GLUT
// and so cannot run under OSMesa; this is the same shape from its published data.
#include "core/bezier.h"
#include "core/mesh.h"

#include <array>
#include <vector>

namespace wb {

constexpr int kTeapotPoints = 306;
constexpr int kTeapotPatches = 32;
constexpr double kTeapotHeight = 3.15; // the knob's top; the bottom is z = 0

// The control points as published, in order (index 0 is the published point 1).
const std::array<glm::dvec3, kTeapotPoints>& teapotControlPoints();
// Each patch's 16 one-based point numbers as published: 4 rows of 4.
const std::array<std::array<int, 16>, kTeapotPatches>& teapotPatchIndices();

// The part a patch belongs to: "rim" 0-3, "body" 4-11, "handle" 12-15, "spout" 16-19,
// "lid" 20-27, "bottom" 28-31.
const char* teapotPart(int patch);

// The 32 patches in BezierPatch's layout (glMap2f's with u stride 3, v stride 12): a
// published row is one row of the net (u along it). Patches whose du × dv points into
// the pot in that order get their rows reversed, so that every normal points outwards
// and every triangle of teapotMesh is counter-clockwise seen from outside.
const std::vector<BezierPatch>& teapotPatches();

// A triangle mesh of the teapot: an (n+1)×(n+1) grid per patch from evalPatch (points,
// unit normals, texture coordinates (u, v) of the patch, tangents along du), two
// triangles per grid cell; triangles that collapse at a pole are left out. n >= 1,
// otherwise std::invalid_argument.
Mesh teapotMesh(int n);

} // namespace wb
