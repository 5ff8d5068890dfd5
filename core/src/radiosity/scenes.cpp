#include "core/radiosity/scenes.h"

#include <stdexcept>

namespace wb::rad {
Scene cornellBox() { throw std::logic_error("radiosity: scene not implemented yet"); }
Scene classroom() { throw std::logic_error("radiosity: scene not implemented yet"); }
Scene floorLamp() { throw std::logic_error("radiosity: scene not implemented yet"); }
Scene furnace(double, double) { throw std::logic_error("radiosity: scene not implemented yet"); }
Scene parallelPlates(double, double, double) { throw std::logic_error("radiosity: scene not implemented yet"); }
Scene perpendicularPlates(double, double, double) { throw std::logic_error("radiosity: scene not implemented yet"); }
std::vector<std::string> sceneNames() { return {"cornell", "classroom", "floorlamp"}; }
Scene sceneByName(const std::string&) { throw std::logic_error("radiosity: scene not implemented yet"); }
} // namespace wb::rad
