#include "core/raytrace/spd.h"

#include "core/teapot.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
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

// lib_output_color of the SPD library as NFF writes it: colour, kd, ks (mirror and
// highlight), the highlight half-angle as a Phong exponent (the SPD writes 100000,
// "no highlight", for angle 0), kt and the index of refraction.
NffSurface spdSurface(const glm::dvec3& colour, double kd, double ks, double angDeg, double kt,
                      double ior) {
    return NffSurface{colour, kd, ks, angDeg > 0 ? phongPow(angDeg) : 100000.0, kt, ior};
}

NffDocument spdDocument(const glm::dvec3& from, const glm::dvec3& at, const glm::dvec3& up,
                        double angle, double hither) {
    NffDocument doc;
    doc.hasView = true;
    doc.view.from = from;
    doc.view.at = at;
    doc.view.up = up;
    doc.view.angle = angle;
    doc.view.hither = hither;
    doc.view.width = doc.view.height = 512;
    doc.hasBackground = true;
    doc.background = {0.078, 0.361, 0.753}; // UNC sky blue, every SPD scene's
    return doc;
}

void addLight(NffDocument& doc, const glm::dvec3& p) {
    NffLight l;
    l.position = p;
    doc.lights.push_back(l);
}

int addSurface(NffDocument& doc, const NffSurface& f) {
    doc.surfaces.push_back(f);
    return int(doc.surfaces.size()) - 1;
}

void polygon(NffDocument& doc, std::vector<glm::dvec3> v, int surface) {
    NffObject o;
    o.kind = NffObject::Kind::Polygon;
    o.surface = surface;
    o.vertices = std::move(v);
    doc.objects.push_back(std::move(o));
}

void cylcone(NffDocument& doc, const glm::dvec3& base, double rb, const glm::dvec3& apex, double ra,
             int surface) {
    NffObject c;
    c.kind = NffObject::Kind::Cone;
    c.base = base;
    c.apex = apex;
    c.baseRadius = rb;
    c.apexRadius = ra;
    c.surface = surface;
    doc.objects.push_back(c);
}

// Tetra: a tetrahedron of side 2·√2 (opposite corners of the cube [−1, 1]³) split
// recursively into the 4 half-size tetrahedra at its corners; 4 faces each at the end.
void tetra(NffDocument& doc, int depth, const glm::dvec3& c, double half, int surface) {
    // The corners x·y·z = +1 of the cube c ± half.
    std::vector<glm::dvec3> corner;
    for (int x = -1; x <= 1; x += 2)
        for (int y = -1; y <= 1; y += 2)
            for (int z = -1; z <= 1; z += 2)
                if (x * y * z == 1) corner.push_back(c + half * glm::dvec3(x, y, z));
    if (depth <= 1) {
        for (int f = 0; f < 4; ++f) {
            int ord[3] = {f % 4, (f + 1) % 4, (f + 2) % 4};
            if (f % 2 == 1) std::swap(ord[0], ord[2]); // faces wound outwards
            polygon(doc, {corner[size_t(ord[0])], corner[size_t(ord[1])], corner[size_t(ord[2])]},
                    surface);
        }
        return;
    }
    for (const glm::dvec3& k : corner)
        tetra(doc, depth - 1, c + (k - c) / 2.0, half / 2, surface);
}

// Rings: the 30 midpoints of a dodecahedron's edges, as 6 pentagons (one in the xy
// plane starting on +x, five turned about x by the dihedral angle, then about z).
std::vector<glm::dvec3> dodecRing(double minorRadius) {
    const double scale = 1.0 / (1.0 + minorRadius); // fits in the unit sphere
    std::vector<glm::dvec3> v(30);
    for (int i = 0; i < 5; ++i)
        v[size_t(i)] =
            scale * glm::dvec3(std::cos(i * 2.0 * kPi / 5.0), std::sin(i * 2.0 * kPi / 5.0), 0);
    const glm::dmat3 rx =
        rotation({1, 0, 0}, 2.0 * std::acos(std::cos(kPi / 3.0) / std::sin(kPi / 5.0)));
    for (int p = 1; p < 6; ++p) {
        const glm::dmat3 rz = rotation({0, 0, 1}, kPi * (2.0 * (p - 1) + 1.0) / 5.0);
        for (int i = 0; i < 5; ++i)
            v[size_t(5 * p + i)] = rz * (rx * v[size_t(i)]);
    }
    return v;
}

