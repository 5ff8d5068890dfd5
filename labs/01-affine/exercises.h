#pragma once
// Lab 01's graded tasks (course §2.1, practical 1): each answer is ONE homogeneous 3x3
// matrix M, applied to all vertices at once, [P'1 ... P'n] = M [P1 ... Pn], then
// (x, y, w) -> (x/w, y/w). Points are (x, y, 1); glm matrices are column-major:
// m[c][r] is row r of column c. See exercises.cpp for each task in the course's terms.
#include "common/exercise.h"

#include <glm/glm.hpp>

namespace wb::lab01 {

// ③ Mirror image in the line Λ through K and L.
glm::dmat3 mirrorMatrix(glm::dvec2 k, glm::dvec2 l);
// ④ Shadow on Λ from a light at infinity whose rays travel along `dir`.
glm::dmat3 shadowDirectionalMatrix(glm::dvec2 k, glm::dvec2 l, glm::dvec2 dir);
// ⑤ Shadow on Λ from a point light S.
glm::dmat3 shadowPointMatrix(glm::dvec2 k, glm::dvec2 l, glm::dvec2 s);

// The table the lab and wb-check reach your functions through (task order).
struct Table {
    glm::dmat3 (*mirror)(glm::dvec2, glm::dvec2);
    glm::dmat3 (*shadowDirectional)(glm::dvec2, glm::dvec2, glm::dvec2);
    glm::dmat3 (*shadowPoint)(glm::dvec2, glm::dvec2, glm::dvec2);
};

} // namespace wb::lab01
