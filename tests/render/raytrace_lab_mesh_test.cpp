// Lab 07's raster mesh under its triangle budget (issue 12.1): scenes the tracer renders
// (100,000 identical spheres, one polygon of 99,999 vertices, hundreds of thousands of
// tiny spheres) must tessellate within TessellationOptions::maxTriangles and the arrays
// must not hold more than the budget's bytes; scenes under the budget are unchanged.
#include "raster_mesh.h"

#include "core/raytrace/sphere.h"
#include "core/raytrace/triangle.h"

#include <catch2/catch.hpp>

#include <cmath>

namespace {

// Bytes held by the vertex arrays (capacity: what the allocator really gave).
size_t meshBytes(const std::vector<wb::MeshBatch>& mesh) {
    size_t n = 0;
    for (const auto& b : mesh)
        n += (b.pos.capacity() + b.normal.capacity()) * sizeof(float);
    return n;
}

long long meshTriangles(const std::vector<wb::MeshBatch>& mesh) {
    long long n = 0;
    for (const auto& b : mesh)
        n += (long long)(b.pos.size() / 9);
    return n;
}

wb::ViewCamera camera160() {
    wb::CameraSpec spec;
    spec.eye = {0, 0, 30};
    return wb::ViewCamera::make(spec, 0, 0, 1, 160, 120);
}

// 72 bytes per triangle: 3 vertices × (3 position + 3 normal floats) × 4 bytes.
constexpr size_t kBytesPerTriangle = 72;

void checkBudget(const wb::rt::Scene& scene, const wb::TessellationOptions& opt,
                 wb::TessellationStats& st) {
    const auto mesh = wb::tessellate(scene, camera160(), opt, &st);
    INFO("triangles " << st.triangles << ", level " << st.level << ", stand-ins " << st.standIns);
    CHECK(st.triangles <= opt.maxTriangles);
    CHECK(meshTriangles(mesh) == st.triangles);
    // Exact reservation: capacity is the triangles drawn (no doubling growth).
    CHECK(meshBytes(mesh) <= size_t(opt.maxTriangles) * kBytesPerTriangle);
    CHECK(st.budget == opt.maxTriangles);
}

} // namespace

TEST_CASE("lab 07 raster mesh: 100,000 identical spheres fit the triangle budget", "[mesh]") {
    wb::rt::Scene scene;
    const int mat = scene.addMaterial(wb::rt::Material{});
    for (int i = 0; i < 100000; ++i)
        scene.add(wb::rt::Sphere({0, 0, 0}, 1.0), mat);
    wb::TessellationOptions opt;
    opt.maxTriangles = 200000; // smaller than the default to keep the test fast
    wb::TessellationStats st;
    checkBudget(scene, opt, st);
    CHECK(st.level < 1.0);
    // At the coarsest level a sphere is 4 segments × 4 rings × 2 = 32 triangles less the
    // 2 × 4 degenerate ones at the poles = 24, so 200,000 − 12 triangles hold 8,332
    // spheres; the rest is the stand-in box.
    CHECK(st.standIns == 100000 - (200000 - 12) / 24);
}

TEST_CASE("lab 07 raster mesh: one polygon of 99,999 vertices (a fan of large triangles)",
          "[mesh]") {
    wb::rt::Scene scene;
    const int mat = scene.addMaterial(wb::rt::Material{});
    // The NFF reader fans `p 99999` into 99,997 triangles; each is split into up to 64²
    // cells for Gouraud lighting, which made 400 M triangles before the budget.
    const double pi = 3.14159265358979323846;
    const int n = 99999;
    auto at = [&](int i) {
        const double a = 2 * pi * i / n;
        return glm::dvec3(10 * std::cos(a), 10 * std::sin(a), 0);
    };
    for (int i = 1; i + 1 < n; ++i)
        scene.add(wb::rt::Triangle(at(0), at(i), at(i + 1)), mat);
    wb::TessellationOptions opt; // the default budget
    wb::TessellationStats st;
    checkBudget(scene, opt, st);
    CHECK(st.level < 1.0);
    CHECK(st.standIns == 0); // one triangle each fits: only coarsened
}

TEST_CASE("lab 07 raster mesh: 400,000 tiny spheres, the rest of the budget as a stand-in",
          "[mesh]") {
    wb::rt::Scene scene;
    const int mat = scene.addMaterial(wb::rt::Material{});
    for (int i = 0; i < 400000; ++i)
        scene.add(wb::rt::Sphere({(i % 1000) * 0.01 - 5, (i / 1000) * 0.01 - 2, 0}, 0.004), mat);
    wb::TessellationOptions opt;
    opt.maxTriangles = 50000;
    wb::TessellationStats st;
    checkBudget(scene, opt, st);
    CHECK(st.standIns > 0);
    CHECK(st.standIns < 400000);
}

TEST_CASE("lab 07 raster mesh: a scene under the budget is tessellated as before", "[mesh]") {
    wb::rt::Scene scene;
    const int mat = scene.addMaterial(wb::rt::Material{});
    scene.add(wb::rt::Sphere({0, 0, 0}, 1.0), mat);
    scene.add(wb::rt::Sphere({3, 0, 0}, 0.5), mat);
    wb::TessellationStats st;
    const auto mesh = wb::tessellate(scene, camera160(), {}, &st);
    CHECK(st.level == 1.0);
    CHECK(st.standIns == 0);
    CHECK(st.triangles > 100); // a real sphere, not the coarsest stand-in
    CHECK(meshTriangles(mesh) == st.triangles);
}
