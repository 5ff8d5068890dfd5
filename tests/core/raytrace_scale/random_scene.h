#pragma once
// What the tracer's property tests share: a seeded random point in a cube, and a scene of
// every bounded primitive kind at a scale (the walks' and filters' hard cases at 1, 1e-30
// and 1e25), with an unbounded plane under it.
#include "core/raytrace/box.h"
#include "core/raytrace/cylinder.h"
#include "core/raytrace/plane.h"
#include "core/raytrace/quadric.h"
#include "core/raytrace/scene.h"
#include "core/raytrace/smooth_triangle.h"
#include "core/raytrace/sphere.h"
#include "core/raytrace/triangle.h"

#include <glm/glm.hpp>

#include <limits>
#include <random>

namespace wb::test {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Each coordinate uniform in [lo, hi).
inline glm::dvec3 rnd3(std::mt19937_64& g, double lo, double hi) {
    std::uniform_real_distribution<double> u(lo, hi);
    return {u(g), u(g), u(g)};
}

// n primitives of every bounded kind in turn (spheres twice in seven: the leaves' vector
// test wants several in a leaf) at scale `s` around the origin, all of material 0, then a
// plane z = −11s facing +z.
inline void mixedScene(wb::rt::Scene& sc, int n, std::mt19937_64& g, double s) {
    using namespace wb::rt;
    std::uniform_real_distribution<double> r(0.05 * s, 0.6 * s);
    for (int i = 0; i < n; ++i) {
        const glm::dvec3 c = rnd3(g, -10 * s, 10 * s);
        switch (i % 7) {
        case 0:
        case 6:
            sc.add(Sphere(c, r(g)), 0);
            break;
        case 1:
            sc.add(Cone(c, r(g), c + rnd3(g, -s, s) + glm::dvec3(0.01 * s), r(g)), 0);
            break;
        case 2:
            sc.add(Triangle(c, c + rnd3(g, -s, s), c + rnd3(g, -s, s)), 0);
            break;
        case 3:
            sc.add(SmoothTriangle(c, c + rnd3(g, -s, s), c + rnd3(g, -s, s), rnd3(g, -1, 1),
                                  rnd3(g, -1, 1), rnd3(g, -1, 1)),
                   0);
            break;
        case 4:
            sc.add(Quadric(Quadric::Kind::Ellipsoid, c, glm::dvec3(r(g), r(g), r(g))), 0);
            break;
        default:
            sc.add(Box::axisAligned(c, c + glm::abs(rnd3(g, 0.1 * s, s))), 0);
            break;
        }
    }
    sc.add(Plane({0, 0, -11 * s}, {0, 0, 1}), 0);
}

} // namespace wb::test
