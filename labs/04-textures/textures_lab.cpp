#include "textures_lab.h"

#include "exercise_view.h"

#include "core/i18n.h"

#include "common/gl.h"
#include "common/gl_util.h"
#include "common/paths.h"
#include "core/i18n.h"
#include "core/mesh.h"
#include "environment.h"
#include "texture_file.h"

#include "common/panel.h"
#include "core/i18n.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

const wb::ex::LabExercises& wbExercises_lab04();

namespace wb {
namespace {

// A core mesh in float arrays for glDrawElements.
struct GlMesh {
    std::vector<float> positions, normals, texCoords;
    std::vector<float> tangents; // unit ∂p/∂s, for bump mapping
    std::vector<float> scales;   // |∂p/∂s|, |∂p/∂t|, for bump mapping (torus only)
    std::vector<GLuint> indices;
};

GlMesh toGl(const Mesh& m) {
    GlMesh g;
    for (size_t i = 0; i < m.positions.size(); ++i) {
        for (int k = 0; k < 3; ++k) {
            g.positions.push_back(float(m.positions[i][k]));
            g.normals.push_back(float(m.normals[i][k]));
            g.tangents.push_back(float(m.tangents[i][k]));
        }
        g.texCoords.push_back(float(m.texCoords[i].x));
        g.texCoords.push_back(float(m.texCoords[i].y));
    }
    g.indices.assign(m.indices.begin(), m.indices.end());
    return g;
}

// Your mesh (a student handout's stand-in for the lab's own): the tangent along ∂p/∂s of a
// surface of revolution about y, (z, 0, -x)/|..| (both meshes go round y as s grows).
GlMesh toGl(const std::optional<lab04::Mesh>& m) {
    GlMesh g;
    if (!m) return g;
    for (size_t i = 0; i < m->positions.size(); ++i) {
        const glm::dvec3 p = m->positions[i];
        const double rho = std::hypot(p.x, p.z);
        const glm::dvec3 t = rho > 0 ? glm::dvec3(p.z, 0, -p.x) / rho : glm::dvec3(1, 0, 0);
        for (int k = 0; k < 3; ++k) {
            g.positions.push_back(float(p[k]));
            g.normals.push_back(float(m->normals[i][k]));
            g.tangents.push_back(float(t[k]));
        }
        g.texCoords.push_back(float(m->texCoords[i].x));
        g.texCoords.push_back(float(m->texCoords[i].y));
    }
    g.indices.assign(m->indices.begin(), m->indices.end());
    return g;
}

// The lab's own meshes: core's, i.e. the answers of §2.4 task ④. A student handout cuts these
// bodies (labs/handout_strip.txt): there they are empty and the lab draws yours instead.
Mesh labSphere(double radius, int slices, int stacks) {
    return makeSphere(radius, slices, stacks);
}
Mesh labTorus(double R, double r, int rings, int sides) {
    return makeTorus(R, r, rings, sides);
}

// The torus p(s,t) of makeTorus: |∂p/∂s| = 2π·(distance from the y axis), |∂p/∂t| = 2π·r.
void addTorusScales(GlMesh& g, double minorRadius) {
    constexpr double kTwoPi = 6.283185307179586;
    for (size_t i = 0; i + 2 < g.positions.size(); i += 3) {
        g.scales.push_back(
            float(kTwoPi * std::hypot(double(g.positions[i]), double(g.positions[i + 2]))));
        g.scales.push_back(float(kTwoPi * minorRadius));
    }
}

void drawMesh(const GlMesh& g) {
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, g.positions.data());
    glNormalPointer(GL_FLOAT, 0, g.normals.data());
    glTexCoordPointer(2, GL_FLOAT, 0, g.texCoords.data());
    glDrawElements(GL_TRIANGLES, GLsizei(g.indices.size()), GL_UNSIGNED_INT, g.indices.data());
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_NORMAL_ARRAY);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
}

// Uploads `img` (top row first) so that t = 0 is its bottom row, as texture coordinates expect.
void upload(GLuint tex, const Image& img) {
    std::vector<uint8_t> rows(img.data.size());
    const size_t stride = size_t(img.width) * 3;
    for (int y = 0; y < img.height; ++y)
        std::copy_n(&img.data[size_t(img.height - 1 - y) * stride], stride,
                    &rows[size_t(y) * stride]);
    glBindTexture(GL_TEXTURE_2D, tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, img.width, img.height, 0, GL_RGB, GL_UNSIGNED_BYTE,
                 rows.data());
    glGenerateMipmap(GL_TEXTURE_2D);
}

