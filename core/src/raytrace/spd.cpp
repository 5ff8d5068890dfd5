#include "core/raytrace/spd.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace wb::rt {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Right-handed rotation by `angle` about the unit `axis` (Rodrigues), as the SPD
// library's lib_create_axis_rotate_matrix (checked: the first child of balls comes
// out at (0.272166, 0.272166, 0.544331), as in the published balls.nff).
glm::dmat3 rotation(const glm::dvec3& axis, double angle) {
    const double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
    const double x = axis.x, y = axis.y, z = axis.z;
    // Column-major: columns are the images of the basis vectors.
    return glm::dmat3(t * x * x + c, t * x * y + s * z, t * x * z - s * y, //
                      t * x * y - s * z, t * y * y + c, t * y * z + s * x, //
                      t * x * z + s * y, t * y * z - s * x, t * z * z + c);
}

// SPD's Phong exponent from a highlight half-angle in degrees: cos(ang)^p = 1/2.
double phongPow(double angDeg) {
    return angDeg > 0 ? std::log(0.5) / std::log(std::cos(angDeg * kPi / 180)) : 0.0;
}

void checkSize(int sf, const char* what) {
    if (sf < 1 || sf > 6)
        throw std::invalid_argument(std::string(what) + ": size factor must be 1..6");
}

NffObject sphere(const glm::dvec3& c, double r, int surface) {
    NffObject o;
    o.kind = NffObject::Kind::Sphere;
    o.centre = c;
    o.radius = r;
    o.surface = surface;
    return o;
}

struct BallsGen {
    glm::dvec3 objset[9];
    NffDocument* doc;
    int surface;
    void output(int depth, const glm::dvec3& centre, double radius, const glm::dvec3& dir,
                double ratio) {
        doc->objects.push_back(sphere(centre, radius, surface));
        if (depth <= 0) return;
        --depth;
        glm::dmat3 mx(1.0);
        const glm::dvec3 cr = glm::cross(glm::dvec3(0, 0, 1), dir);
        const double crLen = glm::length(cr);
        // Along ±z (also when rounding leaves |dir.z| a hair below 1 with x = y = 0,
        // where the axis would be 0/0): identity or a half turn, as balls.c does.
        if (dir.z >= 1.0 || (crLen == 0 && dir.z > 0)) {
        } else if (dir.z <= -1.0 || crLen == 0) {
            mx = rotation({0, 1, 0}, kPi);
        } else {
            mx = rotation(cr / crLen, std::acos(std::clamp(dir.z, -1.0, 1.0)));
        }
        const double scale = radius * (1.0 + ratio);
        for (const glm::dvec3& v : objset) {
            const glm::dvec3 child = mx * v * scale + centre;
            output(depth, child, radius * ratio, (child - centre) / scale, ratio);
        }
    }
};

// Uniform scale, rotation and translation: p -> s·R·p + t (the SPD transform stack
// with lib_tx_rotate/translate/scale multiplying on the right, as OpenGL's).
struct Similarity {
    glm::dmat3 r{1.0};
    double s = 1.0;
    glm::dvec3 t{0.0};
    glm::dvec3 apply(const glm::dvec3& p) const { return s * (r * p) + t; }
};

void jack(NffDocument& doc, const Similarity& m0, int surface) {
    Similarity m = m0;
    m.s *= 0.75; // scaled down to prevent overlaps
    for (int a = 0; a < 3; ++a) {
        glm::dvec3 e(0.0);
        e[a] = 1;
        NffObject c;
        c.kind = NffObject::Kind::Cone;
        c.base = m.apply(-e);
        c.apex = m.apply(e);
        c.baseRadius = c.apexRadius = 0.1 * m.s;
        c.surface = surface;
        doc.objects.push_back(c);
    }
    for (int sign : {1, -1})
        for (int a = 0; a < 3; ++a) {
            glm::dvec3 e(0.0);
            e[a] = sign;
            doc.objects.push_back(sphere(m.apply(e), 0.2 * m.s, surface));
        }
}

