// Lab 08: what is drawn. Radiosity B is displayed as a renderer displays radiance:
// linear B → white balance (optional: divide by the light's colour) → exposure (automatic:
// the 90th percentile of the non-emitting patches' luminance, by area, shows at 80% of white;
// the slider overrides) → the sRGB encoding (IEC 61966-2-1) of the 8-bit framebuffer.
#include "radiosity_lab_class.h"

#include "common/gl_util.h"

#include "core/i18n.h"

#include "core/radiosity/smoothing.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace wb {

namespace {

// False colour of t in [0, 1]: black, blue, magenta, orange, yellow, white (a heat scale
// that stays readable on the grey of unselected surfaces).
glm::vec3 heat(double t) {
    t = std::clamp(t, 0.0, 1.0);
    const glm::vec3 stops[] = {{0.02f, 0.02f, 0.1f}, {0.1f, 0.2f, 0.9f},  {0.8f, 0.1f, 0.7f},
                               {1.0f, 0.5f, 0.0f},   {1.0f, 0.95f, 0.2f}, {1.0f, 1.0f, 1.0f}};
    const double x = t * 5.0;
    const int i = std::min(4, int(x));
    const float f = float(x - i);
    return stops[i] * (1.0f - f) + stops[i + 1] * f;
}

// The sRGB transfer function: linear 0..1 to the encoded value the framebuffer stores.
double srgbEncode(double x) {
    x = std::clamp(x, 0.0, 1.0);
    return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}

constexpr double kAutoPercentile = 0.90; // of the lit, non-emitting area
constexpr double kAutoWhite = 0.80;      // linear value that percentile displays at

} // namespace

// Exposure that puts the 90th percentile (by area) of the non-emitting patches' luminance at
// 80% of white: the bright walls near the light stay below clipping, as a camera's metering
// would have it; the light itself (E ≫ B of the walls) clips to white.
double RadiosityLab::autoExposure(const std::vector<glm::dvec3>& B) const {
    std::vector<std::pair<double, double>> lum; // luminance, area
    double total = 0;
    const glm::dvec3 wbal = s.whiteBalance ? 1.0 / model_->light : glm::dvec3(1.0);
    for (size_t i = 0; i < B.size(); ++i) {
        const rad::Patch& p = model_->mesh.patches[i];
        if (luminance(p.emission) > 0) continue;
        lum.emplace_back(luminance(B[i] * wbal), p.area);
        total += p.area;
    }
    if (lum.empty() || total <= 0) return 1.0;
    std::sort(lum.begin(), lum.end());
    double acc = 0, at = lum.back().first;
    for (const auto& [l, a] : lum) {
        acc += a;
        if (acc >= kAutoPercentile * total) {
            at = l;
            break;
        }
    }
    return at > 0 ? kAutoWhite / at : 1.0;
}

glm::vec3 RadiosityLab::tone(const glm::dvec3& B) const {
    const glm::dvec3 wbal = s.whiteBalance ? 1.0 / model_->light : glm::dvec3(1.0);
    const glm::dvec3 x = B * wbal * double(s.exposure);
    return glm::vec3(float(srgbEncode(x.x)), float(srgbEncode(x.y)), float(srgbEncode(x.z)));
}

void RadiosityLab::updateColours() {
    uint64_t version;
    std::vector<glm::dvec3> B;
    {
        std::lock_guard<std::mutex> lock(snapMutex_);
        version = snapshot_.version;
        if (version == coloursVersion_ && !coloursDirty_) return;
        B = snapshot_.B;
        if (!workerError_.empty()) message_ = std::move(workerError_);
        workerError_.clear();
        history_ = snapshot_.history;
        steps_ = snapshot_.steps;
        residual_ = snapshot_.residual;
        lastShooter_ = snapshot_.lastShooter;
        drawnPreview_ = snapshot_.preview;
    }
    coloursVersion_ = version;
    coloursDirty_ = false;
    if (B.size() != model_->mesh.patches.size()) return;
    autoExposure_ = autoExposure(B);
    if (s.autoExposure) s.exposure = float(autoExposure_);
    patchColour_.resize(B.size());
    for (size_t i = 0; i < B.size(); ++i)
        patchColour_[i] = tone(B[i]);
    view_.setPatchColours(patchColour_);
    if (s.smooth) {
        const std::vector<glm::dvec3> vb = rad::vertexRadiosity(model_->mesh, B);
        std::vector<glm::vec3> vc(vb.size());
        for (size_t i = 0; i < vb.size(); ++i)
            vc[i] = tone(vb[i]);
        view_.setVertexColours(vc);
    }
    overlayDirty_ = true;
}

