#include "ray_inspector.h"

#include "core/raytrace/box.h"
#include "core/raytrace/course_model.h"
#include "core/raytrace/cylinder.h"
#include "core/raytrace/phong_model.h"
#include "core/raytrace/plane.h"
#include "core/raytrace/polyhedron.h"
#include "core/raytrace/quadric.h"
#include "core/raytrace/rectangle.h"
#include "core/raytrace/smooth_triangle.h"
#include "core/raytrace/sphere.h"
#include "core/raytrace/triangle.h"

#include "core/i18n.h"
#include <algorithm>
#include <cstdio>
#include <unordered_map>

namespace wb {

std::string primitiveKind(const rt::Primitive& p) {
    if (dynamic_cast<const rt::Sphere*>(&p)) return N_("sphere");
    if (dynamic_cast<const rt::Plane*>(&p)) return N_("plane");
    if (dynamic_cast<const rt::Rectangle*>(&p)) return N_("rectangle");
    if (dynamic_cast<const rt::SmoothTriangle*>(&p)) return N_("smooth triangle");
    if (dynamic_cast<const rt::Triangle*>(&p)) return N_("triangle");
    if (dynamic_cast<const rt::Box*>(&p)) return N_("box");
    if (dynamic_cast<const rt::ConvexPolyhedron*>(&p)) return N_("polyhedron");
    if (auto* c = dynamic_cast<const rt::Cone*>(&p))
        return c->r0 == c->r1 ? N_("cylinder") : N_("cone");
    if (auto* q = dynamic_cast<const rt::Quadric*>(&p)) {
        switch (q->kind) {
        case rt::Quadric::Kind::Ellipsoid:
            return N_("ellipsoid");
        case rt::Quadric::Kind::Paraboloid:
            return N_("paraboloid");
        case rt::Quadric::Kind::Hyperboloid:
            return N_("hyperboloid");
        }
    }
    return N_("primitive");
}

namespace {

// Builds the tree from the tracer's own recursion (Tracer::trace with an observer):
// one node per rayBegin, filled by the events of that ray.
struct Inspector : rt::TraceObserver {
    const rt::Scene& scene;
    ModelKind kind;
    rt::CourseModel course;
    rt::PhongModel phong;
    std::unordered_map<const rt::Primitive*, int> index;
    RayTree tree;
    std::vector<int> open; // nodes whose rays are being traced, innermost last
    int lastEnded = -1;    // the node whose ray ended last: the child of a childResult

    Inspector(const rt::Scene& s, ModelKind k) : scene(s), kind(k) {
        for (size_t i = 0; i < s.primitives.size(); ++i)
            index[s.primitives[i].get()] = int(i);
        tree.model = k;
    }

    const rt::ShadingModel& model() const {
        return kind == ModelKind::Course ? static_cast<const rt::ShadingModel&>(course) : phong;
    }

    int indexOf(const rt::Primitive* p) const {
        auto it = index.find(p);
        return it == index.end() ? -1 : it->second;
    }

    RayNode& current() { return tree.nodes[size_t(open.back())]; }

    void shade(RayNode& node, const rt::Ray& ray, const rt::Hit& hit, const rt::Material& m,
               const glm::dvec3& surface, const std::vector<rt::LightSample>& samples) {
        node.ambient = model().direct(scene, ray, hit, m, surface, {});
        for (size_t i = 0; i < samples.size(); ++i) {
            FeelerRecord f;
            const rt::LightSample& s = samples[i];
            f.light = int(i);
            f.toLight = s.toLight;
            f.distance = s.distance;
            f.facing = glm::dot(s.toLight, hit.normal) > 0;
            f.transmittance = s.transmittance;
            if (f.facing) {
                // Every blocker on the tracer's own feeler segment (Tracer::transmittance
                // stops at the first opaque one; the inspector lists them all).
                rt::Ray feeler;
                feeler.origin = hit.point;
                feeler.direction = s.toLight;
                const double t0 = rt::feelerStart(hit.point, hit.normal, s.toLight);
                if (t0 < s.distance)
                    scene.aggregate().forEachHit(feeler, t0, s.distance, [&](const rt::Hit& h) {
                        FeelerRecord::Blocker b;
                        b.primitive = indexOf(h.primitive);
                        b.kind = h.primitive ? primitiveKind(*h.primitive) : "?";
                        b.t = h.t;
                        b.point = h.point;
                        b.kt = scene.materials[size_t(h.material)].kt;
                        f.blockers.push_back(b);
                        return true;
                    });
                std::sort(f.blockers.begin(), f.blockers.end(),
                          [](const auto& a, const auto& b) { return a.t < b.t; });
            }
            if (kind == ModelKind::Course) {
                rt::CourseModel::Trace tr;
                course.trace = &tr;
                course.direct(scene, ray, hit, m, surface, {s});
                course.trace = nullptr;
                f.diffuse = tr.diffuse;
                f.specular = tr.specular;
                f.sh = tr.sh;
                f.ln = tr.ln;
                f.diffuseFactor = tr.diffuseFactor;
                f.halfVector = tr.halfVector;
                f.nn = tr.nn;
                f.nnp = tr.nnp;
                f.specularFactor = tr.specularFactor;
            } else {
                // The phong model is linear in its terms: split them by switching them off.
                rt::LightSample dark = s;
                dark.transmittance = 0; // keeps only the light's own ambient term
                f.lightAmbient = phong.direct(scene, ray, hit, m, surface, {dark}) - node.ambient;
                rt::Material noSpec = m, noDiff = m;
                noSpec.ks = 0;
                noDiff.kd = 0;
                f.diffuse = phong.direct(scene, ray, hit, noSpec, surface, {s}) - node.ambient -
                            f.lightAmbient;
                f.specular = phong.direct(scene, ray, hit, noDiff, surface, {s}) - node.ambient -
                             f.lightAmbient;
            }
            node.feelers.push_back(f);
        }
    }