class TexturesLab : public Lab {
  public:
    explicit TexturesLab(TexturesLabState* s) : s_(s ? s : &own_), ex_(wbExercises_lab04()) {}
    bool busy() const override { return ex_.busy(); }
    int pollMs() const override { return ex_.pollMs(); }
    bool poll() override { return ex_.shellPoll(); }
    std::string title() const override { return tr("Lab 04 - textures"); }
    std::vector<KeyHelp> keys() const override {
        return {{"0", tr("overview: mirror object, textured sphere and torus")},
                {"1", tr("flat textured object (wrap and filter show here)")},
                {"2", tr("hand-made sphere")},
                {"3", tr("hand-made torus")},
                {"4", tr("mirror object: GL_SPHERE_MAP texgen")},
                {"w", tr("GL_REPEAT / GL_CLAMP")},
                {"f", tr("filter: nearest / linear / mipmaps")},
                {"t", tr("texture: bricks / uv grid")},
                {"5", tr("bump-mapped torus (GLSL, section 1.5.2)")},
                {"k", tr("bump mapping on/off (smooth torus, same shader)")},
                {"o", tr("mirror object: sphere / torus")},
                {"b", tr("background room on/off")},
                {tr("Left/Right/Up/Down"), tr("spin the object")},
                ex_.keyHelp()};
    }
    std::vector<OptionHelp> options() const override {
        return {{"texture", tr("FILE"), tr("image for the flat object instead of bricks.png")}};
    }
    bool setOption(const std::string& name, const std::string& value, std::string& error) override {
        if (name != "texture") return Lab::setOption(name, value, error);
        s_->textureFiles[0] = value; // a bad file is reported at init and replaced by a checker
        return true;
    }

    void init() override {
        glGenTextures(3, textures_);
        glGenTextures(1, &sphereMapTex_);
        glGenTextures(1, &latLongTex_);
        haveMap_ = false; // a new context (a second headless render) has no sphere map yet
        s_->message.clear();
        for (int i = 0; i < 3; ++i) {
            // A path given on the command line is used as typed; the defaults live under the asset
            // root.
            const std::string& f = s_->textureFiles[i];
            const std::string path = f.rfind("assets/", 0) == 0 ? assetPath(f) : f;
            Image img;
            std::string msg;
            if (!loadTextureImage(path, img, msg)) {
                std::fprintf(stderr, tr("lab04: %s\n"), msg.c_str());
                s_->message += msg + "\n";
            }
            upload(textures_[i], img);
        }
        upload(latLongTex_, makeLatLongImage(512, 256));
        sphere_ = toGl(labSphere(1.2, 48, 24));
        torus_ = toGl(labTorus(kBumpTorusMajor, kBumpTorusMinor, 64, 32));
        addTorusScales(torus_, kBumpTorusMinor);
        std::string err;
        bumpProgram_ = loadProgram("shaders/bump.vert", "shaders/bump.frag", err);
        if (!bumpProgram_) {
            std::fprintf(stderr, tr("lab04: %s\n"), err.c_str());
            s_->message += err + tr(" (scene 5 falls back to the fixed-function torus)") + "\n";
        }
        room_ = toGl(labSphere(30.0, 64, 32));
        ownMeshes_ = !sphere_.indices.empty();
    }

