#include "core/raytrace/tracer.h"

#include "core/raytrace/phong_model.h"
#include "core/raytrace/texture.h"
#include "lanes_sse2.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wb::rt {

glm::dvec3 reflectDir(const glm::dvec3& e, const glm::dvec3& n) {
    return glm::normalize(e - 2 * glm::dot(e, n) * n);
}

std::optional<glm::dvec3> refractDir(const glm::dvec3& v, const glm::dvec3& n, double eta) {
    const double cv = -glm::dot(v, n);
    const double d = 1 + eta * eta * (cv * cv - 1);
    // d <= 0: total internal reflection (d == 0 is the critical angle itself: the
    // refracted ray would run along the surface and carries nothing).
    if (!(d > 0)) return std::nullopt;
    return glm::normalize(eta * v + (eta * cv - std::sqrt(d)) * n);
}

double Tracer::transmittance(const glm::dvec3& origin, const glm::dvec3& dir, double tMin,
                             double dist, const Primitive* self) const {
    ++shadowRays;
    return feelerTransmittance(origin, dir, tMin, dist, self);
}

double Tracer::feelerTransmittance(const glm::dvec3& origin, const glm::dvec3& dir, double tMin,
                                   double dist, const Primitive* self,
                                   const Primitive** blocker) const {
    Ray feeler;
    feeler.origin = origin;
    feeler.direction = dir;
    // The visitor captures one reference: std::function keeps a functor of up to 16
    // bytes in place, a bigger one (three references) costs a malloc and a free per
    // feeler (4.5% of the balls 4 frame's instructions).
    struct Walk {
        const std::vector<Material>& materials;
        double opaqueKt;
        double k = 1.0;
        const Primitive* opaque = nullptr;
    } walk{scene_.materials, settings_.opaqueKt};
    // Only the blockers' materials matter: no hit records (Primitive::occluded). A flat
    // primitive cannot shadow its own point: the aggregate never asks it (issue 21; the
    // visitor skipped it before, after its exact test had run: the same answers).
    scene_.aggregate().forEachBlocker(
        feeler, tMin, dist,
        [&walk](const Primitive& p) {
            const double kt = walk.materials[size_t(p.material)].kt;
            if (kt < walk.opaqueKt) {
                walk.k = 0.0; // an opaque blocker: no need to look further
                walk.opaque = &p;
                return false;
            }
            walk.k *= kt;
            return true;
        },
        self);
    if (blocker) *blocker = walk.opaque;
    return walk.k;
}

