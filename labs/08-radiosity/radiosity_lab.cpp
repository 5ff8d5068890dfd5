#include "radiosity_lab.h"

#include "exercise_view.h"

#include "core/i18n.h"

#include "gl_hemicube.h"
#include "hemicube_view.h"
#include "patch_view.h"

#include "common/gl.h"
#include "common/gl_util.h"

#include "core/radiosity/form_factors.h"
#include "core/radiosity/scenes.h"
#include "core/radiosity/smoothing.h"
#include "core/radiosity/solver.h"

#include "common/panel.h"
#include "core/i18n.h"

#include <glm/gtc/matrix_transform.hpp>
#include <imgui.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <thread>

const wb::ex::LabExercises& wbExercises_lab08();

namespace wb {

namespace {

double secondsSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double luminance(const glm::dvec3& c) {
    return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

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

// What the solver has published for drawing (the worker thread owns the solver while it runs).
struct Snapshot {
    std::vector<glm::dvec3> B;   // display radiosity per patch
    std::vector<double> history; // residual after each step
    int steps = 0;
    double residual = 1.0;
    int lastShooter = -1;
    uint64_t version = 0;
};

} // namespace

class RadiosityLab : public Lab {
  public:
    RadiosityState s;

    std::string title() const override { return tr("Lab 08 - radiosity"); }

