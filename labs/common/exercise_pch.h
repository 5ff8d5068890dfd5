// (No #pragma once: GCC warns on it in a precompiled main file; it is included once, by -include.)
// What the exercise files include (glm, the standard library), precompiled once by the build
// with the live reload's own flags (labs/common/exercises.cmake): the running lab's rebuild
// of a saved exercises.cpp then parses none of it again. GCC uses the .gch beside the copy of
// this header in build/exercises/pch/ when it fits the flags, else this header as is.
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numeric>
#include <random>
#include <string>
#include <utility>
#include <vector>