namespace {
// feelerStart with eps = |offsetRayOrigin(p, n) − p| known (once per hit, not per light).
double feelerStartAt(double eps, const glm::dvec3& n, const glm::dvec3& dir) {
    return eps / std::max(glm::dot(dir, n), 1e-3);
}

// Per hit, not per light (sampleLightsFrom and traceFromPacket): the feelers' start distance
// at normal incidence and the primitive they must not count (a virtual call).
struct FeelerBase {
    double eps;            // |offsetOrigin − point|, feelerStartAt's eps
    const Primitive* self; // the hit's primitive when flat (a feeler cannot meet it again)
    bool curved = false;   // else: the hit's Primitive::feelerSelfTerms gave f and c
    glm::dvec3 f{};
    double c = 0;
};
FeelerBase feelerBase(const Hit& hit, const glm::dvec3& offsetOrigin) {
    FeelerBase b{glm::length(offsetOrigin - hit.point),
                 hit.primitive && hit.primitive->planar() ? hit.primitive : nullptr};
    if (hit.primitive && !b.self) b.curved = hit.primitive->feelerSelfTerms(hit.point, b.f, b.c);
    return b;
}

// True only if the sphere's own exact test (Sphere::occluded, sphere.cpp's nearest) of the
// feeler from the hit point (f = point − centre and c = |f|² − r² from feelerSelfTerms,
// the bits nearest computes) along unit `dir` on (t0, dist], t0 > 0, answers "no": then the
// walk need not ask it (issue 21, twelfth session; rtframe7 skipped it unconditionally,
// which a grazing feeler from a point rounded to just inside the sphere breaks: its exit
// root ≈ −(|f| − r)/cos can pass t0 = eps / max(cos, 1e-3) once cos < ~1e-3·|f − r|/eps).
// Proof, with h = f·dir computed as nearest does (glm::dot on the same bits; this file
// and sphere.cpp are built without FMA contraction), A = |c|, u = 2^-53:
//  - nearest returns false for disc < 0 or non-finite h or c; else, h > 0 makes
//    q = −fl(h + √disc) ≤ −h < 0 (rounding is monotone and h representable), so the
//    root q is < 0 < t0, and the other root is fl(c / q).
//  - c ≥ 0: c / q ≤ 0 < t0. No hit.
//  - c < 0: the test below, fl(2A) ≤ fl(t0·h), gives A ≤ t0·h: if 2A is finite it is
//    exact, and fl(t0·h) ≤ t0·h·(1 + u) + 2^-1075 (underflow) with A ≥ 2^-1074, so
//    2A ≤ t0·h·(1 + u) + A/2, A ≤ (2/3)(1 + u)·t0·h; if 2A overflows, fl(t0·h) = inf,
//    t0·h ≥ DBL_MAX ≥ A. Then A / |q| ≤ A / h ≤ t0, its rounding too (t0 is a double):
//    the root is not > t0. No hit.
// The typical feeler: cos ≥ 1e-3, h ≈ r·cos, A ≈ 2r·|ε| with ε the refined point's
// distance from the surface (a few ULPs), t0·h ≈ eps·r with eps ~ 2^20 ULPs: true with
// a margin of ~10^5. Grazing or inward feelers (h ≤ 0: the inside of a sphere, a light
// behind the tangent plane) fail it and keep the exact test.
// Written once for one feeler (D = double, a bool) and for two in sse2lanes' lanes (D = D2,
// a lane mask; traceFromPacket): the same operations in the same order, so every lane
// answers as the single feeler would (lanes_sse2.h: glm's dot, one rounding each). The
// scalar comparisons join sse2lanes' in one overload set (a Mask is a bare __m128d, which
// argument-dependent lookup does not find).
using sse2lanes::greater;
using sse2lanes::lessEqual;
using sse2lanes::maskAnd;
inline double lit(double x, double) {
    return x;
}
inline sse2lanes::D2 lit(double x, sse2lanes::D2) {
    return sse2lanes::splat(x);
}
inline bool greater(double a, double b) {
    return a > b;
}
inline bool lessEqual(double a, double b) {
    return a <= b;
}
inline bool maskAnd(bool a, bool b) {
    return a && b;
}
template <class D, class Vec>
inline auto sphereCannotBlock(const Vec& f, D c, const Vec& dir, D t0) {
    const D h = dot(f, dir); // glm::dot or lanes_sse2.h's, found by the argument's type
    return maskAnd(greater(h, lit(0.0, h)), lessEqual(lit(2.0, h) * -c, t0 * h));
}
} // namespace

double feelerStart(const glm::dvec3& p, const glm::dvec3& n, const glm::dvec3& dir) {
    // How far along `dir` the point is as far from the surface as the RTG offset along
    // the normal would put it. The cosine is floored at 1e-3 so that a light at grazing
    // incidence (whose diffuse term is ~0 anyway) cannot push the start past blockers.
    return feelerStartAt(glm::length(offsetRayOrigin(p, n) - p), n, dir);
}

std::vector<LightSample> Tracer::sampleLights(const Hit& hit) const {
    std::vector<LightSample> out;
    sampleLights(hit, out);
    return out;
}

void Tracer::sampleLights(const Hit& hit, std::vector<LightSample>& out) const {
    RayCounts counts;
    sampleLightsFrom(hit, offsetRayOrigin(hit.point, hit.normal), out, counts);
    shadowRays += counts.shadow;
}