// Tree (Aono & Kunii): each branch a cone from its frame's origin to (0, 0, 1) with a
// sphere at the tip, then two children in frames turned, shrunk and moved to the tip.
void growTree(NffDocument& doc, const Similarity& m, const Similarity (&child)[2], double scale,
              int depth, int surface) {
    const glm::dvec3 base = m.apply({0, 0, 0}), apex = m.apply({0, 0, 1});
    const double rb = scale * 0.15, ra = rb * 0.67; // width/height 0.15, diameter ratio 0.67
    cylcone(doc, base, rb, apex, ra, surface);
    doc.objects.push_back(sphere(apex, ra, surface));
    if (depth <= 0) return;
    for (const Similarity& c : child) {
        Similarity n; // m ∘ c
        n.r = m.r * c.r;
        n.s = m.s * c.s;
        n.t = m.apply(c.t);
        growTree(doc, n, child, scale * 0.67, depth - 1, surface);
    }
}

// A deterministic N(0, 1) number per key (splitmix64, then Box–Muller). The SPD's own
// table generator is not reproduced: the mountain has the SPD's shape statistics, not
// its exact heights.
double gaussFor(uint64_t key) {
    auto mix = [](uint64_t z) {
        z += 0x9e3779b97f4a7c15ULL;
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    };
    const uint64_t a = mix(key), b = mix(a);
    const double u1 = (double(a >> 11) + 0.5) / 9007199254740992.0; // (0, 1)
    const double u2 = double(b >> 11) / 9007199254740992.0;
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * kPi * u2);
}

// Carpenter's midpoint displacement on a square grid: each edge midpoint and the centre
// rise by roughness × half the side × N(0, 1) (the centre by √2 times that), keyed by
// the grid point so shared edges agree; at width 1 the square becomes two triangles.
struct Mountain {
    NffDocument* doc;
    int surface, n, sf;
    double roughness;
    double z(int x, int y, double base, double rise) const {
        return base + rise * gaussFor((uint64_t(sf) << 48) ^ (uint64_t(x) << 24) ^ uint64_t(y));
    }
    void grow(int width, int x, int y, double ll, double lr, double ur, double ul) {
        const auto at = [&](int i, int j, double h) {
            return glm::dvec3(-1.0 + 2.0 * i / n, -1.0 + 2.0 * j / n, h);
        };
        if (width == 1) {
            const glm::dvec3 c[4] = {at(x, y, ll), at(x + 1, y, lr), at(x + 1, y + 1, ur),
                                     at(x, y + 1, ul)};
            polygon(*doc, {c[0], c[1], c[2]}, surface);
            polygon(*doc, {c[2], c[3], c[0]}, surface);
            return;
        }
        const int h = width / 2;
        const double rise = h * 2.0 / n * roughness;
        const double lower = z(x + h, y, (ll + lr) / 2, rise);
        const double right = z(x + width, y + h, (lr + ur) / 2, rise);
        const double upper = z(x + h, y + width, (ur + ul) / 2, rise);
        const double left = z(x, y + h, (ul + ll) / 2, rise);
        const double middle = z(x + h, y + h, (ll + lr + ur + ul) / 4, 1.4142136 * rise);
        grow(h, x, y, ll, lower, middle, left);
        grow(h, x + h, y, lower, lr, right, middle);
        grow(h, x + h, y + h, middle, right, ur, upper);
        grow(h, x, y + h, left, middle, upper, ul);
    }
};

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

NffDocument spdTetra(int sf) {
    checkSize(sf, "spdTetra");
    NffDocument doc =
        spdDocument({1.022846, -3.177154, -2.174512}, {-0.004103, -0.004103, 0.216539},
                    {-0.816497, -0.816497, 0.816497}, 45, 1.0);
    addLight(doc, {1.876066, -18.123936, -5.000422});
    const int red = addSurface(doc, spdSurface({1.0, 0.2, 0.2}, 1.0, 0.0, 0.0, 0.0, 0.0));
    tetra(doc, sf, {0, 0, 0}, 1.0, red);
    return doc;
}

