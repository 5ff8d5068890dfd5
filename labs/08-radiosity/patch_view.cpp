#include "patch_view.h"

#include "common/gl.h"
#include "gl_hemicube.h"

namespace wb {

void PatchView::setMesh(const rad::PatchMesh& mesh) {
    positions_.assign(mesh.vertices.begin(), mesh.vertices.end());
    owner_.clear();
    tris_ = rad::displayTriangles(mesh, &owner_);
    outlines_.clear();
    outlines_.reserve(mesh.patches.size());
    for (const rad::Patch& p : mesh.patches) {
        if (!p.outline.empty())
            outlines_.push_back(p.outline);
        else
            outlines_.push_back(std::vector<int>(p.corners.begin(), p.corners.begin() + p.cornerCount));
    }
}

void PatchView::draw(bool smooth) const {
    glDisable(GL_LIGHTING);
    glShadeModel(smooth ? GL_SMOOTH : GL_FLAT);
    const bool haveVertex = vertexColour_.size() == positions_.size();
    const bool havePatch = patchColour_.size() == outlines_.size();
    glBegin(GL_TRIANGLES);
    for (size_t t = 0; t < tris_.size(); ++t) {
        const int p = owner_[t];
        for (int k = 0; k < 3; ++k) {
            const int v = tris_[t][size_t(k)];
            // Flat: GL_FLAT takes the last vertex's colour, so every vertex gets the patch's.
            const glm::vec3 c = smooth && haveVertex ? vertexColour_[size_t(v)]
                                : havePatch          ? patchColour_[size_t(p)]
                                                     : glm::vec3(0.5f);
            glColor3f(c.x, c.y, c.z);
            const glm::vec3& x = positions_[size_t(v)];
            glVertex3f(x.x, x.y, x.z);
        }
    }
    glEnd();
}

void PatchView::drawFlat(const std::vector<glm::vec3>& patchColours) const {
    if (patchColours.size() != outlines_.size()) return;
    glDisable(GL_LIGHTING);
    glShadeModel(GL_FLAT);
    glBegin(GL_TRIANGLES);
    for (size_t t = 0; t < tris_.size(); ++t) {
        const glm::vec3& c = patchColours[size_t(owner_[t])];
        glColor3f(c.x, c.y, c.z);
        for (int k = 0; k < 3; ++k) {
            const glm::vec3& x = positions_[size_t(tris_[t][size_t(k)])];
            glVertex3f(x.x, x.y, x.z);
        }
    }
    glEnd();
}

void PatchView::drawOutlines(const glm::vec3& colour) const {
    glDisable(GL_LIGHTING);
    glColor3f(colour.x, colour.y, colour.z);
    glLineWidth(1.0f);
    for (const auto& loop : outlines_) {
        glBegin(GL_LINE_LOOP);
        for (int v : loop) {
            const glm::vec3& x = positions_[size_t(v)];
            glVertex3f(x.x, x.y, x.z);
        }
        glEnd();
    }
}

void PatchView::drawPatchOutline(int patch, const glm::vec3& colour, float width) const {
    if (patch < 0 || size_t(patch) >= outlines_.size()) return;
    glDisable(GL_LIGHTING);
    glColor3f(colour.x, colour.y, colour.z);
    glLineWidth(width);
    glBegin(GL_LINE_LOOP);
    for (int v : outlines_[size_t(patch)]) {
        const glm::vec3& x = positions_[size_t(v)];
        glVertex3f(x.x, x.y, x.z);
    }
    glEnd();
    glLineWidth(1.0f);
}

void PatchView::drawItems() const {
    glDisable(GL_LIGHTING);
    glDisable(GL_DITHER);
    glDisable(GL_BLEND);
    glShadeModel(GL_FLAT);
    glBegin(GL_TRIANGLES);
    for (size_t t = 0; t < tris_.size(); ++t) {
        uint8_t rgb[3];
        GlHemicube::encode(uint32_t(owner_[t]), rgb);
        glColor3ub(rgb[0], rgb[1], rgb[2]);
        for (int k = 0; k < 3; ++k) {
            const glm::vec3& x = positions_[size_t(tris_[t][size_t(k)])];
            glVertex3f(x.x, x.y, x.z);
        }
    }
    glEnd();
    glEnable(GL_DITHER);
}

void PatchView::hemicubeGeometry(std::vector<glm::vec3>& vertices,
                                 std::vector<uint32_t>& items) const {
    vertices.clear();
    items.clear();
    vertices.reserve(tris_.size() * 3);
    items.reserve(tris_.size());
    for (size_t t = 0; t < tris_.size(); ++t) {
        for (int k = 0; k < 3; ++k) vertices.push_back(positions_[size_t(tris_[t][size_t(k)])]);
        items.push_back(uint32_t(owner_[t]));
    }
}

} // namespace wb
