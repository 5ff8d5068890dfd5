// Student code that misbehaves in every way the runner must survive (issue 18 item 3): a
// crash, an endless loop and an exception, one per task of lab 01. Built like a student's
// exercises.cpp; the test expects each task reported failing with the signal, the timeout
// and the exception, and wb-check itself to finish.
#include "exercises.h"

#include <csignal>
#include <stdexcept>

namespace wb::lab01 {

glm::dmat3 mirrorMatrix(glm::dvec2, glm::dvec2) {
    std::raise(SIGSEGV); // as a null pointer or an index far out of range would
    return glm::dmat3(1.0);
}

glm::dmat3 shadowDirectionalMatrix(glm::dvec2 k, glm::dvec2, glm::dvec2) {
    volatile double x = k.x;
    while (x == x) { // an endless loop
    }
    return glm::dmat3(x);
}

glm::dmat3 shadowPointMatrix(glm::dvec2, glm::dvec2, glm::dvec2) {
    throw std::runtime_error("vector::at out of range");
}

} // namespace wb::lab01

WB_EXERCISE_TABLE(wb::lab01::Table, lab01,
                  {&wb::lab01::mirrorMatrix, &wb::lab01::shadowDirectionalMatrix,
                   &wb::lab01::shadowPointMatrix})
