// Issue 12 point 12: every SPD generator of the project (balls, jacks, gears, tetra,
// rings, lattice, shells, tree, mount, teapot) is in the suite: object counts by the SPD's
// formulas, an exact NFF round trip, every polygon triangulated without overlap, and a
// small render: no NaN, sane ray counts, a picture that is not just the background.
#include "core/raytrace/bvh.h"
#include "core/raytrace/parallel_render.h"
#include "core/raytrace/phong_model.h"
#include "core/raytrace/polygon.h"
#include "core/raytrace/spd.h"
#include "core/teapot.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <set>
#include <sstream>

using namespace wb::rt;

namespace {

struct Counts {
    long long spheres = 0, cones = 0, polygons = 0, polygonVertices = 0;
};

Counts count(const NffDocument& d) {
    Counts c;
    for (const NffObject& o : d.objects) {
        if (o.kind == NffObject::Kind::Sphere) ++c.spheres;
        if (o.kind == NffObject::Kind::Cone) ++c.cones;
        if (o.kind == NffObject::Kind::Polygon || o.kind == NffObject::Kind::PatchPolygon) {
            ++c.polygons;
            c.polygonVertices += (long long)o.vertices.size();
        }
    }
    return c;
}

long long pow(long long b, int e) {
    long long p = 1;
    while (e-- > 0)
        p *= b;
    return p;
}

// Newell's vector area: |it| is the area of a planar polygon, whatever its shape.
glm::dvec3 vectorArea(const std::vector<glm::dvec3>& v) {
    glm::dvec3 n(0.0);
    for (size_t i = 0; i < v.size(); ++i)
        n += glm::cross(v[i], v[(i + 1) % v.size()]);
    return 0.5 * n;
}

} // namespace

TEST_CASE("spd: object counts follow the SPD formulas", "[raytrace][spd]") {
    for (int sf = 1; sf <= 3; ++sf) {
        INFO("size " << sf);
        const Counts gears = count(spdGears(sf));
        CHECK(gears.polygons == 1 + pow(sf, 3) * (2 + 4 * 36)); // ground, 2 faces + 144 sides
        CHECK(count(spdTetra(sf)).polygons == pow(4, sf));
        const Counts rings = count(spdRings(sf));
        CHECK(rings.spheres == 5LL * sf * (sf + 1) * (2 * sf + 1));
        CHECK(rings.cones == rings.spheres);
        CHECK(rings.polygons == 1);
        const Counts lattice = count(spdLattice(sf));
        CHECK(lattice.spheres == pow(sf + 1, 3));
        CHECK(lattice.cones == 3 * sf * (sf + 1) * (sf + 1));
        CHECK(count(spdShells(sf)).spheres == 180 * pow(2, sf) + 1);
        const Counts tree = count(spdTree(sf));
        CHECK(tree.cones == pow(2, sf + 1) - 1);
        CHECK(tree.spheres == tree.cones);
        CHECK(tree.polygons == 1);
        const Counts mount = count(spdMount(sf));
        CHECK(mount.polygons == 2 * pow(4, sf));
        CHECK(mount.spheres == 4);
        // Teapot: n = 2^(SF+1); the board has n² squares, the pot teapotMesh(n)'s
        // triangles (2n² a patch less those collapsed at the poles: core/teapot's test).
        const long long n = 2LL << sf;
        const Counts teapot = count(spdTeapot(sf));
        const long long potTriangles = (long long)wb::teapotMesh(int(n)).indices.size() / 3;
        // Collapsed triangles: at most one per cell of one row of a patch.
        CHECK(potTriangles >= 32 * 2 * n * n - 32 * n);
        CHECK(potTriangles < 32 * 2 * n * n); // the lid's and the bottom's poles collapse
        CHECK(teapot.polygons == n * n + potTriangles);
        CHECK(teapot.polygonVertices == 4 * n * n + 3 * potTriangles);
    }
    CHECK_THROWS_AS(spdScene("kettle", 2), std::invalid_argument);
    CHECK_THROWS_AS(spdScene("gears", 7), std::invalid_argument);
}

TEST_CASE("spd: every scene survives an NFF round trip exactly", "[raytrace][spd]") {
    for (const std::string& name : spdSceneNames()) {
        INFO(name);
        const NffDocument doc = spdScene(name, 2);
        std::stringstream text;
        writeNff(text, doc);
        const NffDocument back = readNff(text, name + ".nff");
        REQUIRE(back.objects.size() == doc.objects.size());
        REQUIRE(back.surfaces.size() == doc.surfaces.size());
        bool same = true;
        for (size_t i = 0; i < doc.objects.size(); ++i) {
            const NffObject &a = doc.objects[i], &b = back.objects[i];
            same = same && a.kind == b.kind && a.centre == b.centre && a.radius == b.radius &&
                   a.base == b.base && a.apex == b.apex && a.vertices == b.vertices;
        }
        CHECK(same);
        CHECK(back.view.from == doc.view.from);
    }
}

TEST_CASE("spd: every polygon is triangulated without overlap", "[raytrace][spd]") {
    // Overlapping or outside triangles (a fan over a concave gear face) have more area
    // than the polygon. 1e-12 relative: sums of ~150 areas rounded at 1e-16 each.
    for (const std::string& name : spdSceneNames()) {
        INFO(name);
        for (const NffObject& o : spdScene(name, 2).objects) {
            if (o.vertices.size() < 3) continue;
            const double area = glm::length(vectorArea(o.vertices));
            double sum = 0;
            for (const auto& t : triangulatePolygon(o.vertices))
                sum += glm::length(vectorArea({o.vertices[size_t(t[0])], o.vertices[size_t(t[1])],
                                               o.vertices[size_t(t[2])]}));
            REQUIRE(std::abs(sum - area) <= 1e-12 * area);
        }
    }
}

TEST_CASE("spd: every scene renders small: no NaN, sane ray counts", "[raytrace][spd]") {
    constexpr int kW = 64, kH = 48; // small: the sanitizer build runs this too
    for (const std::string& name : spdSceneNames()) {
        INFO(name);
        SceneFile sf = toScene(spdScene(name, 2));
        auto bvh = makeAggregate(*sf.scene);
        sf.scene->setAggregate(bvh.get());
        const PhongModel model;
        ParallelRenderOptions opt;
        ParallelRenderStats st;
        const wb::Image img = renderParallel(*sf.scene, sf.camera(), model, kW, kH, opt, &st);
        CHECK(st.nonFinitePixels == 0);
        CHECK(st.primaryRays == kW * kH);
        // Each ray spawns at most a reflected and a transmitted ray per level (depth 5):
        // at most 2 + 4 + ... + 32 = 62 per eye ray; and one feeler per light per hit.
        CHECK(st.secondaryRays <= 62 * st.primaryRays);
        CHECK(st.shadowRays <=
              (long long)sf.scene->lights.size() * (st.primaryRays + st.secondaryRays));
        CHECK(st.shadowRays > 0); // something was hit and lit
        // Not only the background: the scene is in view.
        std::map<int, int> colours;
        for (int i = 0; i < kW * kH; ++i)
            ++colours[img.data[size_t(3 * i)] * 65536 + img.data[size_t(3 * i + 1)] * 256 +
                      img.data[size_t(3 * i + 2)]];
        int most = 0;
        for (const auto& [c, n] : colours)
            most = std::max(most, n);
        CHECK(colours.size() > 20);
        CHECK(most < kW * kH * 9 / 10); // at most 90% of the image one colour (the sky)
    }
}
