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

#include <algorithm>
#include <cstdio>
#include <unordered_map>

namespace wb {

std::string primitiveKind(const rt::Primitive& p) {
    if (dynamic_cast<const rt::Sphere*>(&p)) return "sphere";
    if (dynamic_cast<const rt::Plane*>(&p)) return "plane";
    if (dynamic_cast<const rt::Rectangle*>(&p)) return "rectangle";
    if (dynamic_cast<const rt::SmoothTriangle*>(&p)) return "smooth triangle";
    if (dynamic_cast<const rt::Triangle*>(&p)) return "triangle";
    if (dynamic_cast<const rt::Box*>(&p)) return "box";
    if (dynamic_cast<const rt::ConvexPolyhedron*>(&p)) return "polyhedron";
    if (auto* c = dynamic_cast<const rt::Cone*>(&p)) return c->r0 == c->r1 ? "cylinder" : "cone";
    if (auto* q = dynamic_cast<const rt::Quadric*>(&p)) {
        switch (q->kind) {
        case rt::Quadric::Kind::Ellipsoid:
            return "ellipsoid";
        case rt::Quadric::Kind::Paraboloid:
            return "paraboloid";
        case rt::Quadric::Kind::Hyperboloid:
            return "hyperboloid";
        }
    }
    return "primitive";
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
        n.kind = what == rt::RayKind::Primary     ? "primary"
                 : what == rt::RayKind::Reflected ? "reflected"
                                                  : "refracted";
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
            if (note.find("depth limit") == std::string::npos) note += "depth limit reached; ";
            break;
        case rt::SkipReason::BelowWeight:
            note += child == rt::RayKind::Reflected ? "reflected ray below the weight cut-off; "
                                                    : "transmitted ray below the weight cut-off; ";
            break;
        case rt::SkipReason::TotalInternalReflection:
            note += "total internal reflection (no transmitted ray); ";
            break;
        case rt::SkipReason::RayBudget:
            note += "ray budget per pixel used up; ";
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

std::string fmt(const char* f, double a) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, a);
    return buf;
}
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
    std::vector<std::string> out;
    const ModelKind k = tree.model;
    for (size_t i = 0; i < tree.nodes.size(); ++i) {
        const RayNode& n = tree.nodes[i];
        std::string indent(size_t(n.ray.depth) * 2, ' ');
        out.push_back(indent + "#" + std::to_string(i) + " " + n.kind + " ray from " +
                      vec(n.ray.origin) + " dir " + vec(n.ray.direction) +
                      fmt(" weight %.3f", n.ray.weight) + fmt(" n=%.2f", n.ray.medium.refract));
        indent += "  ";
        if (!n.hit) {
            out.push_back(indent + "misses everything: background " + colour(n.colour, k));
            continue;
        }
        out.push_back(indent + "hits " + n.primitiveKind + " #" + std::to_string(n.primitive) +
                      fmt(" at t = %.3f", n.t) + " P = " + vec(n.point));
        out.push_back(indent + "normal " + vec(n.normal) + fmt(" cos(V,N) = %.3f", n.cosVN) +
                      (n.solid ? (n.entering ? " entering" : " leaving") : " (open surface)") +
                      fmt(" u = %.3f", n.uv.x) + fmt(" v = %.3f", n.uv.y));
        out.push_back(indent + "ambient " + colour(n.ambient, k));
        for (const FeelerRecord& f : n.feelers) {
            const rt::Light& l = scene.lights[size_t(f.light)];
            std::string head = indent + "light " + std::to_string(f.light) +
                               ": L = " + vec(f.toLight) + fmt(" dist %.2f", f.distance);
            if (!f.facing) {
                out.push_back(head + " behind the surface (no feeler)");
                continue;
            }
            out.push_back(head + fmt(" transmittance %.3f", f.transmittance));
            for (const auto& b : f.blockers)
                out.push_back(indent + "  blocked by " + b.kind + " #" +
                              std::to_string(b.primitive) + fmt(" at t = %.2f", b.t) + " " +
                              vec(b.point) + fmt(" kt %.2f", b.kt));
            if (k == ModelKind::Course) {
                out.push_back(indent + fmt("  SH %.3f", f.sh) + fmt(" LN %.3f", f.ln) +
                              fmt(" SH*LN*KD %.3f", f.diffuseFactor) + " diffuse " +
                              colour(f.diffuse, k));
                out.push_back(indent + "  n " + vec(f.halfVector) + fmt(" n.N %.3f", f.nn) +
                              fmt(" ^P %.3f", f.nnp) + fmt(" SH*KS*NNP %.3f", f.specularFactor) +
                              " specular " + colour(f.specular, k));
            } else {
                out.push_back(indent + "  diffuse " + colour(f.diffuse, k) + " specular " +
                              colour(f.specular, k) + " light ambient " +
                              colour(f.lightAmbient, k));
            }
            (void)l;
        }
        out.push_back(indent + "direct " + colour(n.direct, k));
        if (n.reflected >= 0)
            out.push_back(indent + "+ reflected #" + std::to_string(n.reflected) + " " +
                          colour(n.reflectedColour, k) + fmt(" x kr %.2f", n.kr));
        if (n.refracted >= 0)
            out.push_back(indent + "+ transmitted #" + std::to_string(n.refracted) + " " +
                          colour(n.refractedColour, k) + fmt(" x kt %.2f", n.kt));
        if (!n.childNote.empty()) out.push_back(indent + n.childNote);
        if (n.attenuation != 1.0)
            out.push_back(indent + fmt("x attenuation exp(-atten t) = %.4f", n.attenuation));
        out.push_back(indent + "= " + colour(n.colour, k));
    }
    char buf[160];
    std::snprintf(buf, sizeof buf, "pixel RGB (%d, %d, %d); tracer says %s %s", tree.rgb[0],
                  tree.rgb[1], tree.rgb[2], colour(tree.tracerColour, k).c_str(),
                  tree.matchesTracer ? "(same)" : "(DIFFERS: inspector out of step)");
    out.push_back(buf);
    return out;
}

} // namespace wb
