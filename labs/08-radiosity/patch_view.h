#pragma once
// Drawing a patch mesh for lab 08: flat (one colour per patch, figure 13.42), smooth
// (Gouraud between vertex colours, figure 13.43), patch outlines, and an item-id pass
// for picking a patch under the mouse. The triangles are core's displayTriangles, so
// the T-vertices of adaptive refinement are vertices of the drawn mesh and Gouraud
// shows no crack.
#include "core/radiosity/mesh.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace wb {

class PatchView {
  public:
    // Takes the mesh's geometry (after every remesh or refinement).
    void setMesh(const rad::PatchMesh& mesh);
    // Colours in display units (0..1, already tone-mapped): one per patch for flat, one
    // per mesh vertex for smooth.
    void setPatchColours(const std::vector<glm::vec3>& colours) { patchColour_ = colours; }
    void setVertexColours(const std::vector<glm::vec3>& colours) { vertexColour_ = colours; }

    // Draws with the current matrices: smooth (vertex colours) or flat (patch colours).
    void draw(bool smooth) const;
    // Flat, with these colours per patch instead (the form-factor row map).
    void drawFlat(const std::vector<glm::vec3>& patchColours) const;
    // Patch outlines (corners and T-vertices), in `colour`, slightly in front of the faces.
    void drawOutlines(const glm::vec3& colour) const;
    // One patch's outline, thicker (the clicked patch).
    void drawPatchOutline(int patch, const glm::vec3& colour, float width) const;
    // Every patch in its item colour (id + 1 in 24-bit RGB, unlit, no dithering) for picking.
    void drawItems() const;

    const std::vector<std::array<int, 3>>& triangles() const { return tris_; }
    const std::vector<int>& triangleOwner() const { return owner_; }
    // The triangles as three vertices each with their patch, for the GL hemicube.
    void hemicubeGeometry(std::vector<glm::vec3>& vertices, std::vector<uint32_t>& items) const;

  private:
    std::vector<glm::vec3> positions_;        // mesh vertices (float, for GL)
    std::vector<std::array<int, 3>> tris_;    // display triangles (vertex ids)
    std::vector<int> owner_;                  // patch of each triangle
    std::vector<std::vector<int>> outlines_;  // per patch: outline vertex ids
    std::vector<glm::vec3> patchColour_, vertexColour_;
};

} // namespace wb
