#pragma once
// The OpenGL fixed-function lighting equation (OpenGL 2.1 spec §2.14.1, practical 2
// §1.2.4 and lab 2) in plain C++, so that tests can check what the GL draws and the
// ray tracer can shade with the same model as the rasterizer:
//
//   c = e_cm + a_cm·a_cs
//       + Σ_i att_i · spot_i · [ a_cm·a_cli + (n⊙VP_i)·d_cm·d_cli + f_i·(n⊙ĥ_i)^s_rm · s_cm·s_cli ]
//
// clamped to [0, 1] per channel, where x⊙y = max(x·y, 0). Everything is in eye
// coordinates (the eye at the origin looking down −z), as GL computes it: light
// positions and spot directions are the ones glLightfv stored after the modelview
// transform, positions and normals are the vertex's eye-space ones.
#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace wb {

// GL_FRONT (or GL_BACK) material state; defaults are GL's initial values.
struct Material {
    glm::dvec4 emission{0, 0, 0, 1};      // GL_EMISSION e_cm: added whatever the lights do
    glm::dvec4 ambient{0.2, 0.2, 0.2, 1}; // GL_AMBIENT a_cm: scales global and per-light ambient
    glm::dvec4 diffuse{0.8, 0.8, 0.8, 1}; // GL_DIFFUSE d_cm; its alpha is the vertex alpha
    glm::dvec4 specular{0, 0, 0, 1};      // GL_SPECULAR s_cm
    double shininess = 0;                 // GL_SHININESS s_rm, 0..128
};

// One light source (GL_LIGHTi); defaults are those of GL_LIGHT0.
struct Light {
    bool enabled = true;                // glEnable(GL_LIGHTi)
    glm::dvec4 ambient{0, 0, 0, 1};     // GL_AMBIENT a_cli
    glm::dvec4 diffuse{1, 1, 1, 1};     // GL_DIFFUSE d_cli (GL_LIGHT1..7 start at 0)
    glm::dvec4 specular{1, 1, 1, 1};    // GL_SPECULAR s_cli (GL_LIGHT1..7 start at 0)
    glm::dvec4 position{0, 0, 1, 0};    // GL_POSITION P_pli in eye space; w = 0: directional,
                                        // the light lies at infinity in direction (x, y, z)
    glm::dvec3 spotDirection{0, 0, -1}; // GL_SPOT_DIRECTION s_dli in eye space, any length > 0
    double spotExponent = 0;            // GL_SPOT_EXPONENT s_rli, 0..128
    double spotCutoff = 180;            // GL_SPOT_CUTOFF c_rli in degrees: 0..90, or 180 = no spot
    double constantAttenuation = 1;     // GL_CONSTANT_ATTENUATION k0 >= 0
    double linearAttenuation = 0;       // GL_LINEAR_ATTENUATION k1 >= 0
    double quadraticAttenuation = 0;    // GL_QUADRATIC_ATTENUATION k2 >= 0
};

// GL_LIGHT_MODEL_* state; defaults are GL's initial values.
struct LightModel {
    glm::dvec4 ambient{0.2, 0.2, 0.2, 1}; // GL_LIGHT_MODEL_AMBIENT a_cs
    bool localViewer = false;             // GL_LIGHT_MODEL_LOCAL_VIEWER v_bs: true = eye at the
                                          // origin, false = eye at infinity along +z
    bool twoSide = false;                 // GL_LIGHT_MODEL_TWO_SIDE: back faces use the back
                                          // material and the negated normal
};

// The factors of one light's term at one vertex, for the lab panel and for tests.
struct LightTerms {
    double attenuation =
        1;           // att_i: 1/(k0 + k1·d + k2·d²) for a positional light, 1 for a directional
    double spot = 1; // spot_i: (−VP⊙ŝ)^s_rli inside the cone, 0 outside, 1 when c_rli = 180
    double diffuse = 0;  // n⊙VP_i, the cosine of the angle of incidence (0 when facing away)
    double specular = 0; // f_i·(n⊙ĥ_i)^s_rm: 0 when n⊙VP_i = 0
    glm::dvec3 color{
        0}; // att·spot·(a_cm·a_cli + diffuse·d_cm·d_cli + specular·s_cm·s_cli), unclamped
};

// One light's contribution to a vertex at eye-space `position` with unit `normal`.
// Follows the spec, with the choices Mesa (and every desktop GL) makes where the spec
// leaves room: the spot factor applies to positional lights only (a directional light
// has no "vector from the light to the vertex"); a zero half vector (light exactly
// behind the viewer) gives no highlight; a zero attenuation denominator is treated as
// 1e-12 so the result stays finite (GL gives Inf there).
LightTerms lightTerms(const Light& light, const Material& material, bool localViewer,
                      const glm::dvec3& position, const glm::dvec3& normal);
// The same attenuation, spot, diffuse and specular factors (bit for bit) without the
// colour sum: for a caller that weighs the terms itself (the ray tracer, once per hit
// and light), which needs only the material's shininess.
LightTerms lightFactors(const Light& light, double shininess, bool localViewer,
                        const glm::dvec3& position, const glm::dvec3& normal);
// The unit vector from a vertex at eye-space `position` to the viewer: −position
// normalised for a local viewer (zero at the eye itself), +z for one at infinity.
glm::dvec3 eyeDirection(bool localViewer, const glm::dvec3& position);
// lightFactors with the viewer's direction `toEye` = eyeDirection(localViewer, position)
// given, for a caller that evaluates several lights at one vertex and computes it once
// (the ray tracer); bit for bit the factors of the overload above.
LightTerms lightFactors(const Light& light, double shininess, const glm::dvec3& toEye,
                        const glm::dvec3& position, const glm::dvec3& normal);

// The colour GL computes for a vertex: emission + global ambient + every enabled
// light, each channel clamped to [0, 1]; alpha is the material's diffuse alpha.
// `backFacing` matters only with model.twoSide: then `back` and −normal are used.
glm::dvec4 shadeVertex(const LightModel& model, const std::vector<Light>& lights,
                       const Material& front, const glm::dvec3& position, const glm::dvec3& normal,
                       bool backFacing = false, const Material* back = nullptr);

// The unclamped sum (for a ray tracer that adds reflected light before clamping).
glm::dvec3 shadeVertexUnclamped(const LightModel& model, const std::vector<Light>& lights,
                                const Material& material, const glm::dvec3& position,
                                const glm::dvec3& normal);

// Checks the ranges glLightfv/glMaterialfv accept (GL raises GL_INVALID_VALUE outside
// them); returns an empty string when valid, else a message naming the field.
std::string validateLight(const Light& light);
std::string validateMaterial(const Material& material);

} // namespace wb
