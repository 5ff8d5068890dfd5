#pragma once
// Light sources: point or directional, with a colour. The course model uses the
// colour and (for point lights) the distance; the phong model also uses GL's
// attenuation and spot parameters (the same meaning as glLightfv's).
#include <glm/glm.hpp>

namespace wb::rt {

struct Light {
    enum class Kind { Point, Directional };
    Kind kind = Kind::Point;  // point light at `position` or light from direction `direction`
    glm::dvec3 position{0.0}; // world position (point lights)
    glm::dvec3 direction{0, 0,
                         -1}; // direction the light travels (directional lights), any length > 0
    glm::dvec3 colour{1.0};   // intensity per channel, 0..1 (seed 000's BL = (255,255,255) is 1)

    // GL parameters for the phong model only (defaults are GL_LIGHT0's).
    glm::dvec3 ambient{0.0};            // GL_AMBIENT of the light
    double constantAttenuation = 1.0;   // k0
    double linearAttenuation = 0.0;     // k1
    double quadraticAttenuation = 0.0;  // k2
    glm::dvec3 spotDirection{0, 0, -1}; // GL_SPOT_DIRECTION
    double spotExponent = 0.0;          // GL_SPOT_EXPONENT
    double spotCutoff = 180.0;          // GL_SPOT_CUTOFF in degrees, 180 = no spot

    static Light point(const glm::dvec3& p, const glm::dvec3& c = glm::dvec3(1.0)) {
        Light l;
        l.position = p;
        l.colour = c;
        return l;
    }
    static Light directional(const glm::dvec3& dir, const glm::dvec3& c = glm::dvec3(1.0)) {
        Light l;
        l.kind = Kind::Directional;
        l.direction = dir;
        l.colour = c;
        return l;
    }
};

} // namespace wb::rt