    std::vector<KeyHelp> keys() const override {
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

    std::vector<OptionHelp> options() const override {
        return {{"scene", tr("NAME"), tr("cornell, classroom or floorlamp")},
                {"patch-size", "M", tr("longest patch edge in metres")},
                {"method", "rays|cpu|gl", tr("form-factor method")},
                {"solver", "progressive|jacobi|gauss-seidel", tr("how B = E + RFB is solved")},
                {"hemicube", "N", tr("hemicube resolution (even, 8..1024)")},
                {"rays", "K", tr("rays per patch pair (1..256)")},
                {"threads", "N", tr("form-factor threads (0 = all cores)")},
                {"click", "X,Y", tr("click the scene at pixel (X, Y) as the mouse would")}};
    }

    bool setOption(const std::string& name, const std::string& value, std::string& error) override {
        auto number = [&](double lo, double hi, double& out) {
            char* end = nullptr;
            const double v = std::strtod(value.c_str(), &end);
            if (value.empty() || *end || !std::isfinite(v) || v < lo || v > hi) {
                error = trf("expected a number in %g..%g, got '%s'", double(lo), double(hi),
                            value.c_str());
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
                error =
                    trf("expected progressive, jacobi or gauss-seidel, got '%s'", value.c_str());
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
            s.threads = int(v);
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
        error = trf("unknown option --%s", name.c_str());
        return false;
    }

    void init() override {
        loadScene(s.sceneName, patchSizeOption_ > 0 ? patchSizeOption_ : -1.0);
#if !defined(WB_HEADLESS)
        // In a window the solution builds up at once (any key stops it, r goes on); headless
        // renders solve only when their keys say so (r, space), so a script controls the state.
        startRun();
#endif
    }

    ~RadiosityLab() override {
        stopRun();
    }

    bool key(int k) override {
        if (ex_.key(k)) return true;
#if defined(WB_HEADLESS)
        // Headless, keys are a script (--keys "r s"): a run finishes before the next key.
        finishRun();
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
            stepOnce();
            return true;
        case 'r':
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
#if !defined(WB_HEADLESS)
            startRun(); // a new scene solves at once in a window, as at startup
#endif
            return true;
        }
        default:
            return false;
        }
    }

    bool click(int x, int y, const View& view) override {
        (void)view;
        pendingClick_ = true;
        clickX_ = x;
        clickY_ = y;
        return true;
    }

    bool busy() const override {
        return running() || ex_.busy();
    }
    int pollMs() const override {
        return ex_.pollMs();
    }
    bool poll() override {
        return ex_.shellPoll();
    }

    void draw(const View& view) override;
    void gui() override;

    // Test hooks.
    int patchCount() const {
        return model_ ? int(model_->mesh.patches.size()) : 0;
    }
    int stepCount() const {
        return snapshot().steps;
    }
    double residual() const {
        return snapshot().residual;
    }
    std::vector<glm::dvec3> displayB() const {
        return snapshot().B;
    }
    int selected() const {
        return selected_;
    }
    const std::vector<float>& selectedRow() const {
        return selectedRow_;
    }
    const rad::ItemBuffer& selectedItems() const {
        return selectedItems_;
    }
    void select(int patch) {
        selected_ = patch;
        selectedDirty_ = true;
    }
    std::vector<int> patchSurfaces() const {
        std::vector<int> out;
        if (model_)
            for (const rad::Patch& p : model_->mesh.patches)
                out.push_back(p.surface);
        return out;
    }
    std::vector<glm::dvec3> patchCentres() const {
        std::vector<glm::dvec3> out;
        if (model_)
            for (const rad::Patch& p : model_->mesh.patches)
                out.push_back(p.centre);
        return out;
    }
    std::vector<std::string> surfaceNames() const {
        std::vector<std::string> out;
        if (model_)
            for (const rad::Surface& sf : model_->mesh.surfaces)
                out.push_back(sf.name);
        return out;
    }

  private:
    // The scene, its patches, form factors and solver: rebuilt together (the form factors and
    // the solver keep references to the mesh, so the three live at fixed addresses).
    struct Model {
        rad::Scene scene;
        rad::PatchMesh mesh;
        std::unique_ptr<rad::FormFactors> ff;
        std::unique_ptr<rad::Solver> solver;
        double exposure = 1.0; // radiosity that displays as mid-grey (before the user's factor)
    };

    // 1. Scene, mesh, form factors, solver.
    void loadScene(const std::string& name, double patchSize) {
        stopRun();
        try {
            rad::Scene scene = rad::sceneByName(name);
            if (patchSize <= 0) patchSize = defaultPatchSize(scene);
            rad::PatchMesh mesh = rad::meshScene(scene, rad::MeshConfig{patchSize});
            auto m = std::make_unique<Model>();
            m->scene = std::move(scene);
            m->mesh = std::move(mesh);
            s.sceneName = name;
            s.patchSize = patchSize;
            install(std::move(m));
        } catch (const std::exception& e) {
            message_ = e.what();
            std::fprintf(stderr, tr("lab08: scene %s: %s\n"), name.c_str(), e.what());
        }
    }

    static double defaultPatchSize(const rad::Scene& scene) {
        // A twentieth of the scene's diagonal: about a thousand patches in the Cornell box.
        glm::dvec3 lo(1e300), hi(-1e300);
        for (const rad::Surface& sf : scene.surfaces)
            for (const glm::dvec3& p : sf.vertices) {
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            }
        const double d = glm::length(hi - lo);
        return std::isfinite(d) && d > 0 ? d / 20.0 : 0.1;
    }

    void remesh(double patchSize) {
        if (!model_) return;
        stopRun();
        patchSize = std::clamp(patchSize, 1e-3, 100.0);
        try {
            rad::PatchMesh mesh = rad::meshScene(model_->scene, rad::MeshConfig{patchSize});
            if (mesh.patches.size() > kMaxPatches) {
                message_ = trf("patch size %g m would give %zu patches (the lab stops at %zu)",
                               patchSize, mesh.patches.size(), size_t(kMaxPatches));
                return;
            }
            auto m = std::make_unique<Model>();
            m->scene = model_->scene;
            m->mesh = std::move(mesh);
            s.patchSize = patchSize;
            install(std::move(m));
        } catch (const std::exception& e) {
            message_ = e.what();
        }
    }

    void refine() {
        if (!model_) return;
        stopRun();
        // core's threshold is relative to the brightest non-emitting patch (the light's B
        // would make any fraction of it split nothing).
        const std::vector<glm::dvec3> B = model_->solver->displayRadiosity();
        auto m = std::make_unique<Model>();
        m->scene = model_->scene;
        m->mesh = model_->mesh;
        rad::RefineConfig rc;
        rc.maxPatches = kMaxPatches;
        int split = 0;
        try {
            split = rad::refineAdaptive(m->mesh, B, rc);
        } catch (const std::exception& e) {
            message_ = e.what();
            return;
        }
        refineNote_ = trf("%d patches split", int(split));
        if (split == 0) return;
        const bool wasSolved = snapshot().steps > 0;
        install(std::move(m));
        // The old solution drove the split; solve the finer mesh again so the picture shows it.
        if (wasSolved) startRun();
    }

    void setMethod(FfMethod m) {
        if (s.method == m || !model_) {
            s.method = m;
            return;
        }
        stopRun();
        s.method = m;
        rebuildSolver();
    }

    void install(std::unique_ptr<Model> m) {
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
        // Exposure: the mean radiosity of a closed room, Σ A·E / (Σ A · (1 − R̄)).
        double power = 0, area = 0, rArea = 0;
        for (const rad::Patch& p : model_->mesh.patches) {
            power += p.area * luminance(p.emission);
            area += p.area;
            rArea += p.area * luminance(p.reflectivity);
        }
        const double rMean = area > 0 ? rArea / area : 0.5;
        model_->exposure = area > 0 && power > 0 ? power / (area * (1 - rMean)) : 1.0;
        selected_ = -1;
        selectedRow_.clear();
        selectedItems_ = rad::ItemBuffer{};
        rebuildSolver();
    }

    void rebuildSolver() {
        stopRun();
        rad::FormFactorConfig fc;
        fc.method = s.method == FfMethod::Rays          ? rad::FormFactorMethod::Rays
                    : s.method == FfMethod::CpuHemicube ? rad::FormFactorMethod::Hemicube
                                                        : rad::FormFactorMethod::External;
        if (s.method == FfMethod::GlHemicube) {
            // Rows by OpenGL: only on this (the GL) thread, so runs step in draw() (see startRun).
            fc.rowProvider = [this](int i, std::vector<float>& out) {
                std::string err;
                const rad::HemicubeFrame fr = rad::hemicubeFrame(model_->mesh, i);
                // The table's resolution, not the panel's: a slider being dragged must not
                // make item buffer and delta table disagree.
                const int res = model_->ff->deltaTable().resolution;
                if (!glHemicube_.render(fr, res, GlHemicube::kNearFraction * sceneRadius_,
                                        providerItems_, err))
                    throw std::runtime_error(err);
                rad::accumulate(providerItems_, model_->ff->deltaTable(),
                                int(model_->mesh.patches.size()), i, out);
            };
        }
        fc.rays.samples = s.raySamples;
        fc.hemicubeResolution = s.hemicubeRes;
        fc.threads = s.threads;
        model_->solver.reset();
        rad::SolverConfig sc;
        sc.kind = s.solver == 1   ? rad::SolverKind::Jacobi
                  : s.solver == 2 ? rad::SolverKind::GaussSeidel
                                  : rad::SolverKind::Progressive;
        sc.ambient = s.ambient;
        sc.tolerance = s.tolerance;
        try {
            model_->ff = std::make_unique<rad::FormFactors>(model_->mesh, fc);
            if (s.method == FfMethod::GlHemicube && sc.kind != rad::SolverKind::Progressive) {
                // Jacobi and Gauss-Seidel gather F·B over rows on TBB threads, where no GL
                // context is current: every GL row is drawn here first (computeAll calls the
                // provider serially on this thread) and the sweeps read the stored matrix.
                if (!model_->ff->stored())
                    throw std::runtime_error("Jacobi / Gauss-Seidel with GL rows need F stored (at "
                                             "most " +
                                             std::to_string(fc.maxStoredPatches) +
                                             " patches); use progressive or the CPU hemicube");
                model_->ff->computeAll();
            }
            model_->solver = std::make_unique<rad::Solver>(model_->mesh, *model_->ff, sc);
        } catch (const std::exception& e) {
            // Never leave the lab without a solver: progressive with the CPU hemicube.
            message_ = e.what();
            std::fprintf(stderr, tr("lab08: %s (progressive with the CPU hemicube instead)\n"),
                         e.what());
            s.method = FfMethod::CpuHemicube;
            s.solver = 0;
            fc.method = rad::FormFactorMethod::Hemicube;
            fc.rowProvider = nullptr;
            sc.kind = rad::SolverKind::Progressive;
            model_->ff = std::make_unique<rad::FormFactors>(model_->mesh, fc);
            model_->solver = std::make_unique<rad::Solver>(model_->mesh, *model_->ff, sc);
        }
        publish();
        selectedDirty_ = selected_ >= 0;
    }

    // 2. Solving: one step here, or a run on a worker thread that publishes snapshots.
    void stepOnce() {
        if (!model_) return;
        const auto t0 = std::chrono::steady_clock::now();
        try {
            model_->solver->step();
        } catch (const std::exception& e) {
            message_ = e.what();
        }
        lastStepSeconds_ = secondsSince(t0);
        publish();
    }

    void startRun() {
        if (!model_ || running()) return;
        cancel_ = false;
        running_ = true;
        runStart_ = std::chrono::steady_clock::now();
        runSeconds_ = 0;
        if (s.method == FfMethod::GlHemicube) {
            // GL rows need the GL thread: draw() takes steps for ~30 ms per frame instead.
            mainThreadRun_ = true;
            return;
        }
        rad::Solver* solver = model_->solver.get();
        const double tol = s.tolerance;
        worker_ = std::thread([this, solver, tol] {
            auto lastPublish = std::chrono::steady_clock::now();
            while (!cancel_.load() && solver->residual() >= tol &&
                   solver->steps() < solver->config().maxSteps) {
                try {
                    solver->step();
                } catch (const std::exception& e) {
                    std::lock_guard<std::mutex> lock(snapMutex_);
                    workerError_ = e.what();
                    break;
                }
                // At most ~30 snapshots a second: copying B per shot would dominate at 10k patches.
                if (secondsSince(lastPublish) > 0.033) {
                    publish();
                    lastPublish = std::chrono::steady_clock::now();
                }
            }
            publish();
            runSeconds_ = secondsSince(runStart_);
            running_ = false;
        });
    }

    void stopRun() {
        cancel_ = true;
        if (worker_.joinable()) worker_.join();
        if (mainThreadRun_) runSeconds_ = secondsSince(runStart_);
        mainThreadRun_ = false;
        running_ = false;
    }

    // Headless: one line per solution state drawn (the command-line front end's report).
    void printSummary() {
        const Snapshot snap = snapshot();
        if (snap.version == printedVersion_) return;
        printedVersion_ = snap.version;
        const rad::FormFactors& ff = *model_->ff;
        const char* methods[] = {"rays", "CPU hemicube", "GL hemicube"};
        std::printf(
            tr("%s: %zu patches, %s, %d steps, residual %.2e, form factors %.2f s (%lld rows, "
               "%.1f MiB), last run %.2f s\n"),
            model_->scene.name.c_str(), model_->mesh.patches.size(), methods[int(s.method)],
            snap.steps, snap.residual, ff.seconds(), ff.rowsComputed(),
            double(ff.bytes()) / (1024.0 * 1024.0), runSeconds_.load());
        std::fflush(stdout);
    }

    // Waits for a run to end by itself (headless scripts).
    void finishRun() {
        if (worker_.joinable()) worker_.join();
        while (mainThreadRun_)
            stepOnMainThread(true);
        running_ = false;
    }

    // The GL method's run: steps until the frame's time budget is spent (headless: to the end).
    void stepOnMainThread(bool headless) {
        if (!mainThreadRun_ || !model_) return;
        rad::Solver& sol = *model_->solver;
        const auto t0 = std::chrono::steady_clock::now();
        try {
            while (sol.residual() >= s.tolerance && sol.steps() < sol.config().maxSteps &&
                   (headless || secondsSince(t0) < 0.03))
                sol.step();
        } catch (const std::exception& e) {
            message_ = e.what();
            mainThreadRun_ = false;
        }
        if (sol.residual() < s.tolerance || sol.steps() >= sol.config().maxSteps)
            mainThreadRun_ = false;
        publish();
        if (!mainThreadRun_) {
            runSeconds_ = secondsSince(runStart_);
            running_ = false;
        }
    }

    bool running() const {
        return running_.load();
    }

    // Copies what drawing needs out of the solver (called by the worker while it runs, or here).
    void publish() {
        if (!model_ || !model_->solver) return;
        const rad::Solver& sol = *model_->solver;
        Snapshot snap;
        snap.B = sol.displayRadiosity();
        snap.history = sol.history();
        snap.steps = sol.steps();
        snap.residual = sol.residual();
        snap.lastShooter = sol.lastShooter();
        std::lock_guard<std::mutex> lock(snapMutex_);
        snap.version = snapshot_.version + 1;
        snapshot_ = std::move(snap);
    }

    Snapshot snapshot() const {
        std::lock_guard<std::mutex> lock(snapMutex_);
        return snapshot_;
    }

    // 3. Display colours from the latest snapshot.
    glm::vec3 tone(const glm::dvec3& B) const {
        const double scale = 0.35 * double(s.exposure) / std::max(model_->exposure, 1e-30);
        glm::vec3 c;
        for (int k = 0; k < 3; ++k) {
            const double x = std::clamp(B[k] * scale, 0.0, 1.0);
            c[k] = float(std::pow(x, 1.0 / 2.2)); // display gamma
        }
        return c;
    }

    void updateColours() {
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
        }
        coloursVersion_ = version;
        coloursDirty_ = false;
        if (B.size() != model_->mesh.patches.size()) return;
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

    // 4. The selected patch: its row and item buffer by the current method.
    void updateSelection() {
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

    void setupCamera(const View& view) const;
    void drawOverlay(const View& view);
    int pick(const View& view, int x, int y);

    static constexpr size_t kMaxPatches = 40000; // [ ] and a stop here: the lab stays responsive

    std::unique_ptr<Model> model_;
    ex::ExerciseMode ex_{wbExercises_lab08()}; // e: your form factors (exercises.cpp)
    PatchView view_;
    GlHemicube glHemicube_;
    bool glGeometryOk_ = false;
    double sceneRadius_ = 1.0;
    glm::dvec3 sceneCentre_{0.0};
    double patchSizeOption_ = -1.0;
    std::string message_, refineNote_;

    // Solving.
    std::thread worker_;
    std::atomic<bool> cancel_{false}, running_{false};
    bool mainThreadRun_ = false;    // the GL method's run, stepped in draw()
    rad::ItemBuffer providerItems_; // the GL row provider's item buffer
    std::chrono::steady_clock::time_point runStart_;
    std::atomic<double> runSeconds_{0};
    double lastStepSeconds_ = 0;
    mutable std::mutex snapMutex_;
    Snapshot snapshot_;
    std::string workerError_;     // a step's exception on the worker (guarded by snapMutex_)
    uint64_t printedVersion_ = 0; // headless summary printed for this snapshot

    // Display.
    std::vector<glm::vec3> patchColour_;
    uint64_t coloursVersion_ = ~uint64_t(0);
    bool coloursDirty_ = true;
    std::vector<double> history_;
    int steps_ = 0;
    double residual_ = 1.0;
    int lastShooter_ = -1;

    // Selection.
    bool pendingClick_ = false;
    int clickX_ = 0, clickY_ = 0;
    int selected_ = -1;
    bool selectedDirty_ = false;
    std::vector<float> selectedRow_;
    rad::ItemBuffer selectedItems_;
    std::string selectedSource_;
    double selectedSeconds_ = 0, selectedRowSum_ = 0, selectedRowMax_ = 0;
    GLuint overlayTexture_ = 0;
    bool overlayDirty_ = true;
    int overlaySize_ = 0;
};

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
    setPerspective(view, 40.0, std::max(1e-3 * sceneRadius_, (dist - sceneRadius_) * 0.5),
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
    // Headless: a run started by the replayed keys is waited for (busy() until done).
    if (view.headless) {
        finishRun();
        printSummary();
    }
    stepOnMainThread(view.headless);
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
    if (s.showItems) {
        view_.drawItems(); // patch id + 1 as 24-bit RGB: what the GL hemicube draws
    } else if (selected_ >= 0 && !selectedRow_.empty()) {
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
}

void RadiosityLab::drawOverlay(const View& view) {
    // The hemicube of the selected patch, unfolded, in the lower left corner: what the patch
    // sees, each patch in its current colour.
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
    const int side = std::max(16, std::min(view.width, view.height) * 2 / 5);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, view.width, 0, view.height, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glColor3f(0.2f, 1.0f, 0.3f);
    glBegin(GL_LINE_LOOP); // frame
    glVertex2i(3, 3);
    glVertex2i(6 + side, 3);
    glVertex2i(6 + side, 6 + side);
    glVertex2i(3, 6 + side);
    glEnd();
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0);
    glVertex2i(5, 5);
    glTexCoord2f(1, 0);
    glVertex2i(5 + side, 5);
    glTexCoord2f(1, 1);
    glVertex2i(5 + side, 5 + side);
    glTexCoord2f(0, 1);
    glVertex2i(5, 5 + side);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, 0);
    glEnable(GL_DEPTH_TEST);
}

void RadiosityLab::gui() {
    ex_.gui();
    if (ex_.on())
        for (const std::string& line : radiosityExerciseLines(ex_))
            ImGui::TextWrapped("%s", line.c_str());
    if (!model_) {
        ImGui::TextWrapped("%s", message_.c_str());
        return;
    }
    const rad::FormFactors& ff = *model_->ff;
    ImGui::TextWrapped("%s", tr(model_->scene.name.c_str()));
    if (!message_.empty()) ImGui::TextWrapped(tr("note: %s"), message_.c_str());
    ImGui::Text(tr("patches %zu (edge <= %.3f m)"), model_->mesh.patches.size(), s.patchSize);
    int method = int(s.method);
    ImGui::Text(tr("form factors:"));
    ImGui::RadioButton(tr("1 rays"), &method, 0);
    sameLineIfFits(tr("2 CPU"));
    ImGui::RadioButton(tr("2 CPU"), &method, 1);
    sameLineIfFits(tr("3 GL"));
    ImGui::RadioButton(tr("3 GL"), &method, 2);
    if (method != int(s.method)) setMethod(FfMethod(method));
    if (s.method == FfMethod::GlHemicube)
        ImGui::TextWrapped(tr("GL rows are drawn on the GL thread: a run steps between frames. "
                              "Depth: %s."),
                           glHemicube_.reversedDepth() ? tr("reversed float")
                                                       : tr("float, far plane"));
    ImGui::Text(tr("FF time %.3f s, %lld rows"), ff.seconds(), ff.rowsComputed());
    ImGui::Text(tr("F memory %.1f MiB (%s)"), double(ff.bytes()) / (1024.0 * 1024.0),
                ff.stored() ? tr("stored") : tr("rows on demand"));

    ImGui::Separator();
    const char* solvers[] = {tr("progressive"), tr("Jacobi"), tr("Gauss-Seidel")};
    int solver = s.solver;
    if (ImGui::Combo(tr("solver"), &solver, solvers, 3) && solver != s.solver) {
        s.solver = solver;
        rebuildSolver();
    }
    ImGui::Text(tr("iterations %d, residual %.2e"), steps_, residual_);
    if (running())
        ImGui::Text(tr("running %.1f s (any key stops)"), secondsSince(runStart_));
    else if (runSeconds_ > 0)
        ImGui::Text(tr("last run %.2f s"), runSeconds_.load());
    if (!history_.empty()) {
        std::vector<float> lg(history_.size());
        for (size_t i = 0; i < lg.size(); ++i)
            lg[i] = float(std::log10(std::max(history_[i], 1e-12)));
        const float lo = *std::min_element(lg.begin(), lg.end());
        const float hi = *std::max_element(lg.begin(), lg.end());
        ImGui::PlotLines("##residual", lg.data(), int(lg.size()), 0, tr("log10 residual"),
                         lo - 0.1f, hi + 0.1f, ImVec2(0, 70));
    }
    float tol = float(std::log10(s.tolerance));
    if (ImGui::SliderFloat(tr("log10 tol"), &tol, -8.0f, -1.0f, "%.1f")) {
        s.tolerance = std::pow(10.0, double(tol));
    }
    if (ImGui::Checkbox(tr("ambient term"), &s.ambient)) {
        // The solver's config is fixed at construction: restart it with the new setting.
        rebuildSolver();
    }
    if (ImGui::Button(running() ? tr("stop (r)") : tr("run (r)"))) {
        if (running())
            stopRun();
        else
            startRun();
    }
    ImGui::SameLine();
    if (ImGui::Button(tr("step (space)")) && !running()) stepOnce();

    ImGui::Separator();
    if (ImGui::Checkbox(tr("s smooth"), &s.smooth)) coloursDirty_ = true;
    sameLineIfFits(tr("p outlines"));
    ImGui::Checkbox(tr("p outlines"), &s.outlines);
    ImGui::Checkbox(tr("item colours (hemicube's view)"), &s.showItems);
    if (ImGui::SliderFloat(tr("exposure"), &s.exposure, 0.1f, 10.0f, "%.2f",
                           ImGuiSliderFlags_Logarithmic))
        coloursDirty_ = true;
    int res = s.hemicubeRes;
    if (ImGui::SliderInt(tr("hemicube"), &res, 16, 1024) && res != s.hemicubeRes) {
        s.hemicubeRes = std::max(8, res & ~1);
    }
    if (ImGui::IsItemDeactivatedAfterEdit()) rebuildSolver();
    int k = s.raySamples;
    if (ImGui::SliderInt(tr("rays k"), &k, 1, 256)) s.raySamples = k;
    if (ImGui::IsItemDeactivatedAfterEdit()) rebuildSolver();
    if (!refineNote_.empty()) ImGui::Text("a: %s", refineNote_.c_str());

    ImGui::Separator();
    if (selected_ >= 0 && !selectedRow_.empty()) {
        const rad::Patch& p = model_->mesh.patches[size_t(selected_)];
        ImGui::TextWrapped(tr("patch %d on %s"), selected_,
                           model_->mesh.surfaces[size_t(p.surface)].name.c_str());
        ImGui::Text(tr("row by %s"), selectedSource_.c_str());
        ImGui::Text(tr("sum F = %.4f, max %.2e"), selectedRowSum_, selectedRowMax_);
        ImGui::Text(tr("%.1f ms, hemicube %d"), selectedSeconds_ * 1e3, selectedItems_.resolution);
        ImGui::TextWrapped(tr("Scene: F from this patch, log scale over 4 decades (white = max). "
                              "Lower left: its hemicube unfolded (top face in the middle)."));
        if (overlayTexture_ && overlaySize_ > 0)
            ImGui::Image(reinterpret_cast<ImTextureID>(uintptr_t(overlayTexture_)),
                         ImVec2(160, 160), ImVec2(0, 1), ImVec2(1, 0));
    } else {
        ImGui::TextWrapped(tr("Click a patch to see its form-factor row and its hemicube."));
    }
}

std::unique_ptr<Lab> makeRadiosityLab() {
    return std::make_unique<RadiosityLab>();
}

RadiosityState& radiosityState(Lab& lab) {
    return static_cast<RadiosityLab&>(lab).s;
}
int radiosityPatchCount(const Lab& lab) {
    return static_cast<const RadiosityLab&>(lab).patchCount();
}
int radiosityStepCount(const Lab& lab) {
    return static_cast<const RadiosityLab&>(lab).stepCount();
}
double radiosityResidual(const Lab& lab) {
    return static_cast<const RadiosityLab&>(lab).residual();
}
std::vector<glm::dvec3> radiosityDisplayB(const Lab& lab) {
    return static_cast<const RadiosityLab&>(lab).displayB();
}
int radiositySelected(const Lab& lab) {
    return static_cast<const RadiosityLab&>(lab).selected();
}
const std::vector<float>& radiositySelectedRow(const Lab& lab) {
    return static_cast<const RadiosityLab&>(lab).selectedRow();
}
const rad::ItemBuffer& radiositySelectedItems(const Lab& lab) {
    return static_cast<const RadiosityLab&>(lab).selectedItems();
}
void radiositySelect(Lab& lab, int patch) {
    static_cast<RadiosityLab&>(lab).select(patch);
}
std::vector<int> radiosityPatchSurfaces(const Lab& lab) {
    return static_cast<const RadiosityLab&>(lab).patchSurfaces();
}
std::vector<glm::dvec3> radiosityPatchCentres(const Lab& lab) {
    return static_cast<const RadiosityLab&>(lab).patchCentres();
}
std::vector<std::string> radiositySurfaceNames(const Lab& lab) {
    return static_cast<const RadiosityLab&>(lab).surfaceNames();
}

} // namespace wb