// Inlined into sampleLightsFrom, as it was written there (the single path's code stays).
__attribute__((always_inline)) inline double
Tracer::cachedFeeler(const glm::dvec3& point, const glm::dvec3& toLight, double t0, double dist,
                     const Primitive* self, const Primitive** cacheEntry) const {
    const Primitive* cached = cacheEntry ? *cacheEntry : nullptr;
    Ray feeler;
    feeler.origin = point;
    feeler.direction = toLight;
    // The shadow cache (traceFrom): the previous feeler's opaque blocker, asked by its exact
    // test on this feeler's segment, as the walk would ask it (never `self`; only an opaque
    // material makes the transmittance 0).
    if (cached && cached != self &&
        scene_.materials[size_t(cached->material)].kt < settings_.opaqueKt &&
        cached->occluded(feeler, t0, dist))
        return 0.0;
    return feelerTransmittance(point, toLight, t0, dist, self, cacheEntry);
}

void Tracer::sampleLightsFrom(const Hit& hit, const glm::dvec3& offsetOrigin,
                              std::vector<LightSample>& out, RayCounts& counts,
                              const Primitive** lastBlockers) const {
    out.clear();
    out.reserve(scene_.lights.size());
    const FeelerBase base = feelerBase(hit, offsetOrigin);
    const double eps = base.eps;
    for (std::size_t li = 0; li < scene_.lights.size(); ++li) {
        const Light& l = scene_.lights[li];
        LightSample s;
        s.light = &l;
        if (l.kind == Light::Kind::Point) {
            const glm::dvec3 v = l.position - hit.point;
            const double dist = glm::length(v);
            s.toLight = dist > 0 ? v / dist : hit.normal; // light exactly at the point
            s.distance = dist;
        } else {
            const double len = glm::length(l.direction);
            s.toLight = len > 0 ? -l.direction / len : hit.normal;
            s.distance = std::numeric_limits<double>::infinity();
        }
        if (glm::dot(s.toLight, hit.normal) > 0) {
            // The feeler is the exact segment point–light, started where it is as far off
            // the surface as the normal offset of reflected rays: a feeler that grazes a
            // blocker's border (seed 000's does, exactly) is judged on the true line.
            const double t0 = feelerStartAt(eps, hit.normal, s.toLight);
            if (t0 < s.distance) {
                ++counts.shadow;
                const Primitive* self =
                    base.self || (base.curved && sphereCannotBlock(base.f, base.c, s.toLight, t0))
                        ? hit.primitive
                        : nullptr;
                s.transmittance = cachedFeeler(hit.point, s.toLight, t0, s.distance, self,
                                               lastBlockers ? &lastBlockers[li] : nullptr);
            } else {
                s.transmittance = 1.0; // the light is closer than the offset
            }
        } else {
            s.transmittance = 0.0; // the surface faces away from the light
        }
        out.push_back(s);
    }
}