NffDocument spdRings(int sf) {
    checkSize(sf, "spdRings");
    const double radius = 0.07412; // cylinders and spheres
    const double spread = 1.0 / std::sin(kPi / 8.0);
    const glm::dvec3 from(-1.0, -spread, 0.5);
    NffDocument doc = spdDocument(from, from + glm::dvec3(0, 1, 0), {0, 0, 1}, 45, 1.0);
    for (const glm::dvec3& p :
         {glm::dvec3(3, -spread, 3), glm::dvec3(-4, -spread, 1), glm::dvec3(2, -spread, -4)})
        addLight(doc, p);
    // A white wall behind the pyramid that just fills the 45° view (+1%).
    const int white = addSurface(doc, spdSurface({1, 1, 1}, 1.0, 0.0, 0.0, 0.0, 0.0));
    const double wy = spread * (sf + 1);
    const double wxz = 1.01 * (wy - from.y) * std::tan(kPi / 8.0);
    polygon(doc,
            {{wxz + from.x, wy, wxz + from.z},
             {-wxz + from.x, wy, wxz + from.z},
             {-wxz + from.x, wy, -wxz + from.z},
             {wxz + from.x, wy, -wxz + from.z}},
            white);
    const glm::dvec3 colours[6] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1},
                                   {0, 1, 1}, {1, 0, 1}, {1, 1, 0}};
    const std::vector<glm::dvec3> ring = dodecRing(radius);
    // A pyramid of objects, depth d holding (d+1)² of them, its point towards the eye.
    for (int d = 0; d < sf; ++d)
        for (int iz = 0; iz <= d; ++iz)
            for (int ix = 0; ix <= d; ++ix) {
                const glm::dvec3 offset(2 * ix - d, spread * (d + 1), 2 * iz - d);
                int surface = 0;
                for (int e = 0; e < 30; ++e) {
                    if (e % 5 == 0)
                        surface = addSurface(doc, spdSurface(colours[e / 5], 0.5, 0.2, 10.0, 0, 0));
                    const int prevE = e % 5 == 0 ? e + 4 : e - 1;
                    const glm::dvec3 base = ring[size_t(e)] + offset;
                    cylcone(doc, base, radius, ring[size_t(prevE)] + offset, radius, surface);
                    doc.objects.push_back(sphere(base, radius, surface));
                }
            }
    return doc;
}

NffDocument spdLattice(int sf) {
    checkSize(sf, "spdLattice");
    const double inv = 1.0 / sf, r1 = 0.25 / sf, r2 = 0.0625 / sf;
    const double delta =
        r1 * (1.0 - std::sqrt(0.0625 / 0.25)) * 0.99; // cylinder ends inside the spheres
    const double cx = ((sf >> 1) + 0.5) * inv;
    NffDocument doc = spdDocument({cx, 1.0, 1.0 - 1.0 / (sf << 1)},
                                  {cx, -1.0, -1.0 - 1.0 / (sf << 1)}, {0.2, 1.0, 0.0}, 60, 0.0);
    for (const glm::dvec3& p :
         {glm::dvec3(2, .5, .5), glm::dvec3(-1, .5, .5), glm::dvec3(.5, 2, .5),
          glm::dvec3(.5, -1, .5), glm::dvec3(.5, .5, 2), glm::dvec3(.5, .5, -1)})
        addLight(doc, p);
    const glm::dvec3 axisColour[3] = {{0.9, 0.1, 0.1}, {0.1, 0.9, 0.1}, {0.1, 0.1, 0.9}};
    for (int x = 0; x <= sf; ++x)
        for (int y = 0; y <= sf; ++y)
            for (int z = 0; z <= sf; ++z) {
                const glm::dvec3 c(x * inv, y * inv, z * inv);
                doc.objects.push_back(sphere(
                    c, r1, addSurface(doc, spdSurface({0.9, 0.9, 0.9}, 0.5, 0.5, 5.0, 0, 0))));
                const int ijk[3] = {x, y, z};
                for (int a = 0; a < 3; ++a) {
                    if (ijk[a] == sf) continue;
                    glm::dvec3 e(0.0);
                    e[a] = 1;
                    cylcone(doc, c + delta * e, r2, c + (inv - delta) * e, r2,
                            addSurface(doc, spdSurface(axisColour[a], 0.99, 0.0, 0.0, 0, 0)));
                }
            }
    return doc;
}

