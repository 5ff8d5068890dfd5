// Lab 01 - affine maps: YOUR answers (course §2.1). Edit the bodies; the running lab
// rebuilds this file when you save it (press `e` in the lab to see your matrices drawn over
// the reference), and `./wb check lab01` grades it: ③ mirror, ④ + shadow at infinity,
// ⑤ + shadow from a point light.
//
// Every task is ONE homogeneous 3x3 matrix M (practical 1): a point P = (x, y) is the
// column (x, y, 1); M P = (x', y', w') is the point (x'/w', y'/w'). Any non-zero multiple of
// M is the same map, and the check accepts it. glm is column-major: M[c][r] is row r,
// column c; glm::dmat3(1.0) is the identity; glm::outerProduct(a, b) is a bᵀ.
// The line Λ through K and L: a x + b y + c = 0 with (a, b) = (K.y - L.y, L.x - K.x),
// c = -(a K.x + b K.y); pi = (a, b, c) so that pi·P = 0 for P on Λ. K != L always.
#include "exercises.h"

namespace wb::lab01 {

// ③ Mirror image Θ' of the object in the line Λ through K and L (§2.1 ③, fig. 1.1 a;
// exercise 1.1: T(p0) R(φ) Mx R(-φ) T(-p0), or in closed form the linear part
// I - 2 n nᵀ/(n·n) with n = (a, b) and a translation that keeps Λ fixed).
// Inputs: K, L anywhere with |K|, |L| up to 1e4; the line may be vertical, horizontal, or
// pass through the origin.
glm::dmat3 mirrorMatrix(glm::dvec2 k, glm::dvec2 l) {
    (void)k, (void)l;
    WB_NOT_DONE();
}

// ④ Shadow on Λ from a light at infinity: the rays travel along the vector `dir`
// (§2.1 ④, fig. 1.1 b; practical 1.2: M = I - l piᵀ/(n·l) with l = (dir, 0)). Multiplied by
// (n·l) it has no division: M = (n·l) I - l piᵀ.
// Degenerate: rays parallel to Λ (n·l = 0) never reach it; the map then sends every point
// to the point at infinity along l (the division-free form gives exactly that). Must not
// produce NaN or Inf.
glm::dmat3 shadowDirectionalMatrix(glm::dvec2 k, glm::dvec2 l, glm::dvec2 dir) {
    (void)k, (void)l, (void)dir;
    WB_NOT_DONE();
}

// ⑤ Shadow on Λ from a point light S (§2.1 ⑤, fig. 1.1 c; practical 1.3):
// M = (pi·S) I - S piᵀ with S = (S.x, S.y, 1) (or any non-zero multiple).
// Degenerate: S on Λ (pi·S = 0): every point goes to S itself, M = -S piᵀ (rank 1); do not
// divide by pi·S. No NaN or Inf.
glm::dmat3 shadowPointMatrix(glm::dvec2 k, glm::dvec2 l, glm::dvec2 s) {
    (void)k, (void)l, (void)s;
    WB_NOT_DONE();
}

} // namespace wb::lab01

WB_EXERCISE_TABLE(wb::lab01::Table, lab01,
                  {&wb::lab01::mirrorMatrix, &wb::lab01::shadowDirectionalMatrix,
                   &wb::lab01::shadowPointMatrix})
