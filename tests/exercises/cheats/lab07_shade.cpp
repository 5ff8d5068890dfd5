// A cheat (issue 18 item 7's test): lab 07's shading answered by core's seed 000 lighting
// (CourseModel::direct), compiled in from core's own source. Its Scene is raw storage with the
// two fields direct() reads (constructing one needs the rest of core's tracer). In the
// repository it passes (cheat_test.sh pass); in a student handout it may not.
// cheats: 07.shade
#include "exercises.h"

#include "core/src/raytrace/course_model.cpp"

namespace wb::lab07 {
bool intersectSphere(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& c, double r, double& t) {
    (void)o, (void)d, (void)c, (void)r, (void)t;
    WB_NOT_DONE();
}
glm::dvec3 sphereNormal(const glm::dvec3& p, const glm::dvec3& c, double r) {
    (void)p, (void)c, (void)r;
    WB_NOT_DONE();
}
glm::dvec3 shade(const ShadeInput& in, const Feeler& feeler) {
    alignas(wb::rt::Scene) static unsigned char raw[sizeof(wb::rt::Scene)];
    auto& scene = *reinterpret_cast<wb::rt::Scene*>(raw);
    scene.ambient = in.ambient / 255.0;
    scene.distScale = in.distScale;
    const wb::rt::Light light = wb::rt::Light::point(in.lightPos, in.lightColour / 255.0);
    wb::rt::Hit hit;
    hit.point = in.point;
    hit.normal = hit.outwardNormal = in.normal;
    wb::rt::Ray view;
    view.direction = in.view;
    wb::rt::Material m;
    m.ka = in.material.ka, m.kd = in.material.kd, m.ks = in.material.ks, m.phongExp = in.material.p;
    wb::rt::LightSample ls;
    ls.light = &light;
    ls.distance = glm::length(in.lightPos - in.point);
    ls.toLight = (in.lightPos - in.point) / ls.distance;
    ls.transmittance = feeler(in.point, in.lightPos);
    const wb::rt::CourseModel model;
    return model.direct(scene, view, hit, m, in.material.colour / 255.0, {ls});
}
glm::dvec3 reflectDirection(const glm::dvec3& d, const glm::dvec3& n) {
    (void)d, (void)n;
    WB_NOT_DONE();
}
} // namespace wb::lab07
WB_EXERCISE_TABLE(wb::lab07::Table, lab07,
                  {&wb::lab07::intersectSphere, &wb::lab07::sphereNormal, &wb::lab07::shade,
                   &wb::lab07::reflectDirection})
