#pragma once
// Barycentric coordinates of practical 4.1: for a fixed triangle ABC the vectors
// u_β and u_γ of (4.6) are computed once, then every point costs two dot products
// (4.7): β = (u_β, P − A), γ = (u_γ, P − A), α = 1 − β − γ.
//
// (4.6) is evaluated through cross products, which are the same numbers by
// Lagrange's identity, (e1,e1)(e2,e2) − (e1,e2)² = |e1×e2|², and by the triple
// product expansion, (e2,e2)e1 − (e1,e2)e2 = e2×(e1×e2). For slivers the left-hand
// sides subtract two nearly equal large numbers and lose most digits; the cross
// products do not (tests compare both with a long double reference).
//
// In 3D a point off the triangle's plane gets the coordinates of its orthogonal
// projection onto that plane (u_β, u_γ lie in the plane).
#include <glm/glm.hpp>

#include <optional>

namespace wb {

// (α, β, γ): P = αA + βB + γC with α + β + γ = 1.
using Barycentrics = glm::dvec3;

class BarycentricFrame2 {
  public:
    BarycentricFrame2(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c);
    // False for a degenerate triangle (collinear or coincident vertices, an area so
    // small that |e1×e2|² underflows, or non-finite input); then coords() returns nothing.
    // coords() also returns nothing for a non-finite point.
    bool valid() const { return valid_; }
    std::optional<Barycentrics> coords(const glm::dvec2& p) const;
    const glm::dvec2& uBeta() const { return uBeta_; }
    const glm::dvec2& uGamma() const { return uGamma_; }

  private:
    glm::dvec2 a_, uBeta_{0.0}, uGamma_{0.0};
    bool valid_ = false;
};

class BarycentricFrame3 {
  public:
    BarycentricFrame3(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);
    bool valid() const { return valid_; } // as in BarycentricFrame2
    std::optional<Barycentrics> coords(const glm::dvec3& p) const;
    const glm::dvec3& uBeta() const { return uBeta_; }
    const glm::dvec3& uGamma() const { return uGamma_; }

  private:
    glm::dvec3 a_, uBeta_{0.0}, uGamma_{0.0};
    bool valid_ = false;
};

} // namespace wb
