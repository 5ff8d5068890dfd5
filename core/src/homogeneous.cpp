#include "core/homogeneous.h"

#include <algorithm>
#include <cmath>

namespace wb {
namespace {

template <int Dim, typename Vec> HomogeneousColumns<Dim> toColumns(const std::vector<Vec>& points) {
    HomogeneousColumns<Dim> h;
    h.cols = points.size();
    h.data.resize(std::size_t(Dim) * h.cols);
    for (std::size_t j = 0; j < h.cols; ++j) {
        for (int r = 0; r < Dim - 1; ++r)
            h.at(r, j) = points[j][r];
        h.at(Dim - 1, j) = 1.0;
    }
    return h;
}

template <int Dim, typename Mat>
HomogeneousColumns<Dim> product(const Mat& m, const HomogeneousColumns<Dim>& p) {
    HomogeneousColumns<Dim> out;
    out.cols = p.cols;
    out.data.assign(p.data.size(), 0.0);
    // C = M·P with P stored column-major: for each column, out(:,j) = Σ_k M(:,k) P(k,j).
    // The k-outer order walks both GLM's columns and P's columns contiguously.
    for (std::size_t j = 0; j < p.cols; ++j)
        for (int k = 0; k < Dim; ++k) {
            const double pk = p.at(k, j);
            for (int r = 0; r < Dim; ++r)
                out.at(r, j) += m[k][r] * pk;
        }
    return out;
}

template <int Dim, typename Vec> ProjectedPoints<Vec> divide(const HomogeneousColumns<Dim>& p) {
    ProjectedPoints<Vec> out;
    out.points.resize(p.cols);
    out.kinds.resize(p.cols);
    for (std::size_t j = 0; j < p.cols; ++j) {
        Vec v(0.0);
        const double w = p.at(Dim - 1, j);
        bool finiteInput = std::isfinite(w);
        for (int r = 0; r < Dim - 1; ++r) {
            v[r] = p.at(r, j);
            finiteInput = finiteInput && std::isfinite(v[r]);
        }
        PointKind kind = PointKind::Finite;
        if (!finiteInput) {
            kind = PointKind::Undefined;
        } else {
            Vec q = v / w; // may be Inf/NaN when w is 0 or tiny: checked just below
            bool ok = w != 0.0;
            for (int r = 0; r < Dim - 1 && ok; ++r)
                ok = std::isfinite(q[r]);
            if (ok) {
                v = q;
            } else {
                // Scale first so that |v| cannot overflow, then normalise.
                double big = 0.0;
                for (int r = 0; r < Dim - 1; ++r)
                    big = std::max(big, std::abs(v[r]));
                if (big == 0.0) {
                    kind = PointKind::Undefined;
                } else {
                    kind = PointKind::AtInfinity;
                    v = glm::normalize(v / big);
                }
            }
        }
        if (kind == PointKind::Undefined) v = Vec(0.0);
        if (kind == PointKind::AtInfinity) ++out.atInfinity;
        if (kind == PointKind::Undefined) ++out.undefined;
        out.points[j] = v;
        out.kinds[j] = kind;
    }
    return out;
}

} // namespace

HomogeneousColumns<3> toHomogeneous(const std::vector<glm::dvec2>& points) {
    return toColumns<3>(points);
}
HomogeneousColumns<4> toHomogeneous(const std::vector<glm::dvec3>& points) {
    return toColumns<4>(points);
}
HomogeneousColumns<3> multiply(const glm::dmat3& m, const HomogeneousColumns<3>& p) {
    return product<3>(m, p);
}
HomogeneousColumns<4> multiply(const glm::dmat4& m, const HomogeneousColumns<4>& p) {
    return product<4>(m, p);
}
ProjectedPoints<glm::dvec2> dehomogenize(const HomogeneousColumns<3>& p) {
    return divide<3, glm::dvec2>(p);
}
ProjectedPoints<glm::dvec3> dehomogenize(const HomogeneousColumns<4>& p) {
    return divide<4, glm::dvec3>(p);
}
ProjectedPoints<glm::dvec2> transformPoints(const glm::dmat3& m,
                                            const std::vector<glm::dvec2>& points) {
    return dehomogenize(multiply(m, toHomogeneous(points)));
}
ProjectedPoints<glm::dvec3> transformPoints(const glm::dmat4& m,
                                            const std::vector<glm::dvec3>& points) {
    return dehomogenize(multiply(m, toHomogeneous(points)));
}

} // namespace wb
