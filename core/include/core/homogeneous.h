#pragma once
// Batched homogeneous transforms (lab 1's "good program"): the n points are the
// columns of one 3×n (or 4×n) matrix, multiplied by the 3×3 (4×4) map in ONE matrix
// product, then divided by w.
//
// Division by w: a column with w = 0 (or so small that x/w would overflow) is a point
// at infinity. It is reported as PointKind::AtInfinity and its coordinates are the
// unit direction (x, y)/|(x, y)| (sign as the product gave it), never Inf or NaN.
// A column that is the zero vector (x = y = w = 0, e.g. a point of the plane under a
// shadow matrix whose light lies on that plane) is no point at all: PointKind::Undefined
// with coordinates 0. A non-finite input column is also Undefined.
#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace wb {

enum class PointKind : std::uint8_t { Finite, AtInfinity, Undefined };

// A 3×n (Dim = 3) or 4×n (Dim = 4) matrix of homogeneous columns, stored column-major
// (x0 y0 w0 x1 y1 w1 ...), i.e. exactly the course's [P1 ... Pn].
template <int Dim> struct HomogeneousColumns {
    std::size_t cols = 0;
    std::vector<double> data; // Dim * cols entries, column j at data[Dim*j]
    double& at(int row, std::size_t col) { return data[Dim * col + std::size_t(row)]; }
    double at(int row, std::size_t col) const { return data[Dim * col + std::size_t(row)]; }
};

// Cartesian points after the division by w; kinds[i] says how to read points[i].
template <typename Vec> struct ProjectedPoints {
    std::vector<Vec> points;
    std::vector<PointKind> kinds;
    std::size_t atInfinity = 0; // how many kinds are AtInfinity
    std::size_t undefined = 0;  // how many kinds are Undefined
};

// [P1..Pn] with w = 1.
HomogeneousColumns<3> toHomogeneous(const std::vector<glm::dvec2>& points);
HomogeneousColumns<4> toHomogeneous(const std::vector<glm::dvec3>& points);

// M · [P1..Pn]: one matrix product (rows of M against the columns).
HomogeneousColumns<3> multiply(const glm::dmat3& m, const HomogeneousColumns<3>& p);
HomogeneousColumns<4> multiply(const glm::dmat4& m, const HomogeneousColumns<4>& p);

// (x, y, w) -> (x/w, y/w) column by column, with the w = 0 rules above.
ProjectedPoints<glm::dvec2> dehomogenize(const HomogeneousColumns<3>& p);
ProjectedPoints<glm::dvec3> dehomogenize(const HomogeneousColumns<4>& p);

// The whole lab-1 step: dehomogenize(multiply(m, toHomogeneous(points))).
ProjectedPoints<glm::dvec2> transformPoints(const glm::dmat3& m,
                                            const std::vector<glm::dvec2>& points);
ProjectedPoints<glm::dvec3> transformPoints(const glm::dmat4& m,
                                            const std::vector<glm::dvec3>& points);

} // namespace wb