// The selected patch: its row and item buffer by the current method.
void RadiosityLab::updateSelection() {
    if (!selectedDirty_ || !model_) return;
    selectedDirty_ = false;
    selectedRow_.clear();
    selectedItems_ = rad::ItemBuffer{};
    overlayDirty_ = true;
    const int n = int(model_->mesh.patches.size());
    if (selected_ < 0 || selected_ >= n) {
        selected_ = -1;
        return;
    }
    const rad::FormFactors& ff = *model_->ff;
    const rad::HemicubeFrame frame = rad::hemicubeFrame(model_->mesh, selected_);
    const auto t0 = std::chrono::steady_clock::now();
    try {
        if (s.method == FfMethod::GlHemicube) {
            std::string err;
            if (!glHemicube_.render(frame, ff.deltaTable().resolution,
                                    GlHemicube::kNearFraction * sceneRadius_, selectedItems_,
                                    err)) {
                message_ = err;
                selected_ = -1;
                return;
            }
            rad::accumulate(selectedItems_, ff.deltaTable(), n, selected_, selectedRow_);
            selectedSource_ = tr("GL hemicube");
        } else {
            rad::castItemBuffer(ff.bvh(), frame, ff.deltaTable().resolution, selectedItems_);
            if (s.method == FfMethod::Rays) {
                rad::RayFormFactorConfig rc;
                rc.samples = s.raySamples;
                rad::rayFormFactorRow(model_->mesh, ff.bvh(), selected_, rc, selectedRow_);
                selectedSource_ = tr("rays (hemicube picture: CPU)");
            } else {
                rad::accumulate(selectedItems_, ff.deltaTable(), n, selected_, selectedRow_);
                selectedSource_ = tr("CPU hemicube");
            }
        }
    } catch (const std::exception& e) {
        message_ = e.what();
        selected_ = -1;
        return;
    }
    selectedSeconds_ = secondsSince(t0);
    double sum = 0, mx = 0;
    for (float f : selectedRow_) {
        sum += double(f);
        mx = std::max(mx, double(f));
    }
    selectedRowSum_ = sum;
    selectedRowMax_ = mx;
}

void RadiosityLab::setupCamera(const View& view) const {
    const rad::Scene& sc = model_->scene;
    // Orbit the eye about the target: yaw about the scene's up, pitch about the camera's right.
    const glm::dvec3 up = glm::normalize(sc.up);
    glm::dvec3 d = sc.eye - sc.target;
    const glm::dmat4 yaw = glm::rotate(glm::dmat4(1.0), glm::radians(double(-view.yaw)), up);
    d = glm::dvec3(yaw * glm::dvec4(d, 0.0));
    const glm::dvec3 right = glm::normalize(glm::cross(up, d));
    const glm::dmat4 pitch = glm::rotate(glm::dmat4(1.0), glm::radians(double(-view.pitch)), right);
    d = glm::dvec3(pitch * glm::dvec4(d, 0.0));
    const glm::dvec3 eye = sc.target + d;
    const double dist = glm::length(eye - sceneCentre_);
    // The Cornell box is seen from outside with its published 40° (vertical). The classroom
    // and the floor lamp are seen from inside the room: at 40° the ceiling lamps were cut at the
    // top and the red box at the right edge once the panel narrows the view, so the view opens
    // to at least 56° vertically and 80° horizontally (a 24 mm lens's field, 1280×800 with the
    // panel: about 1.1:1).
    double fovy = 40.0;
    if (dist < sceneRadius_) {
        const double aspect = double(view.width) / double(std::max(1, view.height));
        const double fitH = 2.0 * glm::degrees(std::atan(std::tan(glm::radians(40.0)) / aspect));
        fovy = std::clamp(std::max(56.0, fitH), 56.0, 100.0);
    }
    setPerspective(view, fovy, std::max(1e-3 * sceneRadius_, (dist - sceneRadius_) * 0.5),
                   dist + 2 * sceneRadius_);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    const glm::dvec3 u2 = glm::normalize(glm::cross(d, right));
    gluLookAt(eye.x, eye.y, eye.z, sc.target.x, sc.target.y, sc.target.z, u2.x, u2.y, u2.z);
}

