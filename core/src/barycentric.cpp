#include "core/barycentric.h"

#include <cmath>

namespace wb {
namespace {
bool finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
} // namespace

BarycentricFrame2::BarycentricFrame2(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c)
    : a_(a) {
    const glm::dvec2 e1 = b - a, e2 = c - a;
    // k = e1×e2 (z component). In 2D, u_β = e2×(e1×e2)/k² = (e2.y, −e2.x)/k and
    // u_γ = e1×(e2×e1)/k² = (−e1.y, e1.x)/k.
    const double k = e1.x * e2.y - e1.y * e2.x;
    if (k == 0.0 || !std::isfinite(k)) return;
    uBeta_ = glm::dvec2(e2.y, -e2.x) / k;
    uGamma_ = glm::dvec2(-e1.y, e1.x) / k;
    valid_ = std::isfinite(uBeta_.x) && std::isfinite(uBeta_.y) && std::isfinite(uGamma_.x) &&
             std::isfinite(uGamma_.y);
}

std::optional<Barycentrics> BarycentricFrame2::coords(const glm::dvec2& p) const {
    if (!valid_) return std::nullopt;
    const glm::dvec2 f = p - a_;
    const double beta = glm::dot(uBeta_, f), gamma = glm::dot(uGamma_, f);
    if (!std::isfinite(beta) || !std::isfinite(gamma)) return std::nullopt; // p not finite
    return Barycentrics(1.0 - beta - gamma, beta, gamma);
}

BarycentricFrame3::BarycentricFrame3(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c)
    : a_(a) {
    const glm::dvec3 e1 = b - a, e2 = c - a;
    const glm::dvec3 n = glm::cross(e1, e2);
    const double nn = glm::dot(n, n); // = (e1,e1)(e2,e2) − (e1,e2)², the denominator of (4.6)
    if (nn == 0.0 || !std::isfinite(nn)) return;
    uBeta_ = glm::cross(e2, n) / nn;  // ((e2,e2)e1 − (e1,e2)e2) / denominator
    uGamma_ = glm::cross(n, e1) / nn; // ((e1,e1)e2 − (e1,e2)e1) / denominator
    valid_ = finite(uBeta_) && finite(uGamma_);
}

std::optional<Barycentrics> BarycentricFrame3::coords(const glm::dvec3& p) const {
    if (!valid_) return std::nullopt;
    const glm::dvec3 f = p - a_;
    const double beta = glm::dot(uBeta_, f), gamma = glm::dot(uGamma_, f);
    if (!std::isfinite(beta) || !std::isfinite(gamma)) return std::nullopt; // p not finite
    return Barycentrics(1.0 - beta - gamma, beta, gamma);
}

} // namespace wb
