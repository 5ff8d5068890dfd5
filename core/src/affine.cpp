#include "core/affine.h"

#include <cmath>
#include <stdexcept>

namespace wb {
namespace {

// GLM matrices are column-major: m[col][row]. This helper keeps the formulas
// readable in the row/column order the course writes them.
void set(glm::dmat3& m, int row, int col, double v) {
    m[col][row] = v;
}

void requireNormal(double nn, const char* what) {
    if (!(nn > 0.0) || !std::isfinite(nn))
        throw std::invalid_argument(std::string(what) + ": the normal must be non-zero and finite");
}

glm::dvec3 homogeneous(const Line2& line) {
    return {line.a, line.b, line.c};
}
glm::dvec4 homogeneous(const Plane& plane) {
    return {plane.n, plane.d};
}

// The central projection from the homogeneous point `s` onto the hyperplane `pi`
// (line in 2D, plane in 3D): M = ±((pi·s) I − s piᵀ), so M·P = ±((pi·s) P − (pi·P) s).
// It lies on the hyperplane, pi·(M P) = (pi·s)(pi·P) − (pi·P)(pi·s) = 0, and on the
// line through s and P, being a combination of the two.
template <typename Mat, typename Vec> Mat centralProjection(const Vec& pi, const Vec& s) {
    // The sign makes w = |pi·s| − sign(pi·s)(pi·P) positive for every P between the
    // light and the plane, whichever way the normal points (see affine.h).
    const double ps = glm::dot(pi, s);
    const double sign = ps < 0.0 ? -1.0 : 1.0;
    Mat m(sign * ps);
    for (int r = 0; r < Vec::length(); ++r)
        for (int c = 0; c < Vec::length(); ++c)
            m[c][r] -= sign * s[r] * pi[c];
    return m;
}

} // namespace

glm::dmat3 mirrorLine(const Line2& line) {
    const double nn = line.a * line.a + line.b * line.b;
    requireNormal(nn, "mirrorLine");
    // Solution (2) of exercise 1.1: Q = P − 2((n,P) + C)/(n,n) · n.
    const double a = line.a, b = line.b, c = line.c;
    glm::dmat3 m(1.0);
    set(m, 0, 0, 1.0 - 2.0 * a * a / nn);
    set(m, 0, 1, -2.0 * a * b / nn);
    set(m, 0, 2, -2.0 * a * c / nn);
    set(m, 1, 0, -2.0 * a * b / nn);
    set(m, 1, 1, 1.0 - 2.0 * b * b / nn);
    set(m, 1, 2, -2.0 * b * c / nn);
    return m;
}

glm::dmat3 shadowLineDirectional(const Line2& line, const glm::dvec2& l) {
    requireNormal(line.a * line.a + line.b * line.b, "shadowLineDirectional");
    if (!(glm::dot(l, l) > 0.0)) throw std::invalid_argument("shadowLineDirectional: l is zero");
    const glm::dvec3 pi = homogeneous(line);
    const double nl = line.a * l.x + line.b * l.y;
    if (nl != 0.0) {
        // Practical 1.2 in 2D: Q = P − (C + (n,P))/(n,l) · l, an affine map (w stays 1).
        glm::dmat3 m(1.0);
        for (int r = 0; r < 2; ++r)
            for (int c = 0; c < 3; ++c)
                m[c][r] -= l[r] * pi[c] / nl;
        return m;
    }
    // Rays parallel to the line never reach it: the limit of the projectively equal
    // matrix −(n,l)·I + l·piᵀ sends every point to the point at infinity along l.
    glm::dmat3 m(0.0);
    for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 3; ++c)
            m[c][r] = l[r] * pi[c];
    return m;
}

glm::dmat3 shadowLinePoint(const Line2& line, const glm::dvec2& s) {
    requireNormal(line.a * line.a + line.b * line.b, "shadowLinePoint");
    return centralProjection<glm::dmat3>(homogeneous(line), glm::dvec3(s, 1.0));
}

glm::dmat4 mirrorPlane(const Plane& plane) {
    const double nn = glm::dot(plane.n, plane.n);
    requireNormal(nn, "mirrorPlane");
    // Q = P − 2((n,P) + D)/(n,n) · n, the 3D form of exercise 1.1 (2).
    glm::dmat4 m(1.0);
    const glm::dvec4 pi = homogeneous(plane);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c)
            m[c][r] -= 2.0 * plane.n[r] * pi[c] / nn;
    return m;
}

glm::dmat4 shadowDirectional(const Plane& plane, const glm::dvec3& l) {
    requireNormal(glm::dot(plane.n, plane.n), "shadowDirectional");
    if (!(glm::dot(l, l) > 0.0)) throw std::invalid_argument("shadowDirectional: l is zero");
    const glm::dvec4 pi = homogeneous(plane);
    const double nl = glm::dot(plane.n, l);
    glm::dmat4 m(nl != 0.0 ? 1.0 : 0.0);
    if (nl != 0.0) {
        // Practical 1.2, exactly the course's matrix: M = I − l·piᵀ/(n,l), w stays 1.
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 4; ++c)
                m[c][r] -= l[r] * pi[c] / nl;
        return m;
    }
    // Light parallel to the plane: every shadow point is at infinity along l (w = 0).
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c)
            m[c][r] = l[r] * pi[c];
    return m;
}

glm::dmat4 shadowPoint(const Plane& plane, const glm::dvec3& s) {
    requireNormal(glm::dot(plane.n, plane.n), "shadowPoint");
    return centralProjection<glm::dmat4>(homogeneous(plane), glm::dvec4(s, 1.0));
}

} // namespace wb

namespace wb {

Line2 lineThrough(const glm::dvec2& k, const glm::dvec2& l) {
    const glm::dvec2 d = l - k;
    if (!(glm::dot(d, d) > 0.0)) throw std::invalid_argument("lineThrough: K and L coincide");
    // Normal (−dy, dx); c from K (K is on the line by construction, L up to rounding).
    Line2 line{-d.y, d.x, 0.0};
    line.c = -(line.a * k.x + line.b * k.y);
    return line;
}

glm::dmat3 translation2(const glm::dvec2& v) {
    glm::dmat3 m(1.0);
    m[2][0] = v.x;
    m[2][1] = v.y;
    return m;
}

glm::dmat3 rotation2(double radians) {
    const double c = std::cos(radians), s = std::sin(radians);
    glm::dmat3 m(1.0);
    m[0][0] = c;
    m[1][0] = -s;
    m[0][1] = s;
    m[1][1] = c;
    return m;
}

glm::dmat3 mirrorX2() {
    glm::dmat3 m(1.0);
    m[1][1] = -1.0;
    return m;
}

glm::dmat3 mirrorLineComposite(const Line2& line) {
    requireNormal(line.a * line.a + line.b * line.b, "mirrorLineComposite");
    const glm::dvec2 p0 = std::abs(line.b) >= std::abs(line.a) ? glm::dvec2(0.0, -line.c / line.b)
                                                               : glm::dvec2(-line.c / line.a, 0.0);
    const double phi = std::atan2(line.a, -line.b);
    return translation2(p0) * rotation2(phi) * mirrorX2() * rotation2(-phi) * translation2(-p0);
}

} // namespace wb