// Inlined into traceRay: a call there cost the single-ray balls 4 frame 10 M instructions
// (callgrind, 2175 -> 2185 M).
template <bool kObserve>
__attribute__((always_inline)) inline Color
Tracer::spawnChildren(const Ray& ray, const Hit& hit, const Material& m,
                      const glm::dvec3& offsetOrigin, Color c, TraceObserver* observer,
                      long& budget, RayCounts& counts, const Primitive** lastBlockers) const {
    if (ray.depth < settings_.maxDepth) {
        // The children's shadow cache: the next level's entries (traceFrom).
        const Primitive** childBlockers =
            lastBlockers ? lastBlockers + scene_.lights.size() : nullptr;
        // A child's weight is its share of this ray's, k / max(1, kr + kt) (issue 12): the
        // weights of one level then sum to <= 1 for any kr, kt, so at most 1/minWeight
        // rays a level pass the cut-off (kr = kt = 1 made 2^depth rays of weight 1).
        // For kr + kt <= 1 the divisor is exactly 1: seed 000's weight × k, same bits.
        const double share = std::max(1.0, m.kr + m.kt);
        // Reflected ray: same side, same medium.
        const bool reflect = m.kr > 0 && ray.weight * m.kr / share >= settings_.minWeight;
        if (reflect && budget <= 0) {
            if constexpr (kObserve)
                observer->childSkipped(RayKind::Reflected, SkipReason::RayBudget);
        } else if (reflect) {
            --budget;
            Ray r;
            r.origin = offsetOrigin;
            r.direction = reflectDir(ray.direction, hit.normal);
            r.weight = ray.weight * m.kr / share;
            r.medium = ray.medium;
            r.depth = ray.depth + 1;
            const Color rc = traceRay<kObserve>(r, RayKind::Reflected, observer, budget, counts,
                                                nullptr, childBlockers);
            if constexpr (kObserve) observer->childResult(RayKind::Reflected, rc, m.kr);
            c = model_.addScaled(c, rc, m.kr);
        } else if (kObserve && m.kr > 0) {
            observer->childSkipped(RayKind::Reflected, SkipReason::BelowWeight);
        }
        // Transmitted ray: through a thin (open) surface unchanged, into or out of a
        // body by formula (7) with the ratio of the indices on both sides.
        const bool transmit = m.kt > 0 && ray.weight * m.kt / share >= settings_.minWeight;
        if (transmit && budget <= 0) {
            if constexpr (kObserve)
                observer->childSkipped(RayKind::Refracted, SkipReason::RayBudget);
        } else if (transmit) {
            std::optional<glm::dvec3> dir = ray.direction;
            Medium medium = ray.medium;
            if (hit.solid) {
                double eta;
                if (hit.entering) {
                    eta = ray.medium.refract / m.medium.refract;
                    medium = m.medium;
                } else {
                    eta = m.medium.refract / scene_.air.refract;
                    medium = scene_.air;
                }
                dir = refractDir(ray.direction, hit.normal, eta);
            }
            if (dir) {
                --budget;
                Ray t;
                t.origin = offsetRayOrigin(hit.point, -hit.normal);
                t.direction = *dir;
                t.weight = ray.weight * m.kt / share;
                t.medium = medium;
                t.depth = ray.depth + 1;
                const Color tc = traceRay<kObserve>(t, RayKind::Refracted, observer, budget, counts,
                                                    nullptr, childBlockers);
                if constexpr (kObserve) observer->childResult(RayKind::Refracted, tc, m.kt);
                c = model_.addScaled(c, tc, m.kt);
            } else if (kObserve) {
                observer->childSkipped(RayKind::Refracted, SkipReason::TotalInternalReflection);
            }
        } else if (kObserve && m.kt > 0) {
            observer->childSkipped(RayKind::Refracted, SkipReason::BelowWeight);
        }
    } else if (kObserve) {
        if (m.kr > 0) observer->childSkipped(RayKind::Reflected, SkipReason::DepthLimit);
        if (m.kt > 0) observer->childSkipped(RayKind::Refracted, SkipReason::DepthLimit);
    }
    // Attenuation along this ray's path in its medium (seed 000: in trace, after shading).
    if (ray.medium.atten > 0) {
        const double factor = std::exp(-ray.medium.atten * hit.t);
        if constexpr (kObserve) observer->attenuated(factor);
        c = model_.scale(c, factor);
    }
    return c;
}

template <bool kObserve>
Color Tracer::traceRay(const Ray& ray, RayKind kind, TraceObserver* observer, long& budget,
                       RayCounts& counts, const Hit* known, const Primitive** lastBlockers) const {
    if (ray.depth == 0)
        ++counts.primary;
    else
        ++counts.secondary;
    if constexpr (kObserve) observer->rayBegin(ray, kind);
    Hit hit;
    if (known ? known->primitive == nullptr
              : !scene_.intersect(ray, 0.0, std::numeric_limits<double>::infinity(), hit)) {
        const Color bg = model_.background(scene_);
        if constexpr (kObserve) {
            observer->missed(bg);
            observer->rayEnd(bg);
        }
        return bg;
    }
    if (known) hit = *known;
    const Material& m = scene_.materials[size_t(hit.material)];
    const glm::dvec3 surface = (m.texture && hit.hasUv)
                                   ? sampleTexture(*m.texture, hit.primitive->textureCoords(hit))
                                   : m.colour;
    // The reflected ray's origin; the shadow feelers start as far off the surface.
    const glm::dvec3 offsetOrigin = offsetRayOrigin(hit.point, hit.normal);
    Color c;
    if constexpr (kObserve) { // observers may trace again from hit(): a vector of its own
        std::vector<LightSample> samples;
        sampleLightsFrom(hit, offsetOrigin, samples, counts);
        c = model_.direct(scene_, ray, hit, m, surface, samples);
        observer->hit(ray, hit, m, surface, samples, c);
    } else {
        // One buffer per thread instead of a vector allocated per hit: the samples are
        // used up by direct() before the recursion below, so nested rays can refill it.
        // (A shading model must not call trace() from direct().)
        thread_local std::vector<LightSample> samples;
        sampleLightsFrom(hit, offsetOrigin, samples, counts, lastBlockers);
        c = model_.direct(scene_, ray, hit, m, surface, samples);
    }
    c = spawnChildren<kObserve>(ray, hit, m, offsetOrigin, c, observer, budget, counts,
                                lastBlockers);
    if constexpr (kObserve) observer->rayEnd(c);
    return c;
}