    void rayBegin(const rt::Ray& ray, rt::RayKind what) override {
        RayNode n;
        n.kind = what == rt::RayKind::Primary     ? N_("primary") // tr() where shown
                 : what == rt::RayKind::Reflected ? N_("reflected")
                                                  : N_("refracted");
        n.parent = open.empty() ? -1 : open.back();
        n.ray = ray;
        open.push_back(int(tree.nodes.size()));
        tree.nodes.push_back(std::move(n));
    }

    void hit(const rt::Ray& ray, const rt::Hit& hit, const rt::Material& m,
             const glm::dvec3& surface, const std::vector<rt::LightSample>& samples,
             const rt::Color& direct) override {
        RayNode& n = current();
        n.hit = true;
        n.primitive = indexOf(hit.primitive);
        n.primitiveKind = hit.primitive ? primitiveKind(*hit.primitive) : "?";
        n.material = hit.material;
        n.t = hit.t;
        n.point = hit.point;
        n.outwardNormal = hit.outwardNormal;
        n.normal = hit.normal;
        n.cosVN = hit.cosVN;
        n.entering = hit.entering;
        n.solid = hit.solid;
        n.uv = hit.primitive ? hit.primitive->textureCoords(hit) : hit.uv;
        n.kr = m.kr;
        n.kt = m.kt;
        n.direct = direct;
        shade(n, ray, hit, m, surface, samples);
    }

    void childSkipped(rt::RayKind child, rt::SkipReason why) override {
        std::string& note = current().childNote;
        switch (why) {
        case rt::SkipReason::DepthLimit:
            // Told once per child; one note for both.
            if (note.find(tr("depth limit reached; ")) == std::string::npos)
                note += tr("depth limit reached; ");
            break;
        case rt::SkipReason::BelowWeight:
            note += child == rt::RayKind::Reflected
                        ? tr("reflected ray below the weight cut-off; ")
                        : tr("transmitted ray below the weight cut-off; ");
            break;
        case rt::SkipReason::TotalInternalReflection:
            note += tr("total internal reflection (no transmitted ray); ");
            break;
        case rt::SkipReason::RayBudget:
            note += tr("ray budget per pixel used up; ");
            break;
        }
    }

    void childResult(rt::RayKind child, const rt::Color& colour, double) override {
        RayNode& n = current();
        if (child == rt::RayKind::Reflected) {
            n.reflected = lastEnded;
            n.reflectedColour = colour;
        } else {
            n.refracted = lastEnded;
            n.refractedColour = colour;
        }
    }

    void attenuated(double factor) override { current().attenuation = factor; }

    void rayEnd(const rt::Color& colour) override {
        current().colour = colour;
        lastEnded = open.back();
        open.pop_back();
    }
};

std::string vec(const glm::dvec3& v) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "(%.3f, %.3f, %.3f)", v.x, v.y, v.z);
    return buf;
}
std::string colour(const rt::Color& c, ModelKind k) {
    char buf[96];
    if (k == ModelKind::Course)
        std::snprintf(buf, sizeof buf, "(%.0f, %.0f, %.0f)", c.x, c.y, c.z);
    else
        std::snprintf(buf, sizeof buf, "(%.3f, %.3f, %.3f)", c.x, c.y, c.z);
    return buf;
}

} // namespace