void recJack(NffDocument& doc, const Similarity& m, int depth, int maxDepth, int surface) {
    jack(doc, m, surface);
    if (depth >= maxDepth) return;
    for (double i : {-0.5, 0.5})
        for (double j : {-0.5, 0.5})
            for (double k : {-0.5, 0.5}) {
                Similarity c = m;
                c.t = m.apply({i, j, k}); // translate, then scale by 1/2
                c.s = m.s * 0.5;
                recJack(doc, c, depth + 1, maxDepth, surface);
            }
}


// One gear of SPD gears: a top face of 4 points per tooth (two on the outer radius at
// ±0.19 of the tooth angle, two on the inner radius at 0.3 and 0.7), a rectangle
// along each of its edges down to the bottom face, and the bottom face, walked the
// other way round. The faces are concave 144-gons.
void gear(NffDocument& doc, const glm::dvec3& centre, double offsetAngle, double outerR,
          double innerR, double thickness, int surface) {
    constexpr int kTeeth = 36;
    const double toothAngle = 2.0 * kPi / kTeeth;
    const auto face = [&](double z, double sign) {
        std::vector<glm::dvec3> pts;
        pts.reserve(4 * kTeeth);
        for (int n = 0; n < kTeeth; ++n) {
            const double a = offsetAngle + sign * 2.0 * kPi * n / kTeeth;
            const double ta = sign * toothAngle;
            const auto at = [&](double angle, double r) {
                return centre + glm::dvec3(r * std::cos(angle), r * std::sin(angle), z);
            };
            pts.push_back(at(a - 0.19 * ta, outerR));
            pts.push_back(at(a + 0.19 * ta, outerR));
            pts.push_back(at(a + 0.3 * ta, innerR));
            pts.push_back(at(a + 0.7 * ta, innerR));
        }
        return pts;
    };
    NffObject top;
    top.kind = NffObject::Kind::Polygon;
    top.surface = surface;
    top.vertices = face(0.0, 1.0);
    const std::vector<glm::dvec3>& g = top.vertices;
    doc.objects.push_back(top);
    for (std::size_t i = 0; i < g.size(); ++i) {
        const glm::dvec3& a = g[i];
        const glm::dvec3& b = g[(i + 1) % g.size()];
        NffObject side;
        side.kind = NffObject::Kind::Polygon;
        side.surface = surface;
        const glm::dvec3 down(0, 0, thickness);
        side.vertices = {a, a - down, b - down, b};
        doc.objects.push_back(side);
    }
    NffObject bottom;
    bottom.kind = NffObject::Kind::Polygon;
    bottom.surface = surface;
    bottom.vertices = face(-thickness, -1.0);
    doc.objects.push_back(bottom);
}

} // namespace

long long spdBallsSpheres(int sf) {
    long long p = 1;
    for (int i = 0; i <= sf; ++i)
        p *= 9;
    return (p - 1) / 8;
}

long long spdJacksCount(int sf) {
    long long p = 1;
    for (int i = 0; i < sf; ++i)
        p *= 8;
    return (p - 1) / 7;
}