void Tracer::add(const RayCounts& counts) const {
    // Only what changed: each is an atomic read-modify-write.
    if (counts.primary) primaryRays += counts.primary;
    if (counts.secondary) secondaryRays += counts.secondary;
    if (counts.shadow) shadowRays += counts.shadow;
}

Color Tracer::trace(const Ray& ray) const {
    RayCounts counts;
    const Color c = trace(ray, counts);
    add(counts);
    return c;
}

Color Tracer::trace(const Ray& ray, RayCounts& counts) const {
    long budget = settings_.maxRaysPerSample;
    return traceRay<false>(ray, RayKind::Primary, nullptr, budget, counts);
}

Color Tracer::traceFrom(const Ray& ray, const Hit& hit, RayCounts& counts) const {
    long budget = settings_.maxRaysPerSample;
    return traceRay<false>(ray, RayKind::Primary, nullptr, budget, counts, &hit);
}

Color Tracer::traceFrom(const Ray& ray, const Hit& hit, RayCounts& counts,
                        const Primitive** lastBlockers) const {
    long budget = settings_.maxRaysPerSample;
    // The cache's levels count depth from 0 (an eye ray).
    return traceRay<false>(ray, RayKind::Primary, nullptr, budget, counts, &hit,
                           ray.depth == 0 ? lastBlockers : nullptr);
}

using namespace sse2lanes;