NffDocument spdShells(int sf) {
    checkSize(sf, "spdShells");
    NffDocument doc = spdDocument({-6, -60, 35}, {0, 8, -15}, {0, 0, 1}, 45, 0.5);
    addLight(doc, {-100, -100, 100});
    const int shell = addSurface(doc, spdSurface({1.0, 0.8, 0.4}, 0.8, 0.2, 5.0, 0.0, 1.0));
    // Pickover's shell: spheres along a logarithmic spiral, r = e^(0.15·angle), z = −2r.
    const long steps = long(180.0 * std::pow(2.0, sf));
    for (long i = -steps * 2 / 3; i <= steps / 3; ++i) {
        const double angle = 3.0 * 6.0 * kPi * double(i) / double(steps);
        const double r = std::exp(0.15 * angle);
        doc.objects.push_back(
            sphere({r * std::sin(angle), r * std::cos(angle), -2.0 * r}, r, shell));
    }
    return doc;
}

NffDocument spdTree(int sf) {
    checkSize(sf, "spdTree");
    NffDocument doc = spdDocument({4.5, 0.4, 2.0}, {0, 0, 1.5}, {0, 0, 1}, 45, 1.0);
    for (const glm::dvec3& p :
         {glm::dvec3(-5, 5, 50), glm::dvec3(30, -30, 30), glm::dvec3(-40, -30, 20),
          glm::dvec3(10, 30, 40), glm::dvec3(-30, 40, 10), glm::dvec3(50, 25, 20),
          glm::dvec3(-10, -60, 30)})
        addLight(doc, p);
    const int field = addSurface(doc, spdSurface({0.2, 0.7, 0.2}, 1.0, 0.0, 0.0, 0, 0));
    polygon(doc, {{50, 50, 0}, {-50, 50, 0}, {-50, -50, 0}, {50, -50, 0}}, field);
    const int bark = addSurface(doc, spdSurface({0.55, 0.4, 0.2}, 1.0, 0.0, 0.0, 0, 0));
    // Child frames: turn about x by the branching angle and about z by the divergence,
    // shrink by the contraction and move to the parent's tip (0, 0, 1).
    Similarity child[2];
    const double branch[2] = {40.0, 25.0}, diverge[2] = {90.0, 140.0 + 90.0},
                 contract[2] = {0.65, 0.70};
    for (int i = 0; i < 2; ++i) {
        child[i].r = rotation({0, 0, 1}, diverge[i] * kPi / 180) *
                     rotation({1, 0, 0}, branch[i] * kPi / 180);
        child[i].s = contract[i];
        child[i].t = {0, 0, 1};
    }
    growTree(doc, Similarity{}, child, 1.0, sf, bark);
    return doc;
}

NffDocument spdMount(int sf) {
    checkSize(sf, "spdMount");
    NffDocument doc = spdDocument({-1.6, 1.6, 1.7}, {0, 0, 0}, {0, 0, 1}, 45, 0.01);
    addLight(doc, {-100, -100, 100});
    // A pyramid of 4 touching glass spheres in front of the mountain.
    const int glass = addSurface(doc, spdSurface({1, 1, 1}, 0.1, 0.1, 5.0, 0.9, 1.5));
    const glm::dvec3 centre(-0.8, 0.8, 1.0);
    const double r = 0.17;
    const glm::dvec3 top(0, 0, r * std::sqrt(1.5));
    doc.objects.push_back(sphere(centre + top, r, glass));
    const glm::dvec3 turned =
        rotation(glm::normalize(glm::dvec3(1, 1, 0)), std::acos(-1.0 / 3.0)) * top;
    for (int i = 0; i < 3; ++i)
        doc.objects.push_back(
            sphere(rotation({0, 0, 1}, i * 2.0 * kPi / 3.0) * turned + centre, r, glass));
    Mountain m;
    m.doc = &doc;
    m.surface = addSurface(doc, spdSurface({0.5, 0.45, 0.35}, 1.0, 0.0, 0.0, 0, 0));
    m.n = 1 << sf;
    m.sf = sf;
    const double ratio = 2.0 / std::exp(std::log(2.0) / (2.2 - 1.0)); // fractal dimension 2.2
    m.roughness = std::sqrt(ratio * ratio - 1.0);
    m.grow(m.n, 0, 0, 0.0, 0.0, 0.0, 0.0);
    return doc;
}

