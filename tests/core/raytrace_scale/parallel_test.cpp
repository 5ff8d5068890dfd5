// Parallel tiled rendering: the image is bit-identical for 1, 2 and 3 threads and any
// tile size, and equal to the single-threaded reference renderer (render.h); the BVH
// gives the same image as the plain loop; progress reports every tile once, serialised;
// the cancel flag stops the frame; corner rays shoot (w+1)(h+1) eye rays; the ray counts
// equal a tracer's own counters.
#include "core/raytrace/bvh.h"
#include "core/raytrace/parallel_render.h"
#include "core/raytrace/phong_model.h"
#include "core/raytrace/render.h"
#include "core/raytrace/spd.h"

#include <catch2/catch.hpp>

#include <limits>
#include <set>
#include <utility>

using namespace wb::rt;

namespace {
constexpr int kW = 72, kH = 64; // small: the sanitizer build runs this too
}

TEST_CASE("rt_parallel: bit-identical for every thread count and tile size",
          "[raytrace][parallel]") {
    SceneFile sf = toScene(spdBalls(2));
    auto bvh = makeAggregate(*sf.scene);
    REQUIRE(bvh);
    sf.scene->setAggregate(bvh.get());
    const LookAtCamera cam = sf.camera();
    PhongModel model;
    const wb::Image ref = render(*sf.scene, cam, model, kW, kH);
    // The rays one tracer counts (its atomics, per trace) for every pixel's ray: the
    // tiles count theirs in RayCounts and add them once.
    const Tracer counter(*sf.scene, model);
    RayCounts local;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const Ray ray = cam.primaryRay(x, y, kW, kH);
            const Color a = counter.trace(ray), b = counter.trace(ray, local);
            REQUIRE(a == b);
        }
    CHECK(counter.primaryRays == kW * kH);
    CHECK(local.primary == kW * kH);
    CHECK(local.secondary == counter.secondaryRays);
    CHECK(local.shadow == counter.shadowRays);
    for (auto [threads, tile] : {std::pair{1, 32}, std::pair{2, 7}, std::pair{3, 16}}) {
        INFO("threads " << threads << " tile " << tile);
        ParallelRenderOptions opt;
        opt.threads = threads;
        opt.tileSize = tile;
        ParallelRenderStats st;
        const wb::Image img = renderParallel(*sf.scene, cam, model, kW, kH, opt, &st);
        CHECK(img.data == ref.data);
        CHECK(st.primaryRays == kW * kH);
        CHECK(st.secondaryRays == local.secondary);
        CHECK(st.secondaryRays > 0); // mirrored spheres
        CHECK(st.shadowRays == local.shadow);
        CHECK(st.shadowRays > 0);
        CHECK(st.nonFinitePixels == 0);
        CHECK_FALSE(st.cancelled);
    }
    // The BVH and the plain loop give the same picture.
    sf.scene->setAggregate(nullptr);
    const wb::Image brute = renderParallel(*sf.scene, cam, model, kW, kH);
    const wb::ImageDiff d = wb::compareImages(brute, ref);
    CHECK(d.sameSize);
    CHECK(d.maxDiff == 0);
    // The picture is not empty: the spheres and the floor differ from the background.
    std::set<int> colours;
    for (int i = 0; i < kW * kH; ++i)
        colours.insert(ref.data[size_t(3 * i)] * 65536 + ref.data[size_t(3 * i + 1)] * 256 +
                       ref.data[size_t(3 * i + 2)]);
    CHECK(colours.size() > 50);
}

TEST_CASE("rt_parallel: progress reports every tile once and serialised", "[raytrace][parallel]") {
    SceneFile sf = toScene(twoSpheresScene());
    const LookAtCamera cam = sf.camera();
    PhongModel model;
    ParallelRenderOptions opt;
    opt.threads = 2;
    opt.tileSize = 16;
    std::atomic<int> inside{0};
    bool overlapped = false;
    std::set<std::pair<int, int>> tiles;
    int last = 0, total = 0;
    opt.progress = [&](const TileProgress& p) {
        if (inside.fetch_add(1) != 0) overlapped = true;
        tiles.insert({p.x0, p.y0});
        CHECK(p.tilesDone == last + 1);
        last = p.tilesDone;
        total = p.tilesTotal;
        CHECK(p.image != nullptr);
        CHECK(p.x1 <= kW);
        CHECK(p.y1 <= kH);
        inside.fetch_sub(1);
    };
    renderParallel(*sf.scene, cam, model, kW, kH, opt);
    CHECK_FALSE(overlapped);
    CHECK(total == 5 * 4); // ceil(72/16) × ceil(64/16)
    CHECK(last == total);
    CHECK(tiles.size() == size_t(total));
}

