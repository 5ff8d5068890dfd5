#pragma once
// Lab 02: the Phong lighting model of OpenGL (practical 2 §1.2.4, lab 2). Two cubes
// under one light: (a) vertex normals perpendicular to the faces, (b) from the cube
// centre through the vertex; keys 1-4 switch the lab's 2x2 table of material and light.
#include "common/gl.h"
#include "common/lab.h"
#include "core/lighting.h"

#include <glm/glm.hpp>

#include <memory>

namespace wb {

// How the faces of the cubes get their colour.
enum class FaceShading {
    Gouraud, // lit at the vertices of each N×N grid cell, colours interpolated (N = 1: 4 vertices)
    PhongGlsl, // per-fragment lighting in shaders/phong.frag, same equation
};

// Everything the lab shows; plain data so tests can set it and read it.
struct LightingState {
    // 1..4: {specular, diffuse} material × {specular, diffuse} light, the lab's table
    int combo = 1;
    bool compareAll = false;     // key 5: the four combinations side by side (2×2), same state
    bool globalAmbientOn = true; // GL_LIGHT_MODEL_AMBIENT = globalAmbient, else black
    // GL_LIGHT_MODEL_AMBIENT: twice GL's default 0.2, so that combinations 1 and 3 (no
    // diffuse light) show the cubes at 0.2·0.4 = 0.08, 20/255 - dark silhouettes that read
    // against the background below (at 0.2 they were 10/255 on a 20/255 background).
    glm::vec3 globalAmbient{0.4f, 0.4f, 0.4f};
    // glClearColor: a mid grey-blue, far from both the dark ambient-only cubes (20/255)
    // and the white highlights, so every combination reads on a projector.
    glm::vec3 background{0.42f, 0.45f, 0.5f};
    bool localViewer = false;              // GL_LIGHT_MODEL_LOCAL_VIEWER
    bool emissionOn = false;               // material GL_EMISSION = emission, else black
    glm::vec3 emission{0.0f, 0.0f, 0.35f}; // GL_EMISSION colour when on
    bool smooth = true;                    // glShadeModel GL_SMOOTH (true) or GL_FLAT
    FaceShading shading = FaceShading::Gouraud;
    int subdivisions = 1; // N of the N×N grid per face, 1..64 (1 = the plain 4-vertex face)
    // GL_POSITION in scene coordinates; w = 0 makes it directional
    glm::vec4 lightPos{-1.0f, 2.5f, 5.0f, 1.0f};
    glm::vec3 lightColor{1.0f, 1.0f, 1.0f};  // the light's diffuse or specular colour (by combo)
    glm::vec3 attenuation{1.0f, 0.0f, 0.0f}; // kc, kl, kq
    bool spotOn = false;                     // GL_SPOT_CUTOFF = spotCutoff, else 180
    glm::vec3 spotTarget{1.6f, 0.0f, 0.0f};  // the spot points from the light to this point
    float spotCutoff = 25.0f;                // degrees, 0..90
    float spotExponent = 8.0f;               // 0..128
    bool showMarker = true;                  // draw the light's position as an unlit marker
    bool showBlocker = false;                // a plate between the light and the right cube
    float cubeSpin = 0.0f;                   // degrees about the vertical axis, both cubes
    float tilt = 20.0f;                      // degrees the camera looks down on the cubes
};

// The material and light of combination 1..4 (specular material: weak diffuse, white
// highlight, shininess 12.8 as in the lab's listing; specular light: only GL_SPECULAR).
Material comboMaterial(const LightingState& s);
Light comboLight(const LightingState& s); // position and spot direction in scene coordinates
LightModel lightModel(const LightingState& s);
const char* comboName(int combo);
// What to look for in combination 1..4: one sentence for the panel.
const char* comboLookFor(int combo);

// Send core lighting state to GL: the light's position and spot direction are
// transformed by the current modelview, as glLightfv does.
void glApplyMaterial(const Material& m);
void glApplyLight(GLenum light, const Light& l);
void glApplyLightModel(const LightModel& m);

// The camera: perspective with this vertical field of view (degrees, divided by the
// zoom), the scene centre this far in front of the eye, tilted down by state.tilt.
constexpr double kLightingFovy = 35.0;
constexpr double kLightingDistance = 10.0;
constexpr float kCubeOffset = 1.6f; // the cubes' centres are at x = ∓kCubeOffset, half-size 1

std::unique_ptr<Lab> makeLightingLab();
// The lab working on `observe` (owned by the caller), so tests can set and read its state.
std::unique_ptr<Lab> makeLightingLab(LightingState* observe);

} // namespace wb
