#!/bin/sh
# handout_cheats.sh ROOT BUILD WORK (issue 18 item 7, labs 06-08): "cheat mutants". For each
# graded task whose answer core computes, an exercise file that just compiles in core's own
# code (#include of its source, as a student could copy it) and calls the function that
# computes the answer. In a handout (ROOT made by ./wb handout, BUILD its build) none of them
# may pass: each fails to compile, throws (the cut body) or is not done. Run against the
# repository itself (ROOT = the checkout, BUILD its build) it must go red: every cheat passes
# there, which shows the cheats do reach the answers.
# Not covered, and why (docs/exercises.md, "Labs 06-08 in a handout"): 06.point (core's Bezier
# evaluation is kept: the teapot and the checks of 06.circle/06.sphere need it), 08.jacobi (Solver needs the whole radiosity core: no cheat compiles alone;
# the cut is checked by grep below).
set -eu
root=$1 build=$2 work=$3
mkdir -p "$work"
leaks=0
cheat() { # cheat NN TASK FILE.cpp [known]: known = a leak accepted in docs/exercises.md
  nn=$1 task=$2 src=$3 known=${4:-}
  so=$work/cheat-$task.so
  # The lab's own compile line, plus core's sources on the include path; --gc-sections drops
  # the parts of an included file the cheat does not call (and what they need from core).
  # --no-undefined: a cheat that needs more of core than it includes fails here, not silently
  # at load time (not under a sanitizer: its runtime comes from the program that loads it).
  strict=-Wl,--no-undefined
  grep -q -- -fsanitize "$build/exercises/lab$nn.compile" && strict=
  sed "s|\"\\\$1\" -o \"\\\$2\"|-ffunction-sections -fdata-sections -Wl,--gc-sections $strict \"\$1\" -o \"\$2\"|" \
    "$build/exercises/lab$nn.compile" > "$work/compile-$nn.sh"
  # The cuts keep every declaration (bodies are replaced), so each cheat builds in a handout
  # as in the repository: one that does not is a broken cheat, and proves nothing.
  if ! CPLUS_INCLUDE_PATH=$root/core/include:$root sh "$work/compile-$nn.sh" "$src" "$so" > "$work/cheat-$task.log" 2>&1; then
    echo "BROKEN: cheat $task does not build: $(grep -m1 'error' "$work/cheat-$task.log" || true)"
    leaks=$((leaks + 1))
    return
  fi
  line=$("$build/bin/wb-check" "lab$nn" --student "$nn=$so" 2>&1 | grep -m1 " $task" || true)
  case $line in
    *✓*) if [ -n "$known" ] && [ -z "${CHEATS_STRICT:-}" ]; then
           echo "known, accepted (docs/exercises.md): cheat $task passes: $line"
         else
           echo "LEAK: cheat $task passes: $line"; leaks=$((leaks + 1))
         fi ;;
    '') echo "LEAK?: cheat $task: no line for the task"; leaks=$((leaks + 1)) ;;
    *) echo "cheat $task: does not pass: $line" ;;
  esac
}

l06() { # the file's head and tail around one lab 06 task body
  cat > "$work/$1.cpp" <<EOF
#include "exercises.h"
#include "core/src/bezier.cpp"
#include "core/src/bezier_shapes.cpp"
namespace wb::lab06 {
glm::dvec3 bezierPoint(const Curve& p, double u) {
    $2
}
std::vector<Curve> circleCurves(double radius) {
    $3
}
std::vector<Patch> spherePatches() {
    $4
}
} // namespace wb::lab06
WB_EXERCISE_TABLE(wb::lab06::Table, lab06,
                  {&wb::lab06::bezierPoint, &wb::lab06::circleCurves, &wb::lab06::spherePatches})
EOF
}
nd='WB_NOT_DONE();'
l06 c06point 'return wb::evalDeCasteljau(p, u);' "(void)radius; $nd" "$nd"
l06 c06circle "(void)p, (void)u; $nd" 'return wb::circleArcs(2, wb::circleHandle(2), radius);' "$nd"
l06 c06sphere "(void)p, (void)u; $nd" "(void)radius; $nd" \
  'std::vector<Patch> out; for (const auto& b : wb::sphereFromNet(wb::labHemisphereNet())) out.push_back(Patch{b.orderU, b.orderV, b.points}); return out;'

