#include "exercise_view.h"

#include "common/gl.h"
#include "core/i18n.h"
#include "exercises.h"

#include <cmath>

namespace wb {
namespace {

struct Ball {
    glm::dvec3 centre;
    double radius;
    lab07::Material material;
    double kr;
};

// Seed 000's units: colours 0..255, a light 60 units up, distScale 30 (SH ~ 0.5).
const std::vector<Ball>& balls() {
    static const std::vector<Ball> b = {
        {{0, 0, 0}, 20, {{21, 234, 21}, 0.5, 0.5, 0.5, 3}, 0.5},
        {{32, 10, -6}, 12, {{234, 21, 21}, 0.5, 0.5, 0.5, 8}, 0.0},
        {{-28, -14, 4}, 10, {{40, 60, 234}, 0.5, 0.6, 0.7, 20}, 0.3},
    };
    return b;
}
const glm::dvec3 kLight{-30, 50, 60};
const glm::dvec3 kEye{0, 0, 120};
const glm::dvec3 kBackground{128, 207, 255}; // seed 000's

// The functions a picture is traced with: yours where callable, else the reference's.
struct Steps {
    const lab07::Table* hit;
    const lab07::Table* normal;
    const lab07::Table* shade;
    const lab07::Table* reflect;
};

bool nearest(const Steps& s, const glm::dvec3& o, const glm::dvec3& d, double& tBest, int& which) {
    which = -1;
    tBest = 1e30;
    for (size_t i = 0; i < balls().size(); ++i) {
        double t = 0;
        if (s.hit->intersectSphere(o, d, balls()[i].centre, balls()[i].radius, t) && t > 1e-6 &&
            t < tBest)
            tBest = t, which = int(i);
    }
    return which >= 0;
}

glm::dvec3 trace(const Steps& s, const glm::dvec3& o, const glm::dvec3& d, int depth) {
    double t = 0;
    int k = -1;
    if (!nearest(s, o, d, t, k)) return kBackground;
    const Ball& b = balls()[size_t(k)];
    lab07::ShadeInput in;
    in.point = o + t * d;
    in.normal = s.normal->sphereNormal(in.point, b.centre, b.radius);
    in.view = d;
    in.material = b.material;
    in.lightPos = kLight;
    const lab07::Feeler feeler = [&s](const glm::dvec3& from, const glm::dvec3& to) {
        const glm::dvec3 v = to - from;
        const double dist = glm::length(v);
        double tt = 0;
        int w = -1;
        const glm::dvec3 start = from + 1e-6 * v / dist;
        return nearest(s, start, v / dist, tt, w) && tt < dist ? 0.0 : 1.0;
    };
    glm::dvec3 c = s.shade->shade(in, feeler);
    if (b.kr > 0 && depth < 2) {
        const glm::dvec3 r = s.reflect->reflectDirection(d, in.normal);
        const double len = glm::length(r);
        if (len > 0 && std::isfinite(len))
            c = lab07::add(
                c, lab07::mulBy(trace(s, in.point + 1e-6 * r / len, r / len, depth + 1), b.kr));
    }
    return c;
}

void render(const Steps& s, int w, int h, std::vector<uint8_t>& out) {
    out.assign(size_t(w) * size_t(h) * 3, 0);
    const double half = 45; // world units across half the height, at the screen z = 0
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const glm::dvec3 p((x + 0.5 - w / 2.0) * 2 * half / h,
                               (y + 0.5 - h / 2.0) * 2 * half / h, 0);
            glm::dvec3 c(0);
            try {
                c = trace(s, kEye, glm::normalize(p - kEye), 0);
            } catch (...) {
                c = glm::dvec3(255, 0, 255); // a step that threw: magenta
            }
            uint8_t* px = &out[(size_t(y) * size_t(w) + size_t(x)) * 3];
            for (int i = 0; i < 3; ++i)
                px[i] = uint8_t(std::isfinite(c[i]) ? std::fmin(255.0, std::fmax(0.0, c[i])) : 0);
        }
}

} // namespace

