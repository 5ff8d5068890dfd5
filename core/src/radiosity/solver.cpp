#include "core/radiosity/solver.h"

#include <stdexcept>

namespace wb::rad {
Solver::Solver(const PatchMesh& mesh, const FormFactors& ff, SolverConfig config) : mesh_(mesh), ff_(ff), config_(config) { throw std::logic_error("radiosity: solver not implemented yet"); }
double Solver::step() { return 0; }
int Solver::run(const std::atomic<bool>*) { return 0; }
std::vector<glm::dvec3> Solver::displayRadiosity() const { return B_; }
glm::dvec3 Solver::emittedPower() const { return glm::dvec3(0); }
glm::dvec3 Solver::absorbedPower() const { return glm::dvec3(0); }
double Solver::computeResidual() { return 0; }
} // namespace wb::rad
