#pragma once
// Surface of seed 000 (GREENSurface): colour, ka, kd, ks, kr, kt, Phong exponent and
// the medium inside the body. The phong model reads the same fields as a GL material
// (ambient = ka·colour, diffuse = kd·colour, specular = ks·white, shininess = p) plus emission.
#include "core/image.h"
#include "core/raytrace/ray.h"

#include <glm/glm.hpp>

namespace wb::rt {

struct Material {
    glm::dvec3 colour{1.0};   // surface colour, 0..1 (seed 000: (21,234,21)/255)
    double ka = 0.5;          // ambient coefficient
    double kd = 0.5;          // diffuse coefficient
    double ks = 0.5;          // specular coefficient
    double kr = 0.0;          // weight of the reflected ray
    double kt = 0.0;          // weight of the transmitted ray; also lets light through to shadows
    double phongExp = 3.0;    // Phong exponent p
    Medium medium;            // medium inside the body (solids only): refraction index, attenuation
    glm::dvec3 emission{0.0}; // GL_EMISSION, phong model only, 0..1
    const Image* texture = nullptr; // optional; replaces `colour` where the primitive has uv
};

} // namespace wb::rt
