// Lab 08: options, keys, the model (scene → patches → form factors → solver) and solving.
// Drawing is in radiosity_display.cpp, the panel in radiosity_panel.cpp.
#include "radiosity_lab_class.h"

#include "core/i18n.h"
#include "core/radiosity/point_rays.h"
#include "core/radiosity/smoothing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace wb {

double secondsSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double luminance(const glm::dvec3& c) {
    return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

int hemicubeFor(const RadiosityState& s) {
    if (s.hemicubeRes > 0) return s.hemicubeRes;
    // The light's groups and every receiver within 2 group diagonals are shot member by
    // member (exact near field, point_rays.h), so a row's pixels only carry what lies farther
    // away. With the groups' light fitted as a plane and the 1e-4 stop, the Cornell box's worst
    // surface against Cycles at 128² is 0.97% (0.99% at 512²): docs/bench/radiosity.md, "Lab 08
    // defaults". 128² for both: 64² and 96² alias visibly (dark and reddish columns of patches
    // on the short block's front face, lit by the walls at a grazing angle). The GL row costs
    // 16× fewer pixels than at 512².
    return 128;
}

std::vector<KeyHelp> RadiosityLab::keys() const {
    return {{"1", tr("form factors by rays")},
            {"2", tr("form factors by CPU hemicube")},
            {"3", tr("form factors by GL hemicube")},
            {"s", tr("smooth / flat")},
            {"p", tr("patch outlines")},
            {tr("space"), tr("one progressive step")},
            {"r", tr("run to convergence (any key stops)")},
            {"a", tr("adaptive subdivision")},
            {"[", tr("smaller patches")},
            {"]", tr("larger patches")},
            {"n", tr("next scene")},
            {tr("click"), tr("a patch: its F row and hemicube")},
            ex_.keyHelp()};
}

std::vector<OptionHelp> RadiosityLab::options() const {
    return {{"scene", tr("NAME"), tr("cornell, classroom or floorlamp")},
            {"patch-size", "M", tr("longest patch edge in metres")},
            {"method", "rays|cpu|gl", tr("form-factor method")},
            {"solver", "progressive|jacobi|gauss-seidel", tr("how B = E + RFB is solved")},
            {"hemicube", "N", tr("hemicube resolution (even, 8..1024)")},
            {"rays", "K", tr("rays per patch pair (1..256)")},
            {"threads", "N", tr("form-factor threads (0 = all cores)")},
            {"click", "X,Y", tr("click the scene at pixel (X, Y) as the mouse would")},
            {"steps", "N", wb::tr("headless: solve at most N steps (0: the unsolved scene)")},
            {"budget", "S", wb::tr("headless: seconds of work before drawing what there is (60)")},
            {"shooting-patch", "M",
             wb::tr("edge of the shooting patches, metres (0: every patch shoots)")},
            {"exposure", "X", wb::tr("display scale of B (default: automatic)")},
            {"preview", "on|off",
             wb::tr("first solve at coarse shooting patches and show it (default: on in a "
                    "window, off headless)")},
            {"white-balance", "on|off", wb::tr("divide by the light's colour (default on)")}};
}

bool RadiosityLab::setOption(const std::string& name, const std::string& value,
                             std::string& error) {
    auto number = [&](double lo, double hi, double& out) {
        char* end = nullptr;
        const double v = std::strtod(value.c_str(), &end);
        if (value.empty() || *end || !std::isfinite(v) || v < lo || v > hi) {
            error =
                trf("expected a number in %g..%g, got '%s'", double(lo), double(hi), value.c_str());
            return false;
        }
        out = v;
        return true;
    };
    double v = 0;
    if (name == "scene") {
        const auto names = rad::sceneNames();
        if (std::find(names.begin(), names.end(), value) == names.end()) {
            error = trf("unknown scene '%s' (cornell, classroom, floorlamp)", value.c_str());
            return false;
        }
        s.sceneName = value;
        return true;
    }
    if (name == "patch-size") {
        // The patch count it gives is checked with the scene (meshChecked), as for [ ] and a.
        if (!number(1e-3, 100.0, v)) return false;
        patchSizeOption_ = v;
        return true;
    }
    if (name == "method") {
        if (value == "rays")
            s.method = FfMethod::Rays;
        else if (value == "cpu")
            s.method = FfMethod::CpuHemicube;
        else if (value == "gl")
            s.method = FfMethod::GlHemicube;
        else {
            error = trf("expected rays, cpu or gl, got '%s'", value.c_str());
            return false;
        }
        return true;
    }
    if (name == "solver") {
        if (value == "progressive")
            s.solver = 0;
        else if (value == "jacobi")
            s.solver = 1;
        else if (value == "gauss-seidel")
            s.solver = 2;
        else {
            error = trf("expected progressive, jacobi or gauss-seidel, got '%s'", value.c_str());
            return false;
        }
        return true;
    }
    if (name == "hemicube") {
        if (!number(8, 1024, v) || int(v) % 2 != 0 || v != std::floor(v)) {
            error = trf("expected an even integer 8..1024, got '%s'", value.c_str());
            return false;
        }
        s.hemicubeRes = int(v);
        return true;
    }
    if (name == "rays") {
        if (!number(1, 256, v) || v != std::floor(v)) {
            error = trf("expected an integer 1..256, got '%s'", value.c_str());
            return false;
        }
        s.raySamples = int(v);
        return true;
    }
    if (name == "threads") {
        if (!number(0, 1024, v) || v != std::floor(v)) {
            error = trf("expected an integer 0..1024, got '%s'", value.c_str());
            return false;
        }
        // More threads than the hardware runs only cost memory (TBB's stacks, per-thread
        // scratch rows): cap, and say so.
        const int hw = std::max(1, int(std::thread::hardware_concurrency()));
        s.threads = int(v);
        if (s.threads > hw) {
            std::fprintf(
                stderr, "%s\n",
                wb::trf("lab08: --threads %d: this machine runs %d threads at once; using %d",
                        s.threads, hw, hw)
                    .c_str());
            s.threads = hw;
        }
        return true;
    }
    if (name == "click") {
        int x = 0, y = 0;
        char tail = 0;
        if (std::sscanf(value.c_str(), "%d,%d%c", &x, &y, &tail) != 2 || x < 0 || y < 0) {
            error = trf("expected X,Y (a pixel of the scene view), got '%s'", value.c_str());
            return false;
        }
        pendingClick_ = true;
        clickX_ = x;
        clickY_ = y;
        return true;
    }
    if (name == "steps") {
        if (!number(0, 1e9, v) || v != std::floor(v)) {
            error = wb::trf("expected an integer 0..1000000000, got '%s'", value.c_str());
            return false;
        }
        s.maxSteps = int(v);
        return true;
    }
    if (name == "budget") {
        if (!number(0.0, 86400.0, v)) {
            error = wb::trf("expected seconds 0..86400, got '%s'", value.c_str());
            return false;
        }
        s.budget = v;
        return true;
    }
    if (name == "shooting-patch") {
        if (!number(0.0, 100.0, v)) return false;
        shooterOption_ = v;
        return true;
    }
    if (name == "exposure") {
        if (!number(1e-6, 1e6, v)) return false;
        s.exposure = float(v);
        s.autoExposure = false;
        return true;
    }
    if (name == "preview") {
        if (value != "on" && value != "off") {
            error = wb::trf("expected on or off, got '%s'", value.c_str());
            return false;
        }
        previewOption_ = value == "on";
        return true;
    }
    if (name == "white-balance") {
        if (value != "on" && value != "off") {
            error = wb::trf("expected on or off, got '%s'", value.c_str());
            return false;
        }
        s.whiteBalance = value == "on";
        return true;
    }
    error = trf("unknown option --%s", name.c_str());
    return false;
}

void RadiosityLab::init() {
    labStart_ = std::chrono::steady_clock::now();
    if (!loadScene(s.sceneName, patchSizeOption_ > 0 ? patchSizeOption_ : -1.0)) {
        // A patch size the scene cannot take: headless fails (exit 1, no PNG); a window says
        // why in the panel and opens the scene at its default size instead.
        failed_ = true;
#if !defined(WB_HEADLESS)
        const std::string why = message_;
        if (loadScene(s.sceneName, -1.0)) message_ = why;
#endif
    }
}

bool RadiosityLab::key(int k) {
    if (ex_.key(k)) return true;
#if defined(WB_HEADLESS)
    // Headless, keys are a script (--keys "r s"): a run finishes before the next key.
    finishRun();
    // Past the budget, keys that cost work are skipped (the picture shows what there is).
    if (overBudget() && std::string("123 ra[]n").find(char(k)) != std::string::npos) {
        budgetHit_ = true;
        return true;
    }
#else
    // Any key stops a run in progress; r and space do nothing else then.
    if (running()) {
        stopRun();
        if (k == 'r' || k == ' ') return true;
    }
#endif
    switch (k) {
    case '1':
    case '2':
    case '3':
        setMethod(FfMethod(k - '1'));
        return true;
    case 's':
        s.smooth = !s.smooth;
        coloursDirty_ = true;
        return true;
    case 'p':
        s.outlines = !s.outlines;
        return true;
    case ' ':
        autoSolve_ = false; // the script steps by hand
        stepOnce();
        return true;
    case 'r':
        autoSolve_ = false;
        startRun();
        return true;
    case 'a':
        refine();
        return true;
    case '[':
        remesh(s.patchSize / std::sqrt(2.0));
        return true;
    case ']':
        remesh(s.patchSize * std::sqrt(2.0));
        return true;
    case 'n': {
        const auto names = rad::sceneNames();
        auto it = std::find(names.begin(), names.end(), s.sceneName);
        const size_t i = it == names.end() ? 0 : size_t(it - names.begin() + 1) % names.size();
        loadScene(names[i], -1.0);
        return true;
    }
    default:
        return false;
    }
}

// 1. Scene, mesh, form factors, solver.
bool RadiosityLab::loadScene(const std::string& name, double patchSize) {
    stopRun();
    try {
        rad::Scene scene = rad::sceneByName(name);
        // Meshes the scene twice to size it: once here (it was made twice more for the groups).
        const double defaultEdge = defaultPatchSize(scene);
        if (patchSize <= 0) patchSize = defaultEdge;
        rad::PatchMesh mesh;
        // Shooting groups of ~4×4 default patches (the Cornell box: 0.10 m, 252 groups, the
        // same for every method: kShooterPatches), fixed per scene: [ ] and a refine the
        // receivers, the shooters stay (none when the patches are as large). 11×11 groups (0.31 m)
        // converged fastest but put the block faces 10-96% off the Cycles reference before the near
        // field (docs/bench/radiosity.md).
        defaultEdge_ = defaultEdge;
        s.shooterEdge = shooterOption_ >= 0 ? shooterOption_ : kShooterPatches * defaultEdge_;
        if (!meshChecked(scene, patchSize, mesh)) return false;
        auto m = std::make_unique<Model>();
        m->scene = std::move(scene);
        m->mesh = std::move(mesh);
        s.sceneName = name;
        s.patchSize = patchSize;
        runSeconds_ = 0; // "last run" belonged to the previous scene
        install(std::move(m));
        return true;
    } catch (const std::exception& e) {
        message_ = e.what();
        std::fprintf(stderr, "lab08: scene %s: %s\n", name.c_str(), e.what());
        return false;
    }
}

double RadiosityLab::defaultPatchSize(const rad::Scene& scene) {
    // Sized for ~kDefaultPatches patches by the mesh itself, not by a formula: first e₀ =
    // √(A / N) (a grid cell of edge e has area <= e²), then one correction by the count the
    // mesher makes of it, e₁ = e₀·√(count / N) (the grid rounds each surface up, and dropping
    // hidden patches or merging surfaces changes the count: the Cornell box gets 3,692 patches
    // at 0.0286 m with today's mesher).
    double area = 0;
    for (const rad::Surface& sf : scene.surfaces) {
        glm::dvec3 nrm(0.0);
        for (size_t i = 0; i < sf.vertices.size(); ++i)
            nrm += glm::cross(sf.vertices[i], sf.vertices[(i + 1) % sf.vertices.size()]);
        area += 0.5 * glm::length(nrm);
    }
    double e = std::sqrt(area / double(kDefaultPatches));
    if (!std::isfinite(e) || e <= 0) return 0.1;
    for (int pass = 0; pass < 2; ++pass) {
        const size_t count = rad::meshScene(scene, rad::MeshConfig{e, 0.0}).patches.size();
        if (count == 0) break;
        e *= std::sqrt(double(count) / double(kDefaultPatches));
    }
    return e;
}

// The one check every way of setting the patch size goes through (--patch-size, [ ], the
// slider; a bounds the same count in refine()): the patch count is estimated from the surface
// areas BEFORE meshing (a cell of edge e covers at most e², so A/e² is a lower bound: 2.85 M
// patches are refused without being made), then the mesh's own count is checked.
bool RadiosityLab::meshChecked(const rad::Scene& scene, double patchSize, rad::PatchMesh& out) {
    double area = 0;
    for (const rad::Surface& sf : scene.surfaces) {
        glm::dvec3 nrm(0.0);
        for (size_t i = 0; i < sf.vertices.size(); ++i)
            nrm += glm::cross(sf.vertices[i], sf.vertices[(i + 1) % sf.vertices.size()]);
        area += 0.5 * glm::length(nrm);
    }
    auto refuse = [&](double count) {
        message_ = wb::trf("patch size %.4g m would give %s%.0f patches; the lab stops at %d",
                           patchSize, count < 0 ? "" : "at least ", std::fabs(count), kMaxPatches);
        std::fprintf(stderr, "lab08: %s\n", message_.c_str());
        return false;
    };
    const double estimate = area / (patchSize * patchSize);
    if (!(patchSize > 0) || !std::isfinite(estimate) || estimate > double(kMaxPatches))
        return refuse(estimate);
    rad::MeshConfig mc{patchSize, s.shooterEdge > patchSize * 1.5 ? s.shooterEdge : 0.0};
    out = rad::meshScene(scene, mc);
    if (out.patches.size() > size_t(kMaxPatches)) return refuse(-double(out.patches.size()));
    return true;
}

void RadiosityLab::remesh(double patchSize) {
    if (!model_) return;
    stopRun();
    patchSize = std::clamp(patchSize, 1e-3, 100.0);
    try {
        rad::PatchMesh mesh;
        if (!meshChecked(model_->scene, patchSize, mesh)) return;
        auto m = std::make_unique<Model>();
        m->scene = model_->scene;
        m->mesh = std::move(mesh);
        s.patchSize = patchSize;
        install(std::move(m));
    } catch (const std::exception& e) {
        message_ = e.what();
    }
}

void RadiosityLab::refine() {
    if (!model_) return;
    stopRun();
    // Split by the converged picture (a split driven by a half-shot solution follows the
    // shooting order, not the light).
#if defined(WB_HEADLESS)
    if (autoSolve_) {
        startRun();
        finishRun();
    }
    // Out of budget: keep the solved mesh (a finer one would be drawn unsolved).
    if (overBudget()) {
        budgetHit_ = true;
        return;
    }
#endif
    // core's threshold is relative to the brightest non-emitting patch (the light's B would
    // make any fraction of it split nothing).
    const std::vector<glm::dvec3> B = model_->solver->displayRadiosity();
    auto m = std::make_unique<Model>();
    m->scene = model_->scene;
    m->mesh = model_->mesh;
    rad::RefineConfig rc;
    rc.maxPatches = size_t(kMaxPatches); // the same cap as every other patch-size change
    int split = 0;
    try {
        split = rad::refineAdaptive(m->mesh, B, rc);
    } catch (const std::exception& e) {
        message_ = e.what();
        return;
    }
    refineNote_ = trf("%d patches split", int(split));
    if (m->mesh.patches.size() >= size_t(kMaxPatches))
        refineNote_ += wb::trf(" (stopped at the cap of %d patches)", kMaxPatches);
    if (split == 0) return;
    install(std::move(m)); // solves the finer mesh again (requestSolve)
}

void RadiosityLab::setMethod(FfMethod m) {
    if (s.method == m || !model_) {
        s.method = m;
        return;
    }
    stopRun();
    s.method = m;
    // Every method shoots from the same groups (kShooterPatches): the mesh stays.
    rebuildSolver();
}

void RadiosityLab::install(std::unique_ptr<Model> m) {
    stopRun();
    model_ = std::move(m);
    message_.clear();
    view_.setMesh(model_->mesh);
    std::vector<glm::vec3> verts;
    std::vector<uint32_t> items;
    view_.hemicubeGeometry(verts, items);
    std::string err;
    glGeometryOk_ = glHemicube_.setGeometry(verts, items, err);
    if (!glGeometryOk_) message_ = err;
    glm::dvec3 lo(1e300), hi(-1e300);
    for (const glm::dvec3& p : model_->mesh.vertices) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    sceneRadius_ = std::max(0.5 * glm::length(hi - lo), 1e-9);
    sceneCentre_ = 0.5 * (lo + hi);
    // The light's colour: the emitters' area-weighted emission (white balance divides by it).
    glm::dvec3 light(0.0);
    for (const rad::Patch& p : model_->mesh.patches)
        light += p.area * p.emission;
    model_->light = luminance(light) > 0 ? light / luminance(light) : glm::dvec3(1.0);
    selected_ = -1;
    selectedRow_.clear();
    selectedItems_ = rad::ItemBuffer{};
    rebuildSolver();
}

// GL hemicube row from `frame` (a patch's, self = its id, or a shooting group's, self = −1).
void RadiosityLab::glRow(const rad::HemicubeFrame& frame, int self, std::vector<float>& out) {
    std::string err;
    // The table's resolution, not the panel's: a slider being dragged must not make item
    // buffer and delta table disagree.
    const int res = model_->ff->deltaTable().resolution;
    if (!glHemicube_.render(frame, res, GlHemicube::kNearFraction * sceneRadius_, providerItems_,
                            err))
        throw std::runtime_error(err);
    rad::accumulate(providerItems_, model_->ff->deltaTable(), int(model_->mesh.patches.size()),
                    self, out);
}

void RadiosityLab::rebuildSolver() {
    stopRun();
    rad::FormFactorConfig fc;
    fc.method = s.method == FfMethod::Rays          ? rad::FormFactorMethod::Rays
                : s.method == FfMethod::CpuHemicube ? rad::FormFactorMethod::Hemicube
                                                    : rad::FormFactorMethod::External;
    if (s.method == FfMethod::GlHemicube) {
        // Rows by OpenGL: only on this (the GL) thread, so runs step in draw() (see startRun).
        fc.rowProvider = [this](int i, std::vector<float>& out) {
            glRow(rad::hemicubeFrame(model_->mesh, i), i, out);
        };
        fc.groupRowProvider = [this](int, const rad::HemicubeFrame& fr, std::vector<float>& out) {
            glRow(fr, -1, out);
        };
    } else if (s.method == FfMethod::Rays) {
        // A shooting group is not a patch: each receiver gathers from the group's area by the
        // exact point-to-polygon term and k visibility rays (point_rays.h).
        // Called on the solver's prefetch worker too: it reads this model (the solver, which
        // joins that worker, is destroyed before the model's form factors) and k as set now.
        const Model* model = model_.get();
        const int k = s.raySamples;
        fc.groupRowProvider = [model, k](int g, const rad::HemicubeFrame&,
                                         std::vector<float>& out) {
            rad::groupGatherRow(model->mesh, model->ff->bvh(), g, k, out,
                                model->ff->nearFieldReady(g));
        };
    }
    fc.rays.samples = s.raySamples;
    fc.hemicubeResolution = hemicubeFor(s);
    fc.threads = s.threads;
    model_->solver.reset();
    rad::SolverConfig sc;
    sc.kind = s.solver == 1   ? rad::SolverKind::Jacobi
              : s.solver == 2 ? rad::SolverKind::GaussSeidel
                              : rad::SolverKind::Progressive;
    sc.ambient = s.ambient;
    sc.tolerance = s.tolerance;
    // The groups next in line are prepared on the second core while this run shoots (or, with
    // GL rows, while the GL thread draws them): the same B and steps, sooner.
    sc.prefetch = true;
    try {
        model_->ff = std::make_unique<rad::FormFactors>(model_->mesh, fc);
        if (s.method == FfMethod::GlHemicube && sc.kind != rad::SolverKind::Progressive) {
            // Jacobi and Gauss-Seidel gather F·B over rows on TBB threads, where no GL context
            // is current: every GL row is drawn here first (computeAll calls the provider
            // serially on this thread) and the sweeps read the stored matrix.
            if (!model_->ff->stored())
                throw std::runtime_error(
                    "Jacobi / Gauss-Seidel with GL rows need F stored (at most " +
                    std::to_string(fc.maxStoredPatches) +
                    " patches); use progressive or the CPU hemicube");
            model_->ff->computeAll();
        }
        model_->solver = std::make_unique<rad::Solver>(model_->mesh, *model_->ff, sc);
        try {
            const auto tp = std::chrono::steady_clock::now();
            buildPreview(fc, sc);
            previewSetupSeconds_ = secondsSince(tp);
        } catch (const std::exception& e) {
            // Without a preview the run is the full solve alone, as before.
            model_->preview = Model::Preview{};
            std::fprintf(stderr, "lab08: no preview: %s\n", e.what());
        }
    } catch (const std::exception& e) {
        // Never leave the lab without a solver: progressive with the CPU hemicube.
        message_ = e.what();
        std::fprintf(stderr, "lab08: %s (progressive with the CPU hemicube instead)\n", e.what());
        s.method = FfMethod::CpuHemicube;
        s.solver = 0;
        fc.method = rad::FormFactorMethod::Hemicube;
        fc.rowProvider = nullptr;
        fc.groupRowProvider = nullptr;
        sc.kind = rad::SolverKind::Progressive;
        model_->ff = std::make_unique<rad::FormFactors>(model_->mesh, fc);
        model_->solver = std::make_unique<rad::Solver>(model_->mesh, *model_->ff, sc);
        model_->preview = Model::Preview{};
        previewShown_ = false;
    }
    publish();
    selectedDirty_ = selected_ >= 0;
    requestSolve();
}

// Every change (method, patches, scene, solver, ambient, hemicube, k) restarts the solve: a
// student never looks at the unlit box by accident. In a window the run starts now; headless
// it runs before the next picture is drawn (--steps 0 draws the unsolved state on purpose).
void RadiosityLab::requestSolve() {
#if defined(WB_HEADLESS)
    autoSolve_ = true;
#else
    startRun();
#endif
}

std::vector<int> RadiosityLab::patchSurfaces() const {
    std::vector<int> out;
    if (model_)
        for (const rad::Patch& p : model_->mesh.patches)
            out.push_back(p.surface);
    return out;
}

std::vector<glm::dvec3> RadiosityLab::patchCentres() const {
    std::vector<glm::dvec3> out;
    if (model_)
        for (const rad::Patch& p : model_->mesh.patches)
            out.push_back(p.centre);
    return out;
}

std::vector<std::string> RadiosityLab::surfaceNames() const {
    std::vector<std::string> out;
    if (model_)
        for (const rad::Surface& sf : model_->mesh.surfaces)
            out.push_back(sf.name);
    return out;
}

std::unique_ptr<Lab> makeRadiosityLab() {
    return std::make_unique<RadiosityLab>();
}

namespace {
const RadiosityLab& rl(const Lab& lab) {
    return static_cast<const RadiosityLab&>(lab);
}
} // namespace

RadiosityState& radiosityState(Lab& lab) {
    return static_cast<RadiosityLab&>(lab).s;
}
int radiosityPatchCount(const Lab& lab) {
    return rl(lab).patchCount();
}
int radiosityStepCount(const Lab& lab) {
    return rl(lab).stepCount();
}
double radiosityResidual(const Lab& lab) {
    return rl(lab).residual();
}
std::vector<glm::dvec3> radiosityDisplayB(const Lab& lab) {
    return rl(lab).displayB();
}
std::vector<glm::dvec3> radiosityPreviewB(const Lab& lab) {
    return rl(lab).previewB();
}
PreviewError radiosityPreviewError(const Lab& lab) {
    return rl(lab).previewError();
}
int radiositySelected(const Lab& lab) {
    return rl(lab).selected();
}
const std::vector<float>& radiositySelectedRow(const Lab& lab) {
    return rl(lab).selectedRow();
}
const rad::ItemBuffer& radiositySelectedItems(const Lab& lab) {
    return rl(lab).selectedItems();
}
void radiositySelect(Lab& lab, int patch) {
    static_cast<RadiosityLab&>(lab).select(patch);
}
std::vector<int> radiosityPatchSurfaces(const Lab& lab) {
    return rl(lab).patchSurfaces();
}
std::vector<glm::dvec3> radiosityPatchCentres(const Lab& lab) {
    return rl(lab).patchCentres();
}
std::vector<std::string> radiositySurfaceNames(const Lab& lab) {
    return rl(lab).surfaceNames();
}
std::string radiositySummary(const Lab& lab) {
    return rl(lab).summary();
}
bool radiosityBudgetHit(const Lab& lab) {
    return rl(lab).budgetHit();
}
glm::vec3 radiosityPatchColour(const Lab& lab, int i) {
    return rl(lab).patchColour(i);
}

} // namespace wb