void Tracer::traceFromPacket(const Ray* rays, const Hit* hits, int n, RayCounts& counts,
                             const Primitive** lastBlockers, Color* out) const {
    // Only the phong model itself (a subclass may shade otherwise) has lanes.
    const bool phong = PhongModel::isExactly(model_) && PhongModel::lanesApply(scene_);
    unsigned lanes = 0;
    for (int j = 0; j < n; ++j) {
        const Hit& h = hits[j];
        if (phong && h.primitive && rays[j].depth == 0 &&
            !(scene_.materials[size_t(h.material)].texture && h.hasUv))
            lanes |= 1u << j;
        else
            out[j] = traceFrom(rays[j], hits[j], counts, lastBlockers);
    }
    if (!lanes) return;
    // traceRay's steps for each lane, with direct() for all lanes at once: the feelers
    // first (in row order, so the shadow cache sees them as traceFrom would), then the
    // direct colours, then each lane's children.
    const std::size_t nLights = scene_.lights.size();
    // The eye hits' feelers of one light walk as a packet when every material is opaque
    // (then only "blocked or not" matters) and the aggregate walks them together (a Bvh).
    const Aggregate& aggregate = scene_.aggregate();
    bool feelerPacket = aggregate.hasOccludedPacket();
    if (feelerPacket)
        for (const Material& mat : scene_.materials)
            if (!(mat.kt < settings_.opaqueKt)) {
                feelerPacket = false;
                break;
            }
    // The feelers for occludedPacket, made once (only origin and direction change).
    Ray feelers[kMaxPacket];
    const Primitive* skip[kMaxPacket];
    // The lanes' transmittances, light by light (directLanes' layout); on the stack for the
    // usual few lights (the thread's vector and its resize cost ~5 M instructions of the
    // balls 4 frame).
    constexpr std::size_t kStackLights = 8;
    double trStack[kStackLights * kMaxPacket];
    thread_local std::vector<double> trHeap;
    double* transmittance = trStack;
    if (nLights > kStackLights) {
        trHeap.resize(nLights * kMaxPacket);
        transmittance = trHeap.data();
    }
    // The hits' points, normals and feeler offsets in lanes, once for every light (a lane
    // outside `lanes` holds the first lane's, so that it computes on numbers).
    alignas(16) double px[kMaxPacket], py[kMaxPacket], pz[kMaxPacket];
    alignas(16) double nx[kMaxPacket], ny[kMaxPacket], nz[kMaxPacket], eps[kMaxPacket];
    const int firstLane = __builtin_ctz(lanes);
    for (int j = 0; j < kMaxPacket; ++j) {
        const Hit& h = hits[(lanes >> j) & 1u ? j : firstLane];
        feelers[j].origin = h.point; // every light's feeler starts there
        px[j] = h.point.x;
        py[j] = h.point.y;
        pz[j] = h.point.z;
        nx[j] = h.normal.x;
        ny[j] = h.normal.y;
        nz[j] = h.normal.z;
    }
    // offsetRayOrigin(point, normal) of every lane (the reflected rays' origin), and
    // feelerBase's eps = |offsetOrigin − point| (glm::length: sqrt of the dot).
    alignas(16) double ox[kMaxPacket], oy[kMaxPacket], oz[kMaxPacket];
    {
        const double* const p[3] = {px, py, pz};
        const double* const nrm[3] = {nx, ny, nz};
        double* const o[3] = {ox, oy, oz};
        offsetRayOrigins(p, nrm, o, kMaxPacket);
    }
    for (int i = 0; i < kMaxPacket; i += 2) {
        const auto load = [i](const double* from) { return D2{_mm_load_pd(&from[i])}; };
        const V2 d = V2{load(ox), load(oy), load(oz)} - V2{load(px), load(py), load(pz)};
        _mm_store_pd(&eps[i], sqrtOf(dot(d, d)).v);
    }
    // feelerBase's per lane: the hit's primitive, `flat` its lanes that are planar, `curved`
    // those whose feelerSelfTerms gave f and c (0 in the other lanes once there is one:
    // numbers; a packet without one, as the mesh's, does not clear them).
    const Primitive* prim[kMaxPacket];
    alignas(16) double fx[kMaxPacket], fy[kMaxPacket], fz[kMaxPacket], selfC[kMaxPacket];
    unsigned flat = 0, curved = 0;
    for (unsigned m = lanes; m; m &= m - 1) {
        const int j = __builtin_ctz(m);
        ++counts.primary;
        const Primitive* p = prim[j] = hits[j].primitive;
        glm::dvec3 f;
        double c;
        if (p->planar()) {
            flat |= 1u << j;
        } else if (p->feelerSelfTerms(hits[j].point, f, c)) {
            if (!curved)
                for (double* a : {fx, fy, fz, selfC})
                    std::fill(a, a + kMaxPacket, 0.0);
            curved |= 1u << j;
            selfC[j] = c;
            fx[j] = f.x;
            fy[j] = f.y;
            fz[j] = f.z;
        }
    }
    // sampleLightsFrom's samples, light by light (each light's feelers in row order, as
    // its shadow cache entry sees them from traceFrom): the unit vector to the point light,
    // its distance and the feeler's start for two hits at a time, then each feeler. Which
    // lanes face the light and which need a feeler come out as masks (the comparisons of
    // sampleLightsFrom: dot > 0, t0 < distance), not as a branch per lane and light.
    for (std::size_t li = 0; li < nLights; ++li) {
        const glm::dvec3& lp = scene_.lights[li].position;
        double* tr = &transmittance[li * kMaxPacket];
        alignas(16) double dist[kMaxPacket], t0[kMaxPacket];
        alignas(16) double dx[kMaxPacket], dy[kMaxPacket], dz[kMaxPacket];
        unsigned ask = 0;
        for (int i = 0; i < kMaxPacket; i += 2) {
            if (!((lanes >> i) & 3u)) continue;
            // Element 0 is lane i, element 1 lane i + 1.
            const auto load = [i](const double* from) { return D2{_mm_load_pd(&from[i])}; };
            const V2 normal{load(nx), load(ny), load(nz)};
            const V2 v = splat(lp) - V2{load(px), load(py), load(pz)};
            const D2 d = sqrtOf(dot(v, v));
            // The light exactly at the point: the normal (the select only when a lane is).
            const __m128d away = _mm_cmpgt_pd(d.v, _mm_setzero_pd());
            const V2 toLight = _mm_movemask_pd(away) == 3 ? v / d : select(away, v / d, normal);
            const D2 c = dot(toLight, normal);
            const D2 start = load(eps) / maxOf(c, splat(1e-3)); // feelerStartAt
            const __m128d faces = _mm_cmpgt_pd(c.v, _mm_setzero_pd());
            const unsigned f = unsigned(_mm_movemask_pd(faces));
            // The surface faces away from the light: 0; the light closer than the offset: 1
            // (a feeler's lane is set to 0 below if it is blocked).
            _mm_storeu_pd(&tr[i], _mm_and_pd(faces, _mm_set1_pd(1.0)));
            ask |= (f & unsigned(_mm_movemask_pd(_mm_cmplt_pd(start.v, d.v)))) << i;
            _mm_store_pd(&dist[i], d.v);
            _mm_store_pd(&t0[i], start.v);
            _mm_store_pd(&dx[i], toLight.x.v);
            _mm_store_pd(&dy[i], toLight.y.v);
            _mm_store_pd(&dz[i], toLight.z.v);
        }
        ask &= lanes;
        // The feelers that skip their own primitive: flat, or sphereCannotBlock (two lanes at
        // a time, the single feeler's body).
        unsigned own = flat;
        for (int i = 0; (ask & curved) && i < kMaxPacket; i += 2) {
            if (!(((ask & curved) >> i) & 3u)) continue;
            const auto load = [i](const double* from) { return D2{_mm_load_pd(&from[i])}; };
            const Mask can = sphereCannotBlock(V2{load(fx), load(fy), load(fz)}, load(selfC),
                                               V2{load(dx), load(dy), load(dz)}, load(t0));
            own |= (maskBits(can) << i) & curved;
        }
        if (!feelerPacket) {
            const Primitive** entry = lastBlockers ? &lastBlockers[li] : nullptr;
            for (unsigned m = ask; m; m &= m - 1) {
                const int j = __builtin_ctz(m);
                ++counts.shadow;
                tr[j] = cachedFeeler(hits[j].point, glm::dvec3(dx[j], dy[j], dz[j]), t0[j], dist[j],
                                     (own >> j) & 1u ? prim[j] : nullptr, entry);
            }
            continue;
        }
        // Every blocker is opaque: a feeler's transmittance is 0 if anything blocks it, else
        // 1, which occludedPacket answers. The shadow cache is not asked here: the packet's
        // walk costs about what the cache's exact tests saved, and occludedPacket does not
        // say which primitive blocked (refilling the cache by one single walk per blocked
        // packet: balls 4 frame 1576.5 -> 1586.3 M instructions).
        if (!ask) continue;
        for (unsigned m = ask; m; m &= m - 1) {
            const int j = __builtin_ctz(m);
            ++counts.shadow;
            feelers[j].direction = glm::dvec3(dx[j], dy[j], dz[j]);
            skip[j] = (own >> j) & 1u ? prim[j] : nullptr;
        }
        const unsigned blocked = aggregate.occludedPacket(feelers, t0, dist, skip, ask);
        for (unsigned m = blocked; m; m &= m - 1)
            tr[__builtin_ctz(m)] = 0.0;
    }
    Color direct[kMaxPacket];
    PhongModel::directLanes(scene_, rays, hits, lanes, transmittance, direct);
    for (int j = 0; j < n; ++j) {
        if (!((lanes >> j) & 1u)) continue;
        long budget = settings_.maxRaysPerSample;
        out[j] = spawnChildren<false>(rays[j], hits[j], scene_.materials[size_t(hits[j].material)],
                                      glm::dvec3(ox[j], oy[j], oz[j]), direct[j], nullptr, budget,
                                      counts, lastBlockers);
    }
}

Color Tracer::trace(const Ray& ray, TraceObserver* observer) const {
    if (!observer) return trace(ray);
    long budget = settings_.maxRaysPerSample;
    RayCounts counts;
    const Color c = traceRay<true>(ray, RayKind::Primary, observer, budget, counts);
    add(counts);
    return c;
}

} // namespace wb::rt