ExerciseTrace traceExercise(const ex::ExerciseMode& mode, int width, int height) {
    ExerciseTrace t;
    t.width = width, t.height = height;
    const auto* ref = mode.referenceTable<lab07::Table>(); // nullptr in a handout
    const auto* mine = mode.studentTable<lab07::Table>();
    // A step is yours when its check let it be called (passing or failing: a failing step
    // shows what it does); the others are the reference's.
    auto pick = [&](const char* id, const char* name) {
        const bool yours = mine && mode.callTried(id, [] { return true; }).has_value();
        if (yours) t.usedYours += std::string(t.usedYours.empty() ? "" : ", ") + name;
        return yours ? mine : ref;
    };
    Steps s{pick("07.intersect", "intersectSphere"), pick("07.normal", "sphereNormal"),
            pick("07.shade", "shade"), pick("07.reflect", "reflectDirection")};
    // Each step of yours traces the whole picture once in a child, with the reference's other
    // steps (in a handout: with yours), before the lab calls it: a step that passes its checks
    // but crashes or loops on one of these rays fails in the panel and the reference's stands
    // in; then all yours together (a NaN of one step crashing another).
    if (mine) {
        const uint64_t key = ex::ExerciseMode::inputKey(width, height);
        std::vector<uint8_t> scratch;
        const char* ids[4] = {"07.intersect", "07.normal", "07.shade", "07.reflect"};
        const lab07::Table** steps[4] = {&s.hit, &s.normal, &s.shade, &s.reflect};
        bool allTried = true;
        for (int i = 0; i < 4; ++i) {
            if (*steps[i] != mine) continue;
            Steps one = ref ? Steps{ref, ref, ref, ref} : s;
            const lab07::Table** oneSteps[4] = {&one.hit, &one.normal, &one.shade, &one.reflect};
            *oneSteps[i] = mine;
            if (!mode.tryInChild(ids[i], key, [&] { render(one, width, height, scratch); })) {
                *steps[i] = ref;
                allTried = false;
            }
        }
        if (allTried &&
            !mode.tryInChild("07.picture", key, [&] { render(s, width, height, scratch); }))
            s = Steps{ref, ref, ref, ref};
        const char* names[4] = {"intersectSphere", "sphereNormal", "shade", "reflectDirection"};
        t.usedYours.clear();
        for (int i = 0; i < 4; ++i)
            if (*steps[i] == mine)
                t.usedYours += std::string(t.usedYours.empty() ? "" : ", ") + names[i];
    }
    // In a handout a step of yours that is not done has no stand-in: no picture until all are.
    if (s.hit && s.normal && s.shade && s.reflect) render(s, width, height, t.mine);
    if (ref) render({ref, ref, ref, ref}, width, height, t.reference);
    return t;
}

void drawExerciseTrace(const ExerciseTrace& t, int viewWidth, int viewHeight) {
    if (t.mine.empty() && t.reference.empty()) return;
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, viewWidth, 0, viewHeight, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_LIGHTING);
    const float zoom =
        std::fmin(float(viewWidth) / float(t.width), float(viewHeight) / float(t.height));
    const float x0 = 0.5f * (float(viewWidth) - zoom * float(t.width));
    const float y0 = 0.5f * (float(viewHeight) - zoom * float(t.height));
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelZoom(zoom, zoom);
    if (!t.mine.empty()) {
        glRasterPos2f(x0, y0);
        glDrawPixels(t.width, t.height, GL_RGB, GL_UNSIGNED_BYTE, t.mine.data());
    }
    if (t.reference.empty()) {
        glPixelZoom(1, 1);
        return;
    }
    // The reference over it, translucent (the ghost): where both agree nothing changes.
    glEnable(GL_BLEND);
    glBlendColor(0, 0, 0, ex::ExerciseMode::kGhostAlpha);
    glBlendFunc(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA);
    glRasterPos2f(x0, y0);
    glDrawPixels(t.width, t.height, GL_RGB, GL_UNSIGNED_BYTE, t.reference.data());
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDisable(GL_BLEND);
    glPixelZoom(1, 1);
}

} // namespace wb