    void draw(const View& view) override {
        ex_.poll(!view.headless);
        if (!ownMeshes_) { // a handout: your meshes wherever the lab used its own, as they are now
            sphere_ = toGl(exerciseMesh(ex_, false, 1.2, 0, 48, 24));
            torus_ = toGl(exerciseMesh(ex_, true, kBumpTorusMajor, kBumpTorusMinor, 64, 32));
            addTorusScales(torus_, kBumpTorusMinor);
            room_ = toGl(exerciseMesh(ex_, false, 30.0, 0, 64, 32));
        }
        glViewport(0, 0, view.width, view.height);
        glClearColor(0.12f, 0.12f, 0.14f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        setPerspective(view, 45.0, 0.1, 100.0);
        glLoadIdentity();
        glTranslated(0.0, 0.0, -5.0);
        applyOrbit(view);
        glEnable(GL_DEPTH_TEST);
        glEnable(GL_TEXTURE_2D);
        glEnable(GL_NORMALIZE);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
        if (s_->background &&
            (s_->scene == TextureScene::Mirror || s_->scene == TextureScene::Overview))
            drawRoom();
        if (s_->scene == TextureScene::Overview) {
            drawOverview(view);
            glDisable(GL_TEXTURE_2D);
            return;
        }

        glPushMatrix();
        if (s_->scene != TextureScene::Flat)
            glRotated(25.0, 1.0, 0.0, 0.0); // show a pole / the hole
        glRotated(s_->spinX, 1.0, 0.0, 0.0);
        glRotated(s_->spinY, 0.0, 1.0, 0.0);
        switch (s_->scene) {
        case TextureScene::Flat:
            drawFlat();
            break;
        case TextureScene::Sphere:
            drawLit(sphere_);
            break;
        case TextureScene::Torus:
            drawLit(torus_);
            break;
        case TextureScene::Mirror:
            drawMirror(view);
            break;
        case TextureScene::Bump:
            drawBump();
            break;
        case TextureScene::Overview: // drawn above
            break;
        }
        glPopMatrix();
        glDisable(GL_TEXTURE_2D);
    }

    bool key(int k) override {
        if (ex_.key(k)) return true;
        switch (k) {
        case '0':
            s_->scene = TextureScene::Overview;
            return true;
        case '1':
            s_->scene = TextureScene::Flat, s_->texture = 0;
            return true;
        case '2':
            s_->scene = TextureScene::Sphere, s_->texture = 1;
            return true;
        case '3':
            s_->scene = TextureScene::Torus, s_->texture = 1;
            return true;
        case '4':
            s_->scene = TextureScene::Mirror;
            return true;
        case '5':
            s_->scene = TextureScene::Bump;
            return true;
        case 'k':
            s_->bump = !s_->bump;
            return true;
        case 'w':
            s_->repeat = !s_->repeat;
            return true;
        case 'f':
            s_->filter = TextureFilter((int(s_->filter) + 1) % 3);
            return true;
        case 't':
            s_->texture = 1 - s_->texture;
            return true;
        case 'o':
            s_->mirrorTorus = !s_->mirrorTorus;
            return true;
        case 'b':
            s_->background = !s_->background;
            return true;
        case kKeyLeft:
            s_->spinY -= 10.0;
            return true;
        case kKeyRight:
            s_->spinY += 10.0;
            return true;
        case kKeyUp:
            s_->spinX -= 10.0;
            return true;
        case kKeyDown:
            s_->spinX += 10.0;
            return true;
        default:
            return false;
        }
    }

    void gui() override {
        ex_.gui();
        if (!ownMeshes_ && (sphere_.indices.empty() || torus_.indices.empty()))
            ImGui::TextWrapped(tr("This copy draws only your sphere and torus (04.sphere, "
                                  "04.torus in exercises.cpp): the scene stays empty of them "
                                  "until they are done."));
        int scene = int(s_->scene);
        ImGui::Text(tr("Scene (0-5)"));
        ImGui::RadioButton(tr("all"), &scene, 0);
        sameLineIfFits(tr("flat"));
        ImGui::RadioButton(tr("flat"), &scene, 1);
        sameLineIfFits(tr("sphere"));
        ImGui::RadioButton(tr("sphere"), &scene, 2);
        sameLineIfFits(tr("torus"));
        ImGui::RadioButton(tr("torus"), &scene, 3);
        sameLineIfFits(tr("mirror"));
        ImGui::RadioButton(tr("mirror"), &scene, 4);
        sameLineIfFits(tr("bump"));
        ImGui::RadioButton(tr("bump"), &scene, 5);
        s_->scene = TextureScene(scene);
        ImGui::Checkbox(tr("GL_REPEAT (w; off = GL_CLAMP)"), &s_->repeat);
        int filter = int(s_->filter);
        // Wide enough for its longest value whatever the label's language leaves it.
        ImGui::SetNextItemWidth(
            std::max(ImGui::CalcItemWidth(), ImGui::CalcTextSize("GL_LINEAR_MIPMAP_LINEAR").x +
                                                 ImGui::GetFrameHeight() +
                                                 2.0f * ImGui::GetStyle().FramePadding.x));
        ImGui::Combo(tr("filter (f)"), &filter, "GL_NEAREST\0GL_LINEAR\0GL_LINEAR_MIPMAP_LINEAR\0");
        s_->filter = TextureFilter(filter);
        // A Combo takes its items as one string of NUL-separated names: translated one by one.
        const char* textures[] = {tr("bricks"), tr("uv grid")};
        ImGui::Combo(tr("texture (t)"), &s_->texture, textures, 2);
        if (s_->scene == TextureScene::Overview)
            ImGui::TextWrapped("%s", s_->texture == 0
                                         ? wb::tr("overview: t swaps the textures of the sphere "
                                                  "(uv grid) and the torus (bricks)")
                                         : wb::tr("overview: t swaps the textures of the sphere "
                                                  "(bricks) and the torus (uv grid)"));
        ImGui::Checkbox(tr("mirror torus (o; off = sphere)"), &s_->mirrorTorus);
        ImGui::Checkbox(tr("background room (b)"), &s_->background);
        ImGui::Checkbox(tr("bump mapping (k)"), &s_->bump);
        float depth = float(s_->bumpDepth);
        if (ImGui::SliderFloat(tr("bump depth"), &depth, 0.0f, 0.15f)) s_->bumpDepth = depth;
        float spin[2] = {float(s_->spinX), float(s_->spinY)};
        if (ImGui::DragFloat2(tr("spin (arrows)"), spin)) s_->spinX = spin[0], s_->spinY = spin[1];
        ImGui::TextWrapped(tr("sphere map rebuilt %d times (once per new view)"),
                           s_->sphereMapBuilds);
        ImGui::TextWrapped(tr("Sphere and torus: seam at s = 0/1 has twin vertices; the sphere's "
                              "pole vertices take s at their slice's middle."));
        if (!s_->message.empty())
            ImGui::TextColored(ImVec4(1, 0.3f, 0.3f, 1), "%s", s_->message.c_str());
    }

  private:
    void applyTextureParameters() {
        const GLint wrap = s_->repeat ? GL_REPEAT : GL_CLAMP;
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap);
        const GLint minF = s_->filter == TextureFilter::Nearest  ? GL_NEAREST
                           : s_->filter == TextureFilter::Linear ? GL_LINEAR
                                                                 : GL_LINEAR_MIPMAP_LINEAR;
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, minF);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER,
                        s_->filter == TextureFilter::Nearest ? GL_NEAREST : GL_LINEAR);
    }

    void setLight() {
        const GLfloat pos[] = {3.0f, 4.0f, 5.0f, 0.0f}; // directional, fixed in the world
        const GLfloat white[] = {1, 1, 1, 1}, ambient[] = {0.25f, 0.25f, 0.25f, 1};
        glLightfv(GL_LIGHT0, GL_POSITION, pos);
        glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
        glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
        glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, white);
        glEnable(GL_LIGHTING);
        glEnable(GL_LIGHT0);
    }

    // A floor-like quad tilted away from the viewer; texture coordinates run from -1 to 3
    // so GL_REPEAT shows 4×4 tiles and GL_CLAMP one tile with smeared edges, and the far
    // end shows what each filter does with many texels per pixel.
    void drawFlat() {
        glBindTexture(GL_TEXTURE_2D, textures_[s_->texture]);
        applyTextureParameters();
        glDisable(GL_LIGHTING);
        glColor3f(1, 1, 1);
        glPushMatrix();
        glRotated(-65.0, 1.0, 0.0, 0.0);
        glBegin(GL_QUADS);
        glNormal3f(0, 0, 1);
        glTexCoord2f(-1, -1);
        glVertex3f(-2.5f, -2.5f, 0);
        glTexCoord2f(3, -1);
        glVertex3f(2.5f, -2.5f, 0);
        glTexCoord2f(3, 3);
        glVertex3f(2.5f, 2.5f, 0);
        glTexCoord2f(-1, 3);
        glVertex3f(-2.5f, 2.5f, 0);
        glEnd();
        glPopMatrix();
    }

    // The first frame: the sphere-mapped mirror object in the middle of the room, the
    // textured sphere (uv grid) on its left and the torus (bricks) on its right, each
    // spun by the arrows about its own centre. The mirror reflects the room only: a
    // sphere map holds the environment at infinity, not the neighbouring bodies.
    void drawOverview(const View& view) {
        auto place = [&](double x, double y, double scale, double tilt) {
            glPushMatrix();
            glTranslated(x, y, 0.0);
            glScaled(scale, scale, scale);
            glRotated(tilt, 1.0, 0.0, 0.0);
            glRotated(s_->spinX, 1.0, 0.0, 0.0);
            glRotated(s_->spinY, 0.0, 1.0, 0.0);
        };
        place(0.0, 0.25, 0.8, 0.0);
        drawMirror(view);
        glPopMatrix();
        place(-1.8, -0.6, 0.48, 25.0);
        // `t` swaps the two bodies' textures here (at start: the uv grid on the sphere, the
        // bricks on the torus), so the key changes what the first view shows.
        drawLit(sphere_, 1 - s_->texture);
        glPopMatrix();
        place(1.8, -0.6, 0.42, 40.0);
        drawLit(torus_, s_->texture);
        glPopMatrix();
    }

    void drawLit(const GlMesh& mesh) { drawLit(mesh, s_->texture); }
    void drawLit(const GlMesh& mesh, int texture) {
        glBindTexture(GL_TEXTURE_2D, textures_[texture]);
        applyTextureParameters();
        setLight();
        // Your sphere / torus (e), the reference's as a ghost wireframe; else the lab's.
        const bool mine = (&mesh == &sphere_ && drawExerciseMesh(ex_, false, 1.2, 0, 48, 24)) ||
                          (&mesh == &torus_ &&
                           drawExerciseMesh(ex_, true, kBumpTorusMajor, kBumpTorusMinor, 64, 32));
        if (!mine) drawMesh(mesh);
        glDisable(GL_LIGHTING);
    }

    // The room at infinity on a big inside-out sphere with the latitude-longitude map.
    void drawRoom() {
        glBindTexture(GL_TEXTURE_2D, latLongTex_);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glDisable(GL_LIGHTING);
        glColor3f(1, 1, 1);
        glDepthMask(GL_FALSE);
        drawMesh(room_);
        glDepthMask(GL_TRUE);
    }

    // GL_SPHERE_MAP texgen (section 1.5.3). The map is the environment seen from the
    // object's centre in the current eye frame, so it is rebuilt when the viewer orbits:
    // the reflection then moves with the viewer as a real mirror's would.
    void drawMirror(const View& view) {
        if (!haveMap_ || view.yaw != mapYaw_ || view.pitch != mapPitch_) {
            glm::dmat4 r(1.0);
            r = glm::rotate(r, glm::radians(double(view.pitch)), glm::dvec3(1, 0, 0));
            r = glm::rotate(r, glm::radians(double(view.yaw)), glm::dvec3(0, 1, 0));
            upload(sphereMapTex_, makeSphereMapImage(glm::dmat3(r), 256));
            haveMap_ = true;
            mapYaw_ = view.yaw;
            mapPitch_ = view.pitch;
            ++s_->sphereMapBuilds;
        }
        glBindTexture(GL_TEXTURE_2D, sphereMapTex_);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
        glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
        glEnable(GL_TEXTURE_GEN_S);
        glEnable(GL_TEXTURE_GEN_T);
        glDisable(GL_LIGHTING); // a perfect mirror: all its colour is the reflection
        glColor3f(1, 1, 1);
        const GlMesh& mirror = s_->mirrorTorus ? torus_ : sphere_;
        if (exerciseSphereMapReady(ex_)) { // your (s, t) per vertex instead of GL's texgen (e)
            glDisable(GL_TEXTURE_GEN_S);
            glDisable(GL_TEXTURE_GEN_T);
            drawWithExerciseSphereMap(ex_, mirror.positions.data(), mirror.normals.data(),
                                      mirror.positions.size() / 3, mirror.indices.data(),
                                      mirror.indices.size());
        } else {
            drawMesh(mirror);
        }
        glDisable(GL_TEXTURE_GEN_S);
        glDisable(GL_TEXTURE_GEN_T);
    }

    // Blinn bump mapping (section 1.5.2) in shaders/bump.*: four white lights and a weak
    // ambient as in fig. 5.20; the height map tiles 10× around the ring, 3× around the tube.
    void drawBump() {

        const GLfloat white[] = {0.45f, 0.45f, 0.45f, 1}, black[] = {0, 0, 0, 1};
        const GLfloat weak[] = {0.12f, 0.12f, 0.12f, 1};
        GLdouble mv[16], pr[16];
        glGetDoublev(GL_MODELVIEW_MATRIX, mv);
        glGetDoublev(GL_PROJECTION_MATRIX, pr);
        s_->bumpModelview = glm::make_mat4(mv);
        s_->bumpProjection = glm::make_mat4(pr);
        glMatrixMode(GL_MODELVIEW);
        glPushMatrix(); // the lights are fixed in eye space, not spun with the torus
        glLoadIdentity();
        for (int i = 0; i < 4; ++i) {
            const GLenum l = GLenum(GL_LIGHT0 + i);
            const GLfloat pos[4] = {float(kBumpLights[i][0]), float(kBumpLights[i][1]),
                                    float(kBumpLights[i][2]), 1.0f};
            glLightfv(l, GL_POSITION, pos);
            glLightfv(l, GL_DIFFUSE, white);
            glLightfv(l, GL_SPECULAR, white);
            glLightfv(l, GL_AMBIENT, black);
            glEnable(l);
        }
        glPopMatrix();
        glLightModelfv(GL_LIGHT_MODEL_AMBIENT, weak);
        const GLfloat diffuse[] = {0.85f, 0.65f, 0.35f, 1}, specular[] = {0.6f, 0.6f, 0.6f, 1};
        glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, diffuse);
        glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
        glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 40.0f);
        glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, black);
        if (!bumpProgram_) { // the shader did not build: the smooth torus, fixed function
            glEnable(GL_LIGHTING);
            glDisable(GL_TEXTURE_2D);
            drawMesh(torus_);
        } else {
            glBindTexture(GL_TEXTURE_2D, textures_[2]);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
            GLint w = 1, h = 1;
            glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
            glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &h);
            glUseProgram(bumpProgram_);
            glUniform1i(glGetUniformLocation(bumpProgram_, "heightMap"), 0);
            glUniform2f(glGetUniformLocation(bumpProgram_, "repeats"), float(kBumpRepeatS),
                        float(kBumpRepeatT));
            glUniform2f(glGetUniformLocation(bumpProgram_, "texelSize"), 1.0f / float(w),
                        1.0f / float(h));
            glUniform1f(glGetUniformLocation(bumpProgram_, "depth"),
                        s_->bump ? float(s_->bumpDepth) : 0.0f);
            glClientActiveTexture(GL_TEXTURE1);
            glEnableClientState(GL_TEXTURE_COORD_ARRAY);
            glTexCoordPointer(3, GL_FLOAT, 0, torus_.tangents.data());
            glClientActiveTexture(GL_TEXTURE2);
            glEnableClientState(GL_TEXTURE_COORD_ARRAY);
            glTexCoordPointer(2, GL_FLOAT, 0, torus_.scales.data());
            glClientActiveTexture(GL_TEXTURE0);
            drawMesh(torus_);
            glClientActiveTexture(GL_TEXTURE2);
            glDisableClientState(GL_TEXTURE_COORD_ARRAY);
            glClientActiveTexture(GL_TEXTURE1);
            glDisableClientState(GL_TEXTURE_COORD_ARRAY);
            glClientActiveTexture(GL_TEXTURE0);
            glUseProgram(0);
        }
        for (int i = 0; i < 4; ++i)
            glDisable(GLenum(GL_LIGHT0 + i));
        glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, black);
        glDisable(GL_LIGHTING);
    }

    TexturesLabState own_;
    TexturesLabState* s_;
    ex::ExerciseMode ex_; // e: your meshes and sphere map (exercises.cpp), the reference as a ghost
    GLuint textures_[3] = {0, 0, 0};
    GLuint bumpProgram_ = 0;
    GLuint sphereMapTex_ = 0, latLongTex_ = 0;
    bool haveMap_ = false;
    float mapYaw_ = 0, mapPitch_ = 0;
    GlMesh sphere_, torus_, room_;
    bool ownMeshes_ = true; // false in a student handout (no answers): yours stand in
};

} // namespace

std::unique_ptr<Lab> makeTexturesLab() {
    return std::make_unique<TexturesLab>(nullptr);
}

std::unique_ptr<Lab> makeTexturesLab(TexturesLabState* observe) {
    return std::make_unique<TexturesLab>(observe);
}

} // namespace wb
