#include "core/radiosity/form_factors.h"

#include <stdexcept>

namespace wb::rad {
FormFactors::FormFactors(const PatchMesh& mesh, FormFactorConfig config) : mesh_(mesh), config_(config) { throw std::logic_error("radiosity: form factors not implemented yet"); }
FormFactors::~FormFactors() = default;
int FormFactors::size() const { return static_cast<int>(mesh_.patches.size()); }
bool FormFactors::stored() const { return !matrix_.empty(); }
void FormFactors::computeAll() {}
const float* FormFactors::row(int, std::vector<float>&) const { throw std::logic_error("radiosity: not implemented yet"); }
float FormFactors::at(int, int) const { throw std::logic_error("radiosity: not implemented yet"); }
bool FormFactors::rowReady(int) const { return false; }
std::size_t FormFactors::bytes() const { return 0; }
double FormFactors::seconds() const { return 0; }
long long FormFactors::rowsComputed() const { return 0; }
void FormFactors::computeRow(int, std::vector<float>&) const {}
} // namespace wb::rad