TEST_CASE("rt_parallel: the cancel flag stops the frame", "[raytrace][parallel]") {
    SceneFile sf = toScene(twoSpheresScene());
    const LookAtCamera cam = sf.camera();
    PhongModel model;
    std::atomic<bool> cancel{false};
    ParallelRenderOptions opt;
    opt.threads = 1;
    opt.tileSize = 8;
    int seen = 0;
    opt.progress = [&](const TileProgress&) {
        ++seen;
        cancel = true; // stop after the first tile
    };
    opt.cancel = &cancel;
    ParallelRenderStats st;
    renderParallel(*sf.scene, cam, model, kW, kH, opt, &st);
    CHECK(st.cancelled);
    CHECK(seen == 1);
    CHECK(st.primaryRays == 8 * 8);
}

TEST_CASE("rt_parallel: corner rays shoot (w+1)(h+1) eye rays", "[raytrace][parallel]") {
    SceneFile sf = toScene(oneSphereScene());
    const LookAtCamera cam = sf.camera();
    PhongModel model;
    ParallelRenderOptions opt;
    opt.cornerRays = true;
    ParallelRenderStats st1, st2;
    opt.threads = 1;
    const wb::Image a = renderParallel(*sf.scene, cam, model, kW, kH, opt, &st1);
    opt.threads = 2;
    opt.tileSize = 5;
    const wb::Image b = renderParallel(*sf.scene, cam, model, kW, kH, opt, &st2);
    CHECK(st1.primaryRays == (kW + 1) * (kH + 1));
    CHECK(st2.primaryRays == (kW + 1) * (kH + 1));
    CHECK(a.data == b.data);
    // Each pixel is the mean of its four corner rays' colours, whichever tile (or the
    // pass after the tiles, for a tile's last corner row and column) averaged it: the
    // image built here from one tracer, for tile sizes that put the seams everywhere.
    const Tracer tracer(*sf.scene, model, opt.trace);
    std::vector<Color> corner(std::size_t((kW + 1) * (kH + 1)));
    for (int y = 0; y <= kH; ++y)
        for (int x = 0; x <= kW; ++x)
            corner[std::size_t(y * (kW + 1) + x)] = tracer.trace(cam.rayAt(x, y, kW, kH));
    wb::Image want(kW, kH, 3);
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const auto at = [&](int cx, int cy) { return corner[std::size_t(cy * (kW + 1) + cx)]; };
            model.toRgb8(0.25 * (at(x, y) + at(x + 1, y) + at(x, y + 1) + at(x + 1, y + 1)),
                         want.at(x, y));
        }
    CHECK(a.data == want.data);
    for (int tile : {1, 2, 3, 31, 64, 72, 73, 200}) {
        INFO("tile " << tile);
        opt.tileSize = tile;
        CHECK(renderParallel(*sf.scene, cam, model, kW, kH, opt).data == want.data);
    }
    // Corner averaging stays close to centre sampling (edges blur by one pixel at most).
    const wb::Image c = render(*sf.scene, cam, model, kW, kH);
    CHECK(wb::compareImages(a, c).meanDiff < 3.0);
    CHECK_THROWS_AS(renderParallel(*sf.scene, ScreenCamera::seed000(), model, 8, 8, opt),
                    std::invalid_argument);
}

namespace {
// A phong model whose direct light is NaN: what a material value outside its meaning used
// to produce (Ks = 1e100 gave Inf, Inf·0 NaN). The readers now refuse such files, so the
// counter the front ends turn into an error is checked with a model that misbehaves.
class NanModel : public PhongModel {
  public:
    Color direct(const Scene&, const Ray&, const Hit&, const Material&, const glm::dvec3&,
                 const std::vector<LightSample>&) const override {
        return Color(std::numeric_limits<double>::quiet_NaN());
    }
};
} // namespace

TEST_CASE("rt_parallel: non-finite colours are counted and written as 0", "[raytrace][parallel]") {
    SceneFile sf = toScene(oneSphereScene());
    const LookAtCamera cam = sf.camera();
    const NanModel model;
    ParallelRenderOptions opt;
    ParallelRenderStats st;
    const wb::Image img = renderParallel(*sf.scene, cam, model, kW, kH, opt, &st);
    // Every eye ray that hits the sphere or the floor is NaN; the sky (background) is not.
    long long black = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const uint8_t* p = img.at(x, y);
            black += p[0] == 0 && p[1] == 0 && p[2] == 0;
        }
    CHECK(st.nonFinitePixels > 0);
    CHECK(st.nonFinitePixels <= black);  // each counted pixel was written black
    CHECK(st.nonFinitePixels < kW * kH); // the background stays finite
}
