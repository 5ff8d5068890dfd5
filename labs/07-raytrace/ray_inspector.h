#pragma once
// The ray inspector: the whole ray tree of one pixel, every hit (object, t, point,
// normal, entering or leaving), every shadow feeler with the objects that blocked it,
// and each term of the colour (ambient, per-light diffuse and specular, reflected × kr,
// transmitted × kt, attenuation). The tree is built from the events of the tracer's own
// recursion (Tracer::trace with an rt::TraceObserver), so no rule exists twice; the
// feelers' blocker lists use the tracer's segment (rt::feelerStart). The root colour is
// checked against the unobserved Tracer::trace: a mismatch is shown, never hidden.
#include "lab_scenes.h"

#include "core/raytrace/shading.h"
#include "core/raytrace/tracer.h"

#include <string>
#include <vector>

namespace wb {

struct FeelerRecord {
    struct Blocker {
        int primitive = -1; // index into Scene::primitives
        std::string kind;   // "sphere", "rectangle", ...
        double t = 0.0;     // distance from the hit point along the feeler
        glm::dvec3 point{0.0};
        double kt = 0.0; // its material's kt (< opaqueKt blocks fully)
    };
    int light = 0;              // index into Scene::lights
    glm::dvec3 toLight{0.0};    // unit
    double distance = 0.0;      // to the light (inf for a directional one)
    bool facing = false;        // the light is on the normal's side (else no feeler is shot)
    double transmittance = 0.0; // Π kt of the blockers, as the tracer computed it
    std::vector<Blocker> blockers;
    // The colour this light adds, in the model's units (course: the integer terms).
    rt::Color diffuse{0.0}, specular{0.0};
    rt::Color lightAmbient{0.0}; // phong model: the light's own GL_AMBIENT term
    // Course model figures of this light (seed 000 prints them).
    double sh = 0.0, ln = 0.0, diffuseFactor = 0.0, nn = 0.0, nnp = 0.0, specularFactor = 0.0;
    glm::dvec3 halfVector{0.0};
};

struct RayNode {
    std::string kind; // "primary", "reflected", "refracted"
    int parent = -1;  // index into RayTree::nodes
    rt::Ray ray;
    bool hit = false;
    int primitive = -1;        // index into Scene::primitives
    std::string primitiveKind; // "sphere", "rectangle", ...
    int material = 0;
    double t = 0.0;
    glm::dvec3 point{0.0}, outwardNormal{0.0}, normal{0.0}; // normal: against the ray
    double cosVN = 0.0;
    bool entering = false, solid = false;
    glm::dvec2 uv{0.0};
    rt::Color ambient{0.0}; // course: BA·C·KA; phong: emission + global ambient·a_cm
    std::vector<FeelerRecord> feelers;
    rt::Color direct{0.0}; // ambient + every light, as the model sums them
    double kr = 0.0, kt = 0.0;
    int reflected = -1, refracted = -1; // child nodes, -1 when not traced
    std::string childNote;              // why a child ray was not traced (depth, weight, TIR)
    rt::Color reflectedColour{0.0}, refractedColour{0.0}; // child results before × k
    double attenuation = 1.0; // exp(−atten·t) of the medium this ray travelled in
    rt::Color colour{0.0};    // what this ray carries back
};

struct RayTree {
    std::vector<RayNode> nodes; // nodes[0] is the primary ray
    ModelKind model = ModelKind::Phong;
    rt::Color tracerColour{0.0}; // Tracer::trace of the same ray, for the check
    bool matchesTracer = false;  // nodes[0].colour == tracerColour exactly
    uint8_t rgb[3] = {0, 0, 0};  // the pixel as written to the image
};

// Name of a primitive's type ("sphere", "plane", ...).
std::string primitiveKind(const rt::Primitive& p);

RayTree inspectRay(const LabScene& scene, ModelKind model, const rt::TraceSettings& settings,
                   const rt::Ray& ray);

// The tree as text, one line per fact, for the panel and for --inspect.
std::vector<std::string> describe(const RayTree& tree, const rt::Scene& scene);

} // namespace wb
