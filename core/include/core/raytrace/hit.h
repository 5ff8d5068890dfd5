#pragma once
// What an intersection reports: seed 000's GREENInter (distance, point, normal
// turned against the ray, cos(v,n), entering flag, surface) plus texture coordinates.
#include <glm/glm.hpp>

namespace wb::rt {

class Primitive;

struct Hit {
    double t = 0.0;                    // distance along the (unit) ray direction
    glm::dvec3 point{0.0};             // hit point, refined onto the surface by the primitive
    glm::dvec3 outwardNormal{0, 0, 1}; // unit normal pointing out of the body / to the front side
    glm::dvec3 normal{0, 0, 1};        // unit normal turned against the ray (cosVN <= 0)
    double cosVN = 0.0;                // dot(ray direction, normal), <= 0 (seed 000's cosvn)
    bool entering = false; // the ray enters a closed body here (false for open surfaces)
    bool solid = false;    // the primitive is a closed body (refraction changes medium)
    glm::dvec2 uv{0.0};    // texture coordinates when hasUv; read them through
                           // primitive->textureCoords(hit) (sphere, quadric fill them lazily)
    bool hasUv = false;    // the primitive provides texture coordinates
    int material = 0;      // index into Scene::materials
    const Primitive* primitive = nullptr; // who was hit
};

} // namespace wb::rt