NffDocument spdBalls(int sf) {
    checkSize(sf, "spdBalls");
    NffDocument doc;
    doc.hasView = true;
    doc.view.from = {2.1, 1.3, 1.7};
    doc.view.at = {0, 0, 0};
    doc.view.up = {0, 0, 1};
    doc.view.angle = 45;
    doc.view.hither = 0.01;
    doc.view.width = doc.view.height = 512;
    doc.hasBackground = true;
    doc.background = {0.078, 0.361, 0.753};
    for (const glm::dvec3& p : {glm::dvec3(4, 3, 2), glm::dvec3(1, -4, 4), glm::dvec3(-3, 1, 5)}) {
        NffLight l;
        l.position = p;
        doc.lights.push_back(l);
    }
    // Floor: beige square, diffuse only.
    doc.surfaces.push_back(NffSurface{{1.0, 0.75, 0.33}, 0.8, 0.0, 0.0, 0.0, 1.0});
    NffObject floor;
    floor.kind = NffObject::Kind::Polygon;
    floor.surface = 0;
    floor.vertices = {{12, 12, -0.5}, {-12, 12, -0.5}, {-12, -12, -0.5}, {12, -12, -0.5}};
    doc.objects.push_back(floor);
    // Spheres: mirrored, highlight half-angle 37 degrees.
    doc.surfaces.push_back(NffSurface{{1.0, 0.9, 0.7}, 0.5, 0.5, phongPow(37.0), 0.0, 1.0});

    BallsGen g;
    g.doc = &doc;
    g.surface = 1;
    const double d = 1.0 / std::sqrt(2.0);
    glm::dvec3 trio[3] = {{d, d, 0}, {d, 0, -d}, {0, d, -d}};
    const glm::dmat3 tilt =
        rotation(glm::normalize(glm::dvec3(1, -1, 0)), std::asin(2.0 / std::sqrt(6.0)));
    for (glm::dvec3& v : trio)
        v = tilt * v;
    for (int set = 0; set < 3; ++set) {
        const glm::dmat3 rz = rotation({0, 0, 1}, set * 2.0 * kPi / 3.0);
        for (int v = 0; v < 3; ++v)
            g.objset[set * 3 + v] = rz * trio[v];
    }
    g.output(sf, {0, 0, 0}, 0.5, {0, 0, 1}, 1.0 / 3.0);
    return doc;
}

NffDocument spdJacks(int sf) {
    checkSize(sf, "spdJacks");
    NffDocument doc;
    doc.hasView = true;
    doc.view.from = {0, 0, -8};
    doc.view.at = {0, 0, 0};
    doc.view.up = {0, 1, 0};
    doc.view.angle = 25;
    doc.view.hither = 0.001;
    doc.view.width = doc.view.height = 256;
    doc.hasBackground = true;
    doc.background = {0.2, 0.05, 0.2}; // dark purple
    NffLight l;
    l.position = {-10, 3, -20};
    doc.lights.push_back(l);
    doc.surfaces.push_back(NffSurface{{0.737, 0.561, 0.561}, 0.7, 0.7, phongPow(20.0), 0.0, 1.0});
    Similarity m;
    m.r = rotation({1, 0, 0}, -30 * kPi / 180) * rotation({0, 1, 0}, -20 * kPi / 180);
    recJack(doc, m, 1, sf, 0);
    return doc;
}