RayTree inspectRay(const LabScene& s, ModelKind model, const rt::TraceSettings& settings,
                   const rt::Ray& ray) {
    Inspector in(*s.scene, model);
    const rt::Tracer tracer(*s.scene, in.model(), settings);
    tracer.trace(ray, &in);
    // The unobserved trace must give the same colour: a mismatch is shown, never hidden.
    in.tree.tracerColour = tracer.trace(ray);
    in.tree.matchesTracer = in.tree.tracerColour == in.tree.nodes[0].colour;
    in.model().toRgb8(in.tree.nodes[0].colour, in.tree.rgb);
    return std::move(in.tree);
}

std::vector<std::string> describe(const RayTree& tree, const rt::Scene& scene) {
    // Each line one translatable sentence (the kinds and primitive names are N_() English, shown
    // through tr()); vectors and colours are numbers in every language.
    std::vector<std::string> out;
    const ModelKind k = tree.model;
    auto c = [k](const rt::Color& col) { return colour(col, k); };
    for (size_t i = 0; i < tree.nodes.size(); ++i) {
        const RayNode& n = tree.nodes[i];
        std::string indent(size_t(n.ray.depth) * 2, ' ');
        out.push_back(indent + trf("#%zu %s ray from %s dir %s weight %.3f n=%.2f", i,
                                   tr(n.kind.c_str()), vec(n.ray.origin).c_str(),
                                   vec(n.ray.direction).c_str(), n.ray.weight,
                                   n.ray.medium.refract));
        indent += "  ";
        if (!n.hit) {
            out.push_back(indent + trf("misses everything: background %s", c(n.colour).c_str()));
            continue;
        }
        out.push_back(indent + trf("hits %s #%lld at t = %.3f P = %s", tr(n.primitiveKind.c_str()),
                                   (long long)n.primitive, n.t, vec(n.point).c_str()));
        out.push_back(indent + trf("normal %s cos(V,N) = %.3f%s u = %.3f v = %.3f",
                                   vec(n.normal).c_str(), n.cosVN,
                                   n.solid ? (n.entering ? tr(" entering") : tr(" leaving"))
                                           : tr(" (open surface)"),
                                   n.uv.x, n.uv.y));
        out.push_back(indent + trf("ambient %s", c(n.ambient).c_str()));
        for (const FeelerRecord& f : n.feelers) {
            const std::string head =
                indent + trf("light %lld: L = %s dist %.2f", (long long)f.light,
                             vec(f.toLight).c_str(), f.distance);
            if (!f.facing) {
                out.push_back(head + tr(" behind the surface (no feeler)"));
                continue;
            }
            out.push_back(head + trf(" transmittance %.3f", f.transmittance));
            for (const auto& b : f.blockers)
                out.push_back(indent + trf("  blocked by %s #%lld at t = %.2f %s kt %.2f",
                                           tr(b.kind.c_str()), (long long)b.primitive, b.t,
                                           vec(b.point).c_str(), b.kt));
            if (k == ModelKind::Course) {
                out.push_back(indent + trf("  SH %.3f LN %.3f SH*LN*KD %.3f diffuse %s", f.sh, f.ln,
                                           f.diffuseFactor, c(f.diffuse).c_str()));
                out.push_back(indent + trf("  n %s n.N %.3f ^P %.3f SH*KS*NNP %.3f specular %s",
                                           vec(f.halfVector).c_str(), f.nn, f.nnp, f.specularFactor,
                                           c(f.specular).c_str()));
            } else {
                out.push_back(indent + trf("  diffuse %s specular %s light ambient %s",
                                           c(f.diffuse).c_str(), c(f.specular).c_str(),
                                           c(f.lightAmbient).c_str()));
            }
        }
        (void)scene;
        out.push_back(indent + trf("direct %s", c(n.direct).c_str()));
        if (n.reflected >= 0)
            out.push_back(indent + trf("+ reflected #%lld %s x kr %.2f", (long long)n.reflected,
                                       c(n.reflectedColour).c_str(), n.kr));
        if (n.refracted >= 0)
            out.push_back(indent + trf("+ transmitted #%lld %s x kt %.2f", (long long)n.refracted,
                                       c(n.refractedColour).c_str(), n.kt));
        if (!n.childNote.empty()) out.push_back(indent + n.childNote);
        if (n.attenuation != 1.0)
            out.push_back(indent + trf("x attenuation exp(-atten t) = %.4f", n.attenuation));
        out.push_back(indent + "= " + c(n.colour));
    }
    out.push_back(trf("pixel RGB (%d, %d, %d); tracer says %s %s", tree.rgb[0], tree.rgb[1],
                      tree.rgb[2], c(tree.tracerColour).c_str(),
                      tree.matchesTracer ? tr("(same)") : tr("(DIFFERS: inspector out of step)")));
    return out;
}

} // namespace wb
