#include "exercise_view.h"

#include "common/gl.h"
#include "exercises.h"

namespace wb {

std::optional<glm::dmat4> exerciseReflection(const ex::ExerciseMode& mode, const Plane& plane,
                                             const std::optional<glm::dmat4>& reference) {
    const auto* t = mode.on() ? mode.studentTable<lab05::Table>() : nullptr;
    if (!t) return reference;
    const auto m = mode.call(
        "05.reflection", [&] { return t->reflectionMatrix(glm::dvec4(plane.n, plane.d)); }, plane.n,
        plane.d);
    return m ? m : reference;
}

std::optional<glm::dmat4> exerciseShadow(const ex::ExerciseMode& mode, const Plane& plane,
                                         const glm::dvec3& light,
                                         const std::optional<glm::dmat4>& reference) {
    const auto* t = mode.on() ? mode.studentTable<lab05::Table>() : nullptr;
    if (!t) return reference;
    const auto m = mode.call(
        "05.shadow",
        [&] { return t->shadowMatrix(glm::dvec4(plane.n, plane.d), glm::dvec4(light, 1.0)); },
        plane.n, plane.d, light);
    return m ? m : reference;
}

std::vector<glm::dvec3> exerciseEllipse(const ex::ExerciseMode& mode, const glm::dvec2& centre,
                                        double a, double b, double z, int n,
                                        const std::vector<glm::dvec3>& reference) {
    const auto* t = mode.on() ? mode.studentTable<lab05::Table>() : nullptr;
    if (!t) return reference;
    const auto e = mode.call(
        "05.ellipse", [&] { return t->ellipseOutline(centre, a, b, z, n); }, centre, a, b, z, n);
    return e && e->size() >= 3 ? *e : reference;
}

void drawEllipseGhost(const std::vector<glm::dvec3>& reference) {
    glPushAttrib(GL_ENABLE_BIT | GL_CURRENT_BIT | GL_LINE_BIT);
    glDisable(GL_LIGHTING);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    ex::ExerciseMode::ghostBegin();
    glColor3f(1.0f, 1.0f, 0.3f);
    glLineWidth(3.0f);
    glBegin(GL_LINE_LOOP);
    for (const glm::dvec3& p : reference)
        glVertex3d(p.x, p.y, p.z + 0.01); // just in front of the glass
    glEnd();
    ex::ExerciseMode::ghostEnd();
    glPopAttrib();
}

} // namespace wb