NffDocument spdGears(int sf) {
    checkSize(sf, "spdGears");
    NffDocument doc;
    doc.hasView = true;
    doc.view.from = {-1.1, -2.1, 2.6};
    doc.view.at = {0, 0, 0};
    doc.view.up = {0, 0, 1};
    doc.view.angle = 45;
    doc.view.hither = 1.0;
    doc.view.width = doc.view.height = 512;
    doc.hasBackground = true;
    doc.background = {0.078, 0.361, 0.753};
    for (const glm::dvec3& p : {glm::dvec3(2, 4, 4), glm::dvec3(-2, 4, 3), glm::dvec3(2, -2.5, 2.5),
                                glm::dvec3(-1, -4, 2), glm::dvec3(-1.111, -2.121, 2.626)}) {
        NffLight l;
        l.position = p;
        doc.lights.push_back(l);
    }
    // Ground: off-white, diffuse 0.3 and mirror 0.6, highlight half-angle 37 degrees.
    doc.surfaces.push_back(NffSurface{{1.0, 0.85, 0.7}, 0.3, 0.6, phongPow(37.0), 0.0, 1.0});
    NffObject ground;
    ground.kind = NffObject::Kind::Polygon;
    ground.surface = 0;
    ground.vertices = {{2, 2, 0}, {-2, 2, 0}, {-2, -2, 0}, {2, -2, 0}};
    doc.objects.push_back(ground);

    // sf³ gears in a cube of side 2 standing on the ground; neighbours mesh: the
    // outer radius is 0.995 of the pitch so that teeth never touch.
    constexpr double kEdgeDiff = 0.1; // 1 − inner/outer radius ratio (tooth depth)
    const double outerR = 1.0 / (sf - (sf - 1) * kEdgeDiff / 2.0);
    const glm::dvec3 zero(-1.0 + outerR, -1.0 + outerR, 1.0);
    const glm::dvec3 step(outerR * (2.0 - kEdgeDiff), outerR * (2.0 - kEdgeDiff), -1.0 / sf);
    const double thickness = std::min(0.1, 1.0 / (2.0 * sf));
    const auto frac = [](double x) { return x - std::floor(x); };
    for (int iz = 0; iz < sf; ++iz)
        for (int iy = 0; iy < sf; ++iy)
            for (int ix = 0; ix < sf; ++ix) {
                const glm::dvec3 centre = zero + glm::dvec3(ix, iy, iz) * step;
                // Pseudo-random colour, brightest channel scaled to 1.
                glm::dvec3 c(0.01 + frac((ix * 3 + iy * 2 + iz + 1) * 5.0 / 7.0),
                             0.01 + frac((iy * 3 + iz * 2 + ix + 1) * 3.0 / 7.0),
                             0.01 + frac((iz * 3 + ix * 2 + iy + 1) * 2.0 / 7.0));
                c /= std::max({c.x, c.y, c.z});
                // Every fifth gear is glass-like: kd 0.2, kt 0.8, ior 1.1; the others
                // are matte. (The SPD writes "no highlight" as exponent 100000.)
                if ((ix * 4 + iy * 2 + iz) % 5 == 0)
                    doc.surfaces.push_back(NffSurface{c, 0.2, 0.0, 100000.0, 0.8, 1.1});
                else
                    doc.surfaces.push_back(NffSurface{c, 1.0, 0.0, 100000.0, 0.0, 0.0});
                const double angle = kPi * ((ix + iy + iz) % 2) / 36.0;
                gear(doc, centre, angle, 0.995 * outerR, (1.0 - kEdgeDiff) * outerR, thickness,
                     int(doc.surfaces.size()) - 1);
            }
    return doc;
}

std::vector<std::string> spdSceneNames() {
    return {"balls", "jacks", "gears"};
}

NffDocument spdScene(const std::string& name, int sf) {
    if (name == "balls") return spdBalls(sf);
    if (name == "jacks") return spdJacks(sf);
    if (name == "gears") return spdGears(sf);
    std::string known;
    for (const std::string& n : spdSceneNames())
        known += (known.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown SPD scene '" + name + "' (one of " + known + ")");
}

NffDocument oneSphereScene() {
    NffDocument doc;
    doc.hasView = true;
    doc.view.from = {0, 0, 4};
    doc.view.at = {0, 0, 0};
    doc.view.up = {0, 1, 0};
    doc.view.angle = 40;
    doc.hasBackground = true;
    doc.background = {0.2, 0.2, 0.3};
    NffLight l;
    l.position = {3, 4, 5};
    doc.lights.push_back(l);
    doc.surfaces.push_back(NffSurface{{0.9, 0.3, 0.2}, 0.7, 0.3, 20.0, 0.0, 1.0});
    doc.objects.push_back(sphere({0, 0, 0}, 1.0, 0));
    return doc;
}

NffDocument twoSpheresScene() {
    NffDocument doc = oneSphereScene();
    doc.objects[0].centre = {-0.8, 0, 0};
    doc.objects[0].radius = 0.7;
    doc.surfaces.push_back(NffSurface{{0.8, 0.8, 0.9}, 0.3, 0.7, 40.0, 0.0, 1.0}); // mirror
    doc.objects.push_back(sphere({0.9, 0, 0}, 0.7, 1));
    return doc;
}

} // namespace wb::rt
