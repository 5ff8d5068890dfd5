#include "core/raytrace/scene.h"

#include <stdexcept>
#include <string>

namespace wb::rt {

bool BruteForce::intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const {
    bool found = false;
    for (const auto& p : prims_)
        if (p->intersect(ray, tMin, tMax, hit)) {
            tMax = hit.t; // later primitives must be nearer
            found = true;
        }
    return found;
}

void BruteForce::forEachHit(const Ray& ray, double tMin, double tMax,
                            const std::function<bool(const Hit&)>& visit) const {
    Hit h;
    for (const auto& p : prims_)
        if (p->intersect(ray, tMin, tMax, h) && !visit(h)) return;
}

void BruteForce::forEachBlocker(const Ray& ray, double tMin, double tMax,
                                const std::function<bool(const Primitive&)>& visit,
                                const Primitive* skip) const {
    for (const auto& p : prims_)
        if (p.get() != skip && p->occluded(ray, tMin, tMax) && !visit(*p)) return;
}

Scene::Scene() : bruteForce_(primitives) {
    materials.push_back(Material{});
}

int Scene::addMaterial(const Material& m) {
    materials.push_back(m);
    return int(materials.size()) - 1;
}

void Scene::addPrimitive(std::unique_ptr<Primitive> prim, int materialIndex) {
    if (materialIndex < 0 || size_t(materialIndex) >= materials.size())
        throw std::out_of_range("Scene: material index " + std::to_string(materialIndex) +
                                " does not exist");
    prim->material = materialIndex;
    primitives.push_back(std::move(prim));
}

} // namespace wb::rt
