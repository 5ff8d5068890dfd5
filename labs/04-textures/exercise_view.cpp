#include "exercise_view.h"

#include "common/gl.h"
#include "exercises.h"

#include <glm/gtc/type_ptr.hpp>

#include <vector>

namespace wb {
namespace {

void arrays(const lab04::Mesh& m, bool withNormals) {
    const size_t n = m.positions.size();
    if (m.normals.size() != n || m.texCoords.size() != n) return;
    for (unsigned i : m.indices)
        if (i >= n) return; // GL would read past the arrays
    std::vector<float> p, nn, t;
    for (size_t i = 0; i < n; ++i) {
        p.insert(p.end(),
                 {float(m.positions[i].x), float(m.positions[i].y), float(m.positions[i].z)});
        nn.insert(nn.end(), {float(m.normals[i].x), float(m.normals[i].y), float(m.normals[i].z)});
        t.insert(t.end(), {float(m.texCoords[i].x), float(m.texCoords[i].y)});
    }
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, p.data());
    if (withNormals) {
        glEnableClientState(GL_NORMAL_ARRAY);
        glEnableClientState(GL_TEXTURE_COORD_ARRAY);
        glNormalPointer(GL_FLOAT, 0, nn.data());
        glTexCoordPointer(2, GL_FLOAT, 0, t.data());
    }
    glDrawElements(GL_TRIANGLES, GLsizei(m.indices.size() / 3 * 3), GL_UNSIGNED_INT,
                   m.indices.data());
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_NORMAL_ARRAY);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
}

lab04::Mesh make(const lab04::Table* t, bool torus, double a, double b, int n, int m) {
    return torus ? t->torusMesh(a, b, n, m) : t->sphereMesh(a, n, m);
}

} // namespace

bool drawExerciseMesh(const ex::ExerciseMode& mode, bool torus, double a, double b, int n, int m) {
    const auto* t = mode.on() ? mode.studentTable<lab04::Table>() : nullptr;
    if (!t) return false;
    const auto mine = mode.call(
        torus ? "04.torus" : "04.sphere", [&] { return make(t, torus, a, b, n, m); }, torus, a, b,
        n, m);
    if (!mine) return false;
    arrays(*mine, true);
    if (const auto* r = mode.referenceTable<lab04::Table>()) {
        glPushAttrib(GL_ENABLE_BIT | GL_CURRENT_BIT | GL_POLYGON_BIT);
        glDisable(GL_LIGHTING);
        glDisable(GL_TEXTURE_2D);
        ex::ExerciseMode::ghostBegin();
        glColor3f(1.0f, 1.0f, 1.0f);
        glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
        arrays(make(r, torus, a, b, n, m), false);
        ex::ExerciseMode::ghostEnd();
        glPopAttrib();
    }
    return true;
}

std::optional<lab04::Mesh> exerciseMesh(const ex::ExerciseMode& mode, bool torus, double a,
                                        double b, int n, int m) {
    const auto* t = mode.on() ? mode.studentTable<lab04::Table>() : nullptr;
    if (!t) return std::nullopt;
    auto mesh =
        mode.call(torus ? "04.torus" : "04.sphere", [&] { return make(t, torus, a, b, n, m); });
    if (!mesh) return std::nullopt;
    const size_t v = mesh->positions.size();
    if (mesh->normals.size() != v || mesh->texCoords.size() != v) return std::nullopt;
    for (unsigned i : mesh->indices)
        if (i >= v) return std::nullopt; // GL would read past the arrays
    mesh->indices.resize(mesh->indices.size() / 3 * 3);
    return mesh;
}

bool exerciseSphereMapReady(const ex::ExerciseMode& mode) {
    const auto* t = mode.on() ? mode.studentTable<lab04::Table>() : nullptr;
    return t && mode.callTried("04.spheremap", [] { return true; }).has_value();
}

void drawWithExerciseSphereMap(const ex::ExerciseMode& mode, const float* positions,
                               const float* normals, size_t vertices, const unsigned* indices,
                               size_t count) {
    const auto* t = mode.studentTable<lab04::Table>();
    if (!t) return;
    GLdouble mv[16];
    glGetDoublev(GL_MODELVIEW_MATRIX, mv);
    const glm::dmat4 m = glm::make_mat4(mv);
    const glm::dmat3 nm = glm::transpose(glm::inverse(glm::dmat3(m)));
    std::vector<float> st(vertices * 2);
    auto coordinates = [&] {
        for (size_t i = 0; i < vertices; ++i) {
            const glm::dvec3 p(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
            const glm::dvec3 n(normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]);
            const glm::dvec3 eyeP = glm::dvec3(m * glm::dvec4(p, 1.0));
            const glm::dvec3 eyeN = glm::normalize(nm * n);
            glm::dvec2 c(0.5);
            try {
                c = t->sphereMap(eyeP, eyeN);
            } catch (...) {
            }
            st[2 * i] = float(c.x), st[2 * i + 1] = float(c.y);
        }
    };
    // Tried once per view in a child: a function that passes its checks but crashes on one
    // of these normals fails in the panel instead of closing the lab.
    uint64_t key = ex::ExerciseMode::inputKey(m, vertices);
    ex::ExerciseMode::hashBytes(key, positions, vertices * 3 * sizeof(float));
    ex::ExerciseMode::hashBytes(key, normals, vertices * 3 * sizeof(float));
    if (!mode.tryInChild("04.spheremap", key, coordinates)) return;
    coordinates();
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, positions);
    glNormalPointer(GL_FLOAT, 0, normals);
    glTexCoordPointer(2, GL_FLOAT, 0, st.data());
    glDrawElements(GL_TRIANGLES, GLsizei(count), GL_UNSIGNED_INT, indices);
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_NORMAL_ARRAY);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
}

} // namespace wb
