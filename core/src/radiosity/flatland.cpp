#include "core/radiosity/flatland.h"

#include <stdexcept>

namespace wb::rad {
double crossedStrings(const Segment2&, const Segment2&) { throw std::logic_error("radiosity: not implemented yet"); }
double crossedStringsOccluded(const Segment2&, const Segment2&, const std::vector<Segment2>&) { throw std::logic_error("radiosity: not implemented yet"); }
double course2D(const Segment2&, const Segment2&, const std::vector<Segment2>&, int, bool) { throw std::logic_error("radiosity: not implemented yet"); }
} // namespace wb::rad
