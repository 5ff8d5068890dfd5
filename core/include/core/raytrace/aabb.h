#pragma once
// Axis-aligned bounding box: what an acceleration structure (BVH, next issue) needs
// from every primitive. Unbounded primitives (the infinite plane) return an
// infinite box and say so with bounded() == false.
#include <glm/glm.hpp>

#include <limits>

namespace wb::rt {

struct Aabb {
    glm::dvec3 lo{std::numeric_limits<double>::infinity()};  // min corner (empty box: +inf)
    glm::dvec3 hi{-std::numeric_limits<double>::infinity()}; // max corner (empty box: -inf)

    void extend(const glm::dvec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    bool bounded() const;
    bool contains(const glm::dvec3& p) const {
        return p.x >= lo.x && p.y >= lo.y && p.z >= lo.z && p.x <= hi.x && p.y <= hi.y &&
               p.z <= hi.z;
    }
    static Aabb infinite() {
        const double inf = std::numeric_limits<double>::infinity();
        return Aabb{glm::dvec3(-inf), glm::dvec3(inf)};
    }
};

inline bool Aabb::bounded() const {
    for (int i = 0; i < 3; ++i)
        if (!(lo[i] > -std::numeric_limits<double>::max() &&
              hi[i] < std::numeric_limits<double>::max()))
            return false;
    return true;
}

} // namespace wb::rt
