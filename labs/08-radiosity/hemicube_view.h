#pragma once
// The five hemicube faces of a patch unfolded into one picture (the classic cross): the
// top face in the middle, each side face folded out with its horizon row on the outer
// edge, so the picture is what the patch "sees" with the ceiling in the centre.
#include "core/image.h"
#include "core/radiosity/hemicube.h"

#include <glm/glm.hpp>

#include <vector>

namespace wb {

// (2·res) × (2·res) RGB, row 0 at the top (as Image); pixel colours from `patchColour`
// (display units 0..1) by the item id; `background` where nothing is seen (and in the
// four corners outside the cross).
Image unfoldHemicube(const rad::ItemBuffer& items, const std::vector<glm::vec3>& patchColour,
                     const glm::vec3& background);

// Where pixel (col, row) of face f lands in the unfolded picture, as (X, Y) with X to the
// right and Y UP (0..2·res−1): the view from the patch looking along its normal n with v
// up, so X runs along −u (n × v) and the +U face is folded out on the left.
glm::ivec2 unfoldedPosition(int res, rad::HemicubeFace f, int col, int row);

} // namespace wb
