#pragma once
// The lab's scenes (metres, E in W/m² of any consistent scale):
//  - cornellBox(): Cornell's "Cornell Box Data" (measured geometry in mm, converted to m;
//    light 343 × 332 ... ), reflectances reduced to RGB as docs/radiosity-core.md explains;
//  - classroom(): the course's example (§1.13): ceiling lamps, painted walls, tables, a red box
//    beside a white wall (colour bleeding);
//  - floorLamp(): the course's second example: a lamp whose shade sends all its light to the
//    ceiling, lighting the room only indirectly;
//  - furnace(): a closed cube with uniform R and E (test: B = E/(1−R));
//  - two small test scenes for the closed forms.
#include "core/radiosity/scene.h"

namespace wb::rad {

// Spectrum -> RGB reflectance by band averages: blue = mean of the samples in [400, 500) nm,
// green [500, 600), red [600, 700]; samples outside 400..700 are ignored. Throws if a band
// has no sample.
glm::dvec3 spectrumToRgbBands(const std::vector<double>& samples, double firstNm, double stepNm);

Scene cornellBox();
Scene classroom();
Scene floorLamp();
Scene furnace(double reflectivity, double emission);
// Two directly opposed parallel rectangles a × b, distance c (each facing the other).
Scene parallelPlates(double a, double b, double c);
// Two rectangles sharing an edge of length l at a right angle, widths w1, w2.
Scene perpendicularPlates(double l, double w1, double w2);

std::vector<std::string> sceneNames(); // "cornell", "classroom", "floorlamp"
Scene sceneByName(const std::string& name); // throws std::invalid_argument for an unknown name

} // namespace wb::rad