int RadiosityLab::pick(const View& view, int x, int y) {
    if (x < 0 || y < 0 || x >= view.width || y >= view.height) return -1;
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE); // as drawn: the front sides
    glCullFace(GL_BACK);
    view_.drawItems();
    uint8_t px[4] = {};
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(x, view.height - 1 - y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    const int32_t id = GlHemicube::decode(px);
    return id >= 0 && id < patchCount() ? id : -1;
}

void RadiosityLab::draw(const View& view) {
    ex_.poll(!view.headless);
    glClearColor(0.08f, 0.08f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (ex_.on()) { // your form factors and rays (exercise_view.cpp)
        drawRadiosityExercise(ex_, view);
        return;
    }
    if (!model_) return;
    if (view.headless) {
        // Headless: a run started by the replayed keys is waited for (busy() until done), and
        // a model changed since the last solve is solved first (unless --steps 0).
        finishRun();
        if (autoSolve_ && s.maxSteps != 0) {
            autoSolve_ = false;
            autoRun_ = true;
            startRun();
            finishRun();
            autoRun_ = false;
        }
        printSummary();
        if (pendingClick_ && (clickX_ >= view.width || clickY_ >= view.height)) {
            // As lab 07 refuses an --inspect outside its image: a click nowhere is a mistake.
            std::fprintf(stderr, "%s\n",
                         wb::trf("lab08: --click %d,%d is outside the %dx%d scene view", clickX_,
                                 clickY_, view.width, view.height)
                             .c_str());
            failed_ = true;
            pendingClick_ = false;
        }
    }
    if (view.headless) {
        stepOnMainThread(true);
        drawScene(view);
        return;
    }
    // In a window the GL method's slice of steps comes after the scene's draw calls: Mesa's
    // llvmpipe rasterizes the frame on its threads while this thread draws the next
    // hemicubes (before, glutSwapBuffers waited ~30-50 ms a frame for it); the frame shows
    // the previous slice's state, and the shell draws one more when the run ends.
    drawScene(view);
    // The first frame that shows a usable picture (unshot light < 5%): the time the student
    // waits for it (docs/bench/radiosity.md; the frame is swapped right after this).
    if (running() && shownSeconds_ < 0 && !usableBefore_ && residual_ < 0.05) {
        shownSeconds_ = secondsSince(runStart_);
        std::printf("lab08: usable picture drawn after %.2f s%s\n", shownSeconds_.load(),
                    drawnPreview_ ? " (preview)" : "");
        std::fflush(stdout);
    }
    glFlush(); // hand the frame to the rasterizer now
    // A GL run's slice ended on a picture to show (the preview became usable, or the full
    // solve overtook it): this frame is swapped at once, the next one steps on.
    if (skipSlice_)
        skipSlice_ = false;
    else
        stepOnMainThread(false, view.inputWaiting);
}

void RadiosityLab::drawScene(const View& view) {
    updateColours();
    setupCamera(view);
    if (pendingClick_) {
        pendingClick_ = false;
        const int id = pick(view, clickX_, clickY_);
        selected_ = id == selected_ ? -1 : id; // a second click on it (or the background) clears
        selectedDirty_ = true;
        glClearColor(0.08f, 0.08f, 0.1f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    }
    updateSelection();

    glEnable(GL_DEPTH_TEST);
    // Patches are one-sided (they emit and receive on the front): back sides are not drawn.
    // Besides being right, this keeps the near and far faces of thin bodies (the classroom's
    // table panels) from fighting once polygon offset pushes the faces back at grazing angles.
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    glDisable(GL_LIGHTING);
    glEnable(GL_POLYGON_OFFSET_FILL); // outlines drawn on the faces win the depth test
    glPolygonOffset(1.0f, 1.0f);
    const bool falseColour = !s.showItems && selected_ >= 0 && !selectedRow_.empty();
    if (s.showItems) {
        view_.drawItems(); // patch id + 1 as 24-bit RGB: what the GL hemicube draws
    } else if (falseColour) {
        // The form-factor row as false colour: log10 F over four decades below the row's max.
        std::vector<glm::vec3> c(selectedRow_.size());
        const double top = std::log10(std::max(selectedRowMax_, 1e-30));
        for (size_t j = 0; j < c.size(); ++j) {
            const double f = double(selectedRow_[j]);
            c[j] = f > 0 ? heat((std::log10(f) - (top - 4.0)) / 4.0) : glm::vec3(0.25f);
        }
        c[size_t(selected_)] = glm::vec3(0.2f, 1.0f, 0.3f);
        view_.drawFlat(c);
    } else {
        view_.draw(s.smooth);
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    if (s.showItems) return;
    if (s.outlines) view_.drawOutlines(glm::vec3(0.0f));
    if (selected_ >= 0) view_.drawPatchOutline(selected_, glm::vec3(0.2f, 1.0f, 0.3f), 3.0f);
    if (selected_ >= 0 && selectedItems_.resolution > 0) drawOverlay(view);
    if (falseColour) drawColourBar(view);
}

// The false colour's scale in the picture itself (so a headless PNG carries it), along the
// right edge from the bottom: 10⁻⁴·max at the bottom to max at the top, a tick per decade;
// the panel gives the numbers.
void RadiosityLab::drawColourBar(const View& view) const {
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, view.width, 0, view.height, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    const float w = 12, x0 = float(view.width) - w - 8, y0 = 8;
    const float h = std::max(40.0f, float(view.height) * 0.45f);
    glBegin(GL_QUADS);
    for (int i = 0; i < 64; ++i) {
        const glm::vec3 a = heat(i / 64.0), b = heat((i + 1) / 64.0);
        const float ya = y0 + h * float(i) / 64, yb = y0 + h * float(i + 1) / 64;
        glColor3f(a.r, a.g, a.b);
        glVertex2f(x0, ya);
        glVertex2f(x0 + w, ya);
        glColor3f(b.r, b.g, b.b);
        glVertex2f(x0 + w, yb);
        glVertex2f(x0, yb);
    }
    glEnd();
    glColor3f(0.85f, 0.85f, 0.85f);
    glBegin(GL_LINES);
    for (int i = 0; i <= 4; ++i) { // one tick per decade
        const float y = y0 + h * float(i) / 4;
        glVertex2f(x0 - 5, y);
        glVertex2f(x0, y);
    }
    glEnd();
    glEnable(GL_DEPTH_TEST);
}

void RadiosityLab::drawOverlay(const View& view) {
    // The hemicube of the selected patch, unfolded, in the upper right corner (the Cornell
    // box's camera leaves the space beside the box free there): what the patch sees, each
    // patch in its current colour.
    const int res = selectedItems_.resolution;
    if (!overlayTexture_) glGenTextures(1, &overlayTexture_);
    glBindTexture(GL_TEXTURE_2D, overlayTexture_);
    if (overlayDirty_) {
        const Image img = unfoldHemicube(selectedItems_, patchColour_, glm::vec3(0.0f));
        // Image rows are top first; GL textures start at the bottom: upload flipped.
        std::vector<uint8_t> flipped(img.data.size());
        const size_t stride = size_t(img.width) * 3;
        for (int y = 0; y < img.height; ++y)
            std::copy_n(&img.data[size_t(img.height - 1 - y) * stride], stride,
                        &flipped[size_t(y) * stride]);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, img.width, img.height, 0, GL_RGB, GL_UNSIGNED_BYTE,
                     flipped.data());
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        overlayDirty_ = false;
        overlaySize_ = 2 * res;
    }
    const int side = std::max(16, std::min(view.width, view.height) / 5);
    const int x0 = view.width - side - 5, y0 = view.height - side - 5;
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, view.width, 0, view.height, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glColor3f(0.2f, 1.0f, 0.3f);
    glBegin(GL_LINE_LOOP); // frame
    glVertex2i(x0 - 2, y0 - 2);
    glVertex2i(x0 + side + 1, y0 - 2);
    glVertex2i(x0 + side + 1, y0 + side + 1);
    glVertex2i(x0 - 2, y0 + side + 1);
    glEnd();
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0);
    glVertex2i(x0, y0);
    glTexCoord2f(1, 0);
    glVertex2i(x0 + side, y0);
    glTexCoord2f(1, 1);
    glVertex2i(x0 + side, y0 + side);
    glTexCoord2f(0, 1);
    glVertex2i(x0, y0 + side);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, 0);
    glEnable(GL_DEPTH_TEST);
}

} // namespace wb
