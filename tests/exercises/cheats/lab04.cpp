// A cheat (issue 18 item 7's test): lab 04's tasks answered by calling the core functions
// that compute them, compiled in from core's own sources. In the repository, where those
// sources hold the answers, each task passes (cheat_test.sh pass: the cheat is a real one);
// in a student handout, where the bodies are cut, none may pass (cheat_test.sh fail).
// 04.texel has no such function (OpenGL's own sampling): it stays a stub.
// cheats: 04.sphere 04.torus 04.spheremap
#include "exercises.h"

#include "core/src/mesh.cpp"
#include "core/src/sphere_map.cpp"

namespace wb::lab04 {
namespace {
Mesh fromCore(const wb::Mesh& c) {
    Mesh m;
    m.positions = c.positions;
    m.normals = c.normals;
    m.texCoords = c.texCoords;
    m.indices.assign(c.indices.begin(), c.indices.end());
    return m;
}
} // namespace

int texelIndex(double s, int size, bool repeat) {
    (void)s, (void)size, (void)repeat;
    WB_NOT_DONE();
}

Mesh sphereMesh(double radius, int slices, int stacks) {
    return fromCore(wb::makeSphere(radius, slices, stacks));
}

Mesh torusMesh(double R, double r, int rings, int sides) {
    return fromCore(wb::makeTorus(R, r, rings, sides));
}

glm::dvec2 sphereMap(const glm::dvec3& eyePos, const glm::dvec3& n) {
    return wb::sphereMapCoord(eyePos, n);
}

} // namespace wb::lab04

WB_EXERCISE_TABLE(wb::lab04::Table, lab04,
                  {&wb::lab04::texelIndex, &wb::lab04::sphereMesh, &wb::lab04::torusMesh,
                   &wb::lab04::sphereMap})
