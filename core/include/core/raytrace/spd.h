#pragma once
// Scenes in code: Eric Haines' Standard Procedural Databases "balls" (sphereflake) and
// "jacks" generators with their view settings, and the small scenes of lab 7's
// timing experiment and the course seeds, all as NFF documents (write them with
// writeNff, render them with toScene).
#include "core/raytrace/nff.h"

#include <string>
#include <vector>

namespace wb::rt {

// Sphereflake of size factor 1..6: (9^(SF+1) − 1)/8 spheres (7,381 at SF 4), each
// parent with 9 children of 1/3 its radius, plus the floor square and 3 lights; the
// SPD view (from 2.1 1.3 1.7, angle 45, 512×512). Throws std::invalid_argument.
NffDocument spdBalls(int sizeFactor);
// Recursive jacks of size factor 1..6: (8^SF − 1)/7 jacks of 3 cylinders and 6
// spheres, 8 half-size copies per level; the SPD view (from 0 0 −8, angle 25).
NffDocument spdJacks(int sizeFactor);
// Gears of size factor 1..6: sf³ meshing gears of 36 teeth (faces are concave
// 144-gons, 144 side rectangles each), every fifth transparent (kt 0.8, ior 1.1),
// on a mirror-like ground square; 5 lights; the SPD view (from −1.1 −2.1 2.6, angle 45).
NffDocument spdGears(int sizeFactor);
// The other SPD databases, size factor 1..6, each with the SPD's view and lights:
NffDocument spdTetra(int sizeFactor);   // 4^SF triangles of a recursive tetrahedron
NffDocument spdRings(int sizeFactor);   // 5·SF(SF+1)(2SF+1) cylinders and spheres, a wall
NffDocument spdLattice(int sizeFactor); // (SF+1)³ shiny spheres joined by 3SF(SF+1)² cylinders
NffDocument spdShells(int sizeFactor);  // 180·2^SF + 1 overlapping spheres on a spiral
NffDocument spdTree(int sizeFactor);    // 2^(SF+1) − 1 cones and spheres, a field square
// 2·4^SF triangles of a fractal mountain (own Gaussian hash: the SPD's statistics, not
// its exact heights) and 4 touching glass spheres (kt 0.9, ior 1.5).
NffDocument spdMount(int sizeFactor);
// Newell's teapot meshed n×n per patch (n = 2^(SF+1)), two smooth triangles (`pp`) per
// cell, less those collapsed at the poles, on a checkerboard of n×n squares; two lights.
// View, lights and colours are the project's own (see spd.cpp).
NffDocument spdTeapot(int sizeFactor);
// Counts by the SPD formulas, for tests and the bench.
long long spdBallsSpheres(int sizeFactor); // (9^(SF+1) − 1)/8
long long spdJacksCount(int sizeFactor);   // (8^SF − 1)/7

// The generators by name: balls, jacks, gears, tetra, rings, lattice, shells, tree, mount,
// teapot.
std::vector<std::string> spdSceneNames();
// spdScene("gears", 2) == spdGears(2); std::invalid_argument for an unknown name or size.
NffDocument spdScene(const std::string& name, int sizeFactor);

// Lab 7's timing experiment: one sphere, and two spheres (one mirror) over a floor.
NffDocument oneSphereScene();
NffDocument twoSpheresScene();

} // namespace wb::rt
