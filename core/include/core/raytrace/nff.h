#pragma once
// Eric Haines' Neutral File Format (the Standard Procedural Databases format), every
// command: `v` block (from, at, up, angle, hither, resolution), `b`, `l` with an
// optional colour, `f` (r g b Kd Ks Shine T ior), `c` (cone/cylinder, one-line and
// three-line forms), `s`, `p` (convex polygon), `pp` (polygon with vertex normals),
// `#` comments. The document model keeps the file's commands in order, so a
// read–write–read round trip is exact; toScene maps it onto the "phong" model.
//
// Mapping (how SPD authors meant it): colour = rgb, kd = Kd, ks = Ks, Phong
// exponent = Shine, kr = Ks (Ks is also the mirror reflectance), kt = T, refraction
// index inside = ior (> 0 required when T > 0; an opaque surface never uses it and the
// SPD generators write 0), ka = 0 (NFF has no ambient term) and the
// scene's global ambient 0; `l` without a colour has intensity 1/sqrt(number of
// lights), so the sum of all lights stays near 1; polygons become fans of
// triangles (`pp`: with interpolated vertex normals); `c` becomes a capped Cone
// (NFF's negative radii, which some writers use, are read as their absolute value).
//
// Limits (hostile input, issue 12): a polygon may have 3..kNffMaxVertices vertices, a
// file at most kNffMaxPrimitives primitives and kNffMaxLights lights, and at most
// kNffMaxBytes bytes; only regular files are read (a FIFO or device is refused, see
// core/file_read.h); numbers must be finite; coordinates and radii within
// ±kNffMaxCoordinate; colours, Kd, Ks and T within [0, 1], Shine within [0, 1e6],
// light and background colours within [0, kNffMaxIntensity]; the resolution at most
// 16384². Line ends may be LF, CR LF or CR; a UTF-8 byte order mark is skipped. Errors
// name the file, the line and the problem; bytes of the file appear escaped (\xNN).
#include "core/raytrace/scene_file.h"

#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

namespace wb::rt {

constexpr int kNffMaxVertices = 100000; // per polygon
// Per file: balls 6 has 0.6 million; 4 million primitives take about 1.5 GB at peak
// (document, scene and BVH), so a hostile file cannot exhaust memory.
constexpr std::size_t kNffMaxPrimitives = 4000000;
// Per file: every light costs a shadow feeler at every hit, so time grows with
// lights × hits (200,000 lights took 50 s at 160×120). The SPD databases use at most
// a handful; 1000 keeps the worst case near 0.3 s at 160×120 and a few seconds at 512².
constexpr std::size_t kNffMaxLights = 1000;
// Ear clipping of concave polygons, per file (issue 20 point 3): vertex visits in all
// (ear clipping is O(n·r) per polygon). 10^8 visits take about 1 s here; a random
// 10^5-gon needs more and the file is refused naming its line (it took 8.4 s, and 40 of
// them over a minute). SPD gears need about 10^4 visits per face.
constexpr long long kNffEarClipWork = 100'000'000;
// Largest file: the text is read whole; 4 million primitives written as `p 3` polygons
// take about 400 MB, so 512 MB holds any file within the primitive cap with comments.
constexpr std::size_t kNffMaxBytes = std::size_t(512) << 20;
// Largest |coordinate| or radius: the tracer squares coordinate differences (sphere
// |f|², triangle edge products); with coordinates up to 1e150 and the framing camera
// a few radii away, squares stay near 1e302, below DBL_MAX ≈ 1.8e308. Beyond about
// 1e154 they overflow and the geometry vanished silently.
constexpr double kNffMaxCoordinate = 1e150;
// Largest light or background component: far above any meaningful intensity, and
// 1000 lights × 1e6 × any depth stay finite.
constexpr double kNffMaxIntensity = 1e6;

struct NffSurface {
    glm::dvec3 colour{1.0}; // r g b, 0..1
    double kd = 1.0;        // diffuse
    double ks = 0.0;        // specular and mirror reflectance
    double shine = 0.0;     // Phong exponent
    double t = 0.0;         // transmittance
    double ior = 1.0;       // index of refraction
};

struct NffLight {
    glm::dvec3 position{0.0}; // point light
    glm::dvec3 colour{1.0};   // valid when hasColour
    bool hasColour = false;   // the file gave r g b
};

struct NffObject {
    enum class Kind { Sphere, Cone, Polygon, PatchPolygon };
    Kind kind = Kind::Sphere;
    int surface = -1;                // index into NffDocument::surfaces (-1: none seen yet)
    glm::dvec3 centre{0.0};          // sphere
    double radius = 0.0;             // sphere
    glm::dvec3 base{0.0}, apex{0.0}; // cone
    double baseRadius = 0.0, apexRadius = 0.0; // cone
    bool coneOneLine = false;                  // cone written as `c x y z r x y z r` on one line
    std::vector<glm::dvec3> vertices;          // polygon / patch
    std::vector<glm::dvec3> normals;           // patch: one per vertex
    int line = 0; // line of the command in its file (0: made in code); not compared
};

struct NffDocument {
    bool hasView = false;
    SceneView view; // the `v` block
    bool hasBackground = false;
    glm::dvec3 background{0.0};       // `b`
    std::vector<NffLight> lights;     // `l`, in file order
    std::vector<NffSurface> surfaces; // every `f`, in file order
    std::vector<NffObject> objects;   // in file order
};

// Parses NFF text; `name` is used in error messages. Throws SceneFileError.
NffDocument readNff(std::istream& in, const std::string& name);
NffDocument readNffText(std::string_view text, const std::string& name);
// A regular file of at most kNffMaxBytes (errors "path:0: ..." otherwise).
NffDocument readNffFile(const std::string& path);
// Writes NFF text that readNff reads back to an equal document (numbers in the
// shortest form that reads back exactly). Each `f` is written just before the first
// object that uses it, so surface indices must not decrease along `objects` (true for
// read and generated documents); objects before any `f` keep surface -1.
void writeNff(std::ostream& out, const NffDocument& doc);
void writeNffFile(const std::string& path, const NffDocument& doc); // throws SceneFileError

// The scene of a document (see the mapping above); the view is the document's or a
// framing default.
SceneFile toScene(const NffDocument& doc);

} // namespace wb::rt