// The SPD's teapot database: Newell's teapot (core/teapot, 32 patches) meshed n×n per
// patch, each grid cell split into two smooth triangles (`pp`, the patch normals), sitting
// on a checkerboard of n×n squares — "the number of squares on the checkerboard is the
// same as the amount of meshing for each of the 32 patches" (SPD teapot.c); two lights.
// n = 2^(SF+1). The view, lights and colours are this project's own choice (the SPD's
// values were not at hand); the structure and the counts follow the SPD's description.
NffDocument spdTeapot(int sf) {
    checkSize(sf, "spdTeapot");
    NffDocument doc = spdDocument({6.0, 7.5, 5.0}, {0.3, 0.0, 1.2}, {0, 0, 1}, 40, 0.1);
    addLight(doc, {-6.0, 8.0, 12.0});
    addLight(doc, {10.0, -6.0, 8.0});
    const int n = 2 << sf;
    // 1st: the checkerboard, 8×8 units centred under the pot (z = 0, where it stands).
    const int red = addSurface(doc, spdSurface({1.0, 0.15, 0.1}, 0.9, 0.1, 30.0, 0, 1));
    const int white = addSurface(doc, spdSurface({1.0, 1.0, 1.0}, 0.9, 0.1, 30.0, 0, 1));
    const double half = 4.0, cell = 2.0 * half / n;
    // All red squares, then all white: surface indices must not decrease along `objects`
    // (writeNff writes each `f` before its first object).
    for (int colour = 0; colour < 2; ++colour)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                if ((i + j) % 2 != colour) continue;
                const double x0 = -half + i * cell, y0 = -half + j * cell;
                polygon(doc,
                        {{x0, y0, 0.0},
                         {x0 + cell, y0, 0.0},
                         {x0 + cell, y0 + cell, 0.0},
                         {x0, y0 + cell, 0.0}},
                        colour == 0 ? red : white);
            }
    // 2nd: the pot.
    const int pot = addSurface(doc, spdSurface({1.0, 0.75, 0.33}, 0.8, 0.2, 20.0, 0, 1));
    const Mesh mesh = teapotMesh(n);
    for (std::size_t k = 0; k + 2 < mesh.indices.size(); k += 3) {
        NffObject o;
        o.kind = NffObject::Kind::PatchPolygon;
        o.surface = pot;
        for (int c = 0; c < 3; ++c) {
            o.vertices.push_back(mesh.positions[mesh.indices[k + std::size_t(c)]]);
            o.normals.push_back(mesh.normals[mesh.indices[k + std::size_t(c)]]);
        }
        doc.objects.push_back(std::move(o));
    }
    return doc;
}

std::vector<std::string> spdSceneNames() {
    return {"balls",   "jacks",  "gears", "tetra", "rings",
            "lattice", "shells", "tree",  "mount", "teapot"};
}

NffDocument spdScene(const std::string& name, int sf) {
    if (name == "balls") return spdBalls(sf);
    if (name == "jacks") return spdJacks(sf);
    if (name == "gears") return spdGears(sf);
    if (name == "tetra") return spdTetra(sf);
    if (name == "rings") return spdRings(sf);
    if (name == "lattice") return spdLattice(sf);
    if (name == "shells") return spdShells(sf);
    if (name == "tree") return spdTree(sf);
    if (name == "mount") return spdMount(sf);
    if (name == "teapot") return spdTeapot(sf);
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