l08() {
  cat > "$work/$1.cpp" <<EOF
#include "exercises.h"
#include "core/src/radiosity/ray_form_factors.cpp"
namespace wb::lab08 {
namespace {
wb::rad::Patch patchOf(const Quad& q) { // core's patch: centre, unit normal, area
    wb::rad::Patch p;
    p.centre = 0.25 * (q.p[0] + q.p[1] + q.p[2] + q.p[3]);
    const glm::dvec3 a = 0.5 * glm::cross(q.p[2] - q.p[0], q.p[3] - q.p[1]);
    p.area = glm::length(a);
    p.normal = a / p.area;
    return p;
}
} // namespace
double formFactor(const Quad& i, const Quad& j) {
    $2
}
std::vector<double> jacobiSweep(const std::vector<double>& B, const std::vector<double>& E,
                                const std::vector<double>& R, const std::vector<double>& F) {
    (void)B, (void)E, (void)R, (void)F;
    WB_NOT_DONE();
}
double formFactorRays(const Quad& i, const Quad& j, int k, unsigned seed, const Visible& visible) {
    $3
}
} // namespace wb::lab08
WB_EXERCISE_TABLE(wb::lab08::Table, lab08,
                  {&wb::lab08::formFactor, &wb::lab08::jacobiSweep, &wb::lab08::formFactorRays})
EOF
}
ff='const wb::rad::Patch a = patchOf(i), b = patchOf(j);
    if (!(a.area > 0) || !(b.area > 0) || a.centre == b.centre) return 0;
    return wb::rad::centresKernel(a, b, b.centre - a.centre'
l08 c08ff "$ff, 1.0);" "(void)i, (void)j, (void)k, (void)seed, (void)visible; $nd"
# (15.20) from core times V counted on an m×m grid of each patch, paired in order (the lab's
# blockers are planes between them: any fair pairing gives the same V within the check's band).
l08 c08rays "(void)i, (void)j; $nd" "$ff, [&] {
        const int m = int(std::lround(std::sqrt(double(k)))); int seen = 0; (void)seed;
        for (int y = 0; y < m; ++y) for (int x = 0; x < m; ++x) {
            const double s = (x + 0.5) / m, t = (y + 0.5) / m;
            auto at = [&](const Quad& q) { return (1 - s) * (1 - t) * q.p[0] + s * (1 - t) * q.p[1] + s * t * q.p[2] + (1 - s) * t * q.p[3]; };
            seen += visible(at(i), at(j)) ? 1 : 0; }
        return double(seen) / double(m * m); }());"

# 07.intersect, 07.normal: core's sphere test (sphere.cpp's nearest<true>, what Sphere::intersect
# and the BVH's exact confirmation call); 07.reflect: core's reflectDir (tracer.cpp).
l07() {
  cat > "$work/$1.cpp" <<EOF
#include "exercises.h"
#include "core/src/raytrace/ray.cpp"
#include "core/src/raytrace/sphere.cpp"
#include "core/src/raytrace/tracer.cpp"
#include <cfloat>
namespace wb::lab07 {
bool intersectSphere(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& c, double r, double& t) {
    $2
}
glm::dvec3 sphereNormal(const glm::dvec3& p, const glm::dvec3& c, double r) {
    $3
}
glm::dvec3 shade(const ShadeInput& in, const Feeler& feeler) {
    (void)in, (void)feeler;
    WB_NOT_DONE();
}
glm::dvec3 reflectDirection(const glm::dvec3& d, const glm::dvec3& n) {
    $4
}
} // namespace wb::lab07
WB_EXERCISE_TABLE(wb::lab07::Table, lab07,
                  {&wb::lab07::intersectSphere, &wb::lab07::sphereNormal, &wb::lab07::shade,
                   &wb::lab07::reflectDirection})
EOF
}
ray='wb::rt::Ray ray; ray.origin = o; ray.direction = d; glm::dvec3 n;
    return wb::rt::nearest<true>(c, r, ray, 0.0, DBL_MAX, t, n);'
# The normal as nearest<true> gives it at the point, for a ray from outside straight at it.
normal='wb::rt::Ray ray; ray.origin = p + (p - c); ray.direction = glm::normalize(c - p);
    double t; glm::dvec3 n(0.0);
    if (!wb::rt::nearest<true>(c, r, ray, 0.0, DBL_MAX, t, n)) return glm::dvec3(0.0);
    return n;'
l07 c07intersect "$ray" "(void)p, (void)c, (void)r; $nd" "(void)d, (void)n; $nd"
l07 c07normal "(void)o, (void)d, (void)c, (void)r, (void)t; $nd" "$normal" "(void)d, (void)n; $nd"
l07 c07reflect "(void)o, (void)d, (void)c, (void)r, (void)t; $nd" "(void)p, (void)c, (void)r; $nd" 'return wb::rt::reflectDir(d, n);'

# 07.shade: core's seed 000 lighting (CourseModel::direct) on the case. Its Scene is raw storage
# with the two fields direct() reads (constructing one needs the rest of core's tracer).
cat > "$work/c07shade.cpp" <<'EOF'
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
EOF

cheat 06 06.point "$work/c06point.cpp" known
cheat 06 06.circle "$work/c06circle.cpp"
cheat 06 06.sphere "$work/c06sphere.cpp"
cheat 07 07.intersect "$work/c07intersect.cpp"
cheat 07 07.normal "$work/c07normal.cpp"
cheat 07 07.shade "$work/c07shade.cpp"
cheat 07 07.reflect "$work/c07reflect.cpp"
cheat 08 08.formfactor "$work/c08ff.cpp"
cheat 08 08.rays "$work/c08rays.cpp"
# 08.jacobi: the sweep's update B_i = E_i + R_i·(F·B_old)_i (wherever it is in solver.cpp; the
# residual's E + R·(F·B) - B is not it, see docs/exercises.md).
if grep -q "= p.emission + p.reflectivity \* FB_\[static_cast<std::size_t>(i)\];" "$root/core/src/radiosity/solver.cpp"; then
  echo "LEAK: 08.jacobi: core's solver still computes B = E + R·(F·B_old)"; leaks=$((leaks + 1))
else
  echo "cheat 08.jacobi: the Jacobi update is cut from core's solver"
fi
echo "cheats: $leaks leak(s)"
[ "$leaks" -eq 0 ]
