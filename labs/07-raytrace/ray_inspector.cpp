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
#include "core/raytrace/texture.h"
#include "core/raytrace/triangle.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
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

struct Inspector {
    const rt::Scene& scene;
    ModelKind kind;
    rt::TraceSettings settings;
    rt::CourseModel course;
    rt::PhongModel phong;
    std::unordered_map<const rt::Primitive*, int> index;
    RayTree tree;

    const rt::ShadingModel& model() const {
        return kind == ModelKind::Course ? static_cast<const rt::ShadingModel&>(course) : phong;
    }

    int indexOf(const rt::Primitive* p) const {
        auto it = index.find(p);
        return it == index.end() ? -1 : it->second;
    }

    // The tracer's feeler start (tracer.cpp, feelerStart): as far along the feeler as the
    // normal offset of reflected rays puts an origin off the surface.
    static double feelerStart(const glm::dvec3& p, const glm::dvec3& n, const glm::dvec3& dir) {
        const double eps = glm::length(rt::offsetRayOrigin(p, n) - p);
        return eps / std::max(glm::dot(dir, n), 1e-3);
    }

    void shade(RayNode& node, const rt::Ray& ray, const rt::Hit& hit, const rt::Material& m,
               const glm::dvec3& surface, const std::vector<rt::LightSample>& samples) {
        const rt::ShadingModel& mod = model();
        node.direct = mod.direct(scene, ray, hit, m, surface, samples);
        node.ambient = mod.direct(scene, ray, hit, m, surface, {});
        for (size_t i = 0; i < samples.size(); ++i) {
            FeelerRecord f;
            const rt::LightSample& s = samples[i];
            f.light = int(i);
            f.toLight = s.toLight;
            f.distance = s.distance;
            f.facing = glm::dot(s.toLight, hit.normal) > 0;
            f.transmittance = s.transmittance;
            if (f.facing) {
                rt::Ray feeler;
                feeler.origin = hit.point;
                feeler.direction = s.toLight;
                const double t0 = feelerStart(hit.point, hit.normal, s.toLight);
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

    int trace(const rt::Ray& ray, const std::string& what, int parent) {
        const rt::Tracer tracer(scene, model(), settings);
        const int id = int(tree.nodes.size());
        tree.nodes.emplace_back();
        {
            RayNode& n = tree.nodes.back();
            n.kind = what;
            n.parent = parent;
            n.ray = ray;
        }
        rt::Hit hit;
        if (!scene.intersect(ray, 0.0, std::numeric_limits<double>::infinity(), hit)) {
            tree.nodes[size_t(id)].colour = model().background(scene);
            return id;
        }
        const rt::Material& m = scene.materials[size_t(hit.material)];
        const glm::dvec3 surface =
            (m.texture && hit.hasUv) ? rt::sampleTexture(*m.texture, hit.uv) : m.colour;
        {
            RayNode& n = tree.nodes[size_t(id)];
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
            n.uv = hit.uv;
            n.kr = m.kr;
            n.kt = m.kt;
            shade(n, ray, hit, m, surface, tracer.sampleLights(hit));
        }
        rt::Color c = tree.nodes[size_t(id)].direct;
        std::string note;
        if (ray.depth < settings.maxDepth) {
            if (m.kr > 0) {
                if (ray.weight * m.kr >= settings.minWeight) {
                    rt::Ray r;
                    r.origin = rt::offsetRayOrigin(hit.point, hit.normal);
                    r.direction = rt::reflectDir(ray.direction, hit.normal);
                    r.weight = ray.weight * m.kr;
                    r.medium = ray.medium;
                    r.depth = ray.depth + 1;
                    const int child = trace(r, "reflected", id);
                    tree.nodes[size_t(id)].reflected = child;
                    tree.nodes[size_t(id)].reflectedColour = tree.nodes[size_t(child)].colour;
                    c = model().addScaled(c, tree.nodes[size_t(child)].colour, m.kr);
                } else {
                    note += "reflected ray below the weight cut-off; ";
                }
            }
            if (m.kt > 0) {
                if (ray.weight * m.kt >= settings.minWeight) {
                    std::optional<glm::dvec3> dir = ray.direction;
                    rt::Medium medium = ray.medium;
                    if (hit.solid) {
                        double eta;
                        if (hit.entering) {
                            eta = ray.medium.refract / m.medium.refract;
                            medium = m.medium;
                        } else {
                            eta = m.medium.refract / scene.air.refract;
                            medium = scene.air;
                        }
                        dir = rt::refractDir(ray.direction, hit.normal, eta);
                    }
                    if (dir) {
                        rt::Ray t;
                        t.origin = rt::offsetRayOrigin(hit.point, -hit.normal);
                        t.direction = *dir;
                        t.weight = ray.weight * m.kt;
                        t.medium = medium;
                        t.depth = ray.depth + 1;
                        const int child = trace(t, "refracted", id);
                        tree.nodes[size_t(id)].refracted = child;
                        tree.nodes[size_t(id)].refractedColour = tree.nodes[size_t(child)].colour;
                        c = model().addScaled(c, tree.nodes[size_t(child)].colour, m.kt);
                    } else {
                        note += "total internal reflection (no transmitted ray); ";
                    }
                } else {
                    note += "transmitted ray below the weight cut-off; ";
                }
            }
        } else if (m.kr > 0 || m.kt > 0) {
            note += "depth limit reached; ";
        }
        RayNode& n = tree.nodes[size_t(id)];
        n.childNote = note;
        if (ray.medium.atten > 0) {
            n.attenuation = std::exp(-ray.medium.atten * hit.t);
            c = model().scale(c, n.attenuation);
        }
        n.colour = c;
        return id;
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
    Inspector in{*s.scene, model, settings, {}, {}, {}, {}};
    for (size_t i = 0; i < s.scene->primitives.size(); ++i)
        in.index[s.scene->primitives[i].get()] = int(i);
    in.tree.model = model;
    in.trace(ray, "primary", -1);
    const rt::Tracer tracer(*s.scene, in.model(), settings);
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
