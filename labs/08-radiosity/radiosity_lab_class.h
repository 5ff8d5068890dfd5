#pragma once
// The lab 08 class, shared by its three files (kept apart so each stays readable):
//   radiosity_lab.cpp      options, keys, the model (scene, patches, form factors, solver) and
//                          solving (background runs, headless budget);
//   radiosity_display.cpp  what is drawn: tone mapping (exposure, white balance, sRGB), the
//                          scene, the form-factor false colour with its colour bar, the
//                          hemicube inset, picking;
//   radiosity_panel.cpp    the ImGui panel.
#include "radiosity_lab.h"

#include "exercise_view.h"

#include "gl_hemicube.h"
#include "hemicube_view.h"
#include "patch_view.h"

#include "common/gl.h"

#include "core/radiosity/form_factors.h"
#include "core/radiosity/scenes.h"
#include "core/radiosity/solver.h"

#include "core/i18n.h"
#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

const wb::ex::LabExercises& wbExercises_lab08();

namespace wb {

double secondsSince(std::chrono::steady_clock::time_point t0);
double luminance(const glm::dvec3& c);

// What the solver has published for drawing (the worker thread owns the solver while it runs).
struct RadiositySnapshot {
    std::vector<glm::dvec3> B;   // display radiosity per patch
    std::vector<double> history; // residual after each step
    int steps = 0;
    double residual = 1.0;
    int lastShooter = -1;
    bool preview = false; // B is the preview's (coarse shooting patches), the full solve runs on
    uint64_t version = 0;
};

class RadiosityLab : public Lab {
  public:
    RadiosityState s;

    std::string title() const override { return tr("Lab 08 - radiosity"); }
    std::vector<KeyHelp> keys() const override;
    std::vector<OptionHelp> options() const override;
    bool setOption(const std::string& name, const std::string& value, std::string& error) override;
    void init() override;
    ~RadiosityLab() override { stopRun(); }
    bool key(int k) override;
    bool click(int x, int y, const View& view) override {
        (void)view;
        pendingClick_ = true;
        clickX_ = x;
        clickY_ = y;
        return true;
    }
    bool busy() const override { return running() || ex_.busy(); }
    bool worksInDraw() const override { return mainThreadRun_ && !ex_.on(); }
    bool frameWanted() override { return frameWanted_.exchange(false); }
    int pollMs() const override { return ex_.pollMs(); }
    bool poll() override { return ex_.shellPoll(); }
    bool headlessFailed() const override { return failed_; }
    void draw(const View& view) override;
    void drawScene(const View& view);
    void gui() override;

    // Test hooks.
    int patchCount() const { return model_ ? int(model_->mesh.patches.size()) : 0; }
    int stepCount() const { return snapshot().steps; }
    double residual() const { return snapshot().residual; }
    std::vector<glm::dvec3> displayB() const { return snapshot().B; }
    // The preview's display B when its phase ended (empty: no preview ran), and its residual.
    const std::vector<glm::dvec3>& previewB() const { return previewB_; }
    double previewResidual() const { return previewResidual_; }
    bool previewOn() const { return previewOption_; }
    PreviewError previewError() const; // radiosity_preview.cpp
    int selected() const { return selected_; }
    const std::vector<float>& selectedRow() const { return selectedRow_; }
    const rad::ItemBuffer& selectedItems() const { return selectedItems_; }
    void select(int patch) {
        selected_ = patch;
        selectedDirty_ = true;
    }
    std::vector<int> patchSurfaces() const;
    std::vector<glm::dvec3> patchCentres() const;
    std::vector<std::string> surfaceNames() const;
    std::string summary() const;
    bool budgetHit() const { return budgetHit_; }
    glm::vec3 patchColour(int i) const {
        return i >= 0 && size_t(i) < patchColour_.size() ? patchColour_[size_t(i)]
                                                         : glm::vec3(0.0f);
    }

  private:
    // The scene, its patches, form factors and solver: rebuilt together (the form factors and
    // the solver keep references to the mesh, so the three live at fixed addresses).
    struct Model {
        rad::Scene scene;
        rad::PatchMesh mesh;
        std::unique_ptr<rad::FormFactors> ff;
        std::unique_ptr<rad::Solver> solver;
        glm::dvec3 light{1.0}; // the emitters' area-weighted colour (for white balance)
        // The first phase of a run (radiosity_preview.cpp): the same patches shooting from
        // coarse groups, no near field; shown until the full solve (above) overtakes it.
        // Declared after the full solve's members: destroyed first (its rays provider reads
        // nothing of theirs, but the order keeps each solver before its form factors).
        struct Preview {
            rad::PatchMesh mesh; // `mesh` regrouped
            std::unique_ptr<rad::FormFactors> ff;
            std::unique_ptr<rad::Solver> solver;
        } preview;
    };

    // radiosity_lab.cpp: model and solving.
    bool loadScene(const std::string& name, double patchSize);
    static double defaultPatchSize(const rad::Scene& scene);
    bool meshChecked(const rad::Scene& scene, double patchSize, rad::PatchMesh& out);
    void remesh(double patchSize);
    void refine();
    void setMethod(FfMethod m);
    void install(std::unique_ptr<Model> m);
    void rebuildSolver();
    void requestSolve();
    void stepOnce();
    void startRun();
    void stopRun();
    void finishRun();
    // inputWaiting: the window's View::inputWaiting (null headless): the slice ends early when
    // the user's input waits.
    void stepOnMainThread(bool headless, bool (*inputWaiting)() = nullptr);
    bool running() const { return running_.load(); }
    bool overBudget() const;
    int stepLimit() const;
    void publish(const rad::Solver& sol, bool preview, bool last = false);
    void publish() { // the full solve's state (a key, a rebuild, a single step)
        if (model_ && model_->solver) publish(*model_->solver, false);
    }
    // radiosity_preview.cpp: the preview's mesh, form factors and solver for the current model.
    void buildPreview(const rad::FormFactorConfig& full, const rad::SolverConfig& sc);
    bool runPreview() const; // the next run starts with the preview phase
    void finishPreview();    // the preview phase has ended: keep its B, let the full solve go on
    RadiositySnapshot snapshot() const {
        std::lock_guard<std::mutex> lock(snapMutex_);
        return snapshot_;
    }
    void printSummary();
    void reportRun() const;
    void glRow(const rad::HemicubeFrame& frame, int self, std::vector<float>& out);

    // radiosity_display.cpp: colours, drawing, picking.
    glm::vec3 tone(const glm::dvec3& B) const;
    double autoExposure(const std::vector<glm::dvec3>& B) const;
    void updateColours();
    void updateSelection();
    void setupCamera(const View& view) const;
    void drawOverlay(const View& view);
    void drawColourBar(const View& view) const;
    int pick(const View& view, int x, int y);

    std::unique_ptr<Model> model_;
    ex::ExerciseMode ex_{wbExercises_lab08()}; // e: your form factors (exercises.cpp)
    PatchView view_;
    GlHemicube glHemicube_;
    bool glGeometryOk_ = false;
    double sceneRadius_ = 1.0;
    glm::dvec3 sceneCentre_{0.0};
    double patchSizeOption_ = -1.0;
    double defaultEdge_ = 0.0;    // the scene's default patch edge (groups are sized by it)
    double shooterOption_ = -1.0; // --shooting-patch (−1: the scene's default)
    std::string message_, refineNote_;
    bool failed_ = false; // headless: no PNG, exit 1 (the scene could not be meshed, a bad click)

    // Solving.
    std::thread worker_;
    std::atomic<bool> cancel_{false}, running_{false};
    bool mainThreadRun_ = false; // the GL method's run, stepped in draw()
    bool autoSolve_ = false;     // headless: solve before drawing (a change since the last solve)
    bool autoRun_ = false;       // the current run is the automatic one (--steps limits it)
    rad::ItemBuffer providerItems_; // the GL row provider's item buffer
    std::chrono::steady_clock::time_point runStart_, labStart_;
    std::atomic<double> runSeconds_{0};
    std::atomic<double> stepSeconds_{0}; // of the run, inside solver steps (the rest: the window)
    std::atomic<double> usableSeconds_{-1}; // the run's time to unshot power < 5% (−1: not yet)
    // The run started below 5% reached by `space` steps: it has no time to usable to report
    // (it logged "unshot power < 5% after 0.00 s"); the steps that got there say so instead.
    std::atomic<bool> usableBefore_{false};
    std::atomic<bool> budgetHit_{false};
    double lastStepSeconds_ = 0;
    mutable std::mutex snapMutex_;
    RadiositySnapshot snapshot_;
    std::string workerError_;     // a step's exception on the worker (guarded by snapMutex_)
    uint64_t printedVersion_ = 0; // headless summary printed for this snapshot
    // The preview (radiosity_preview.cpp). In a window every run of a fresh solve starts with
    // it; headless only with --preview on (a headless picture is the converged answer).
#if defined(WB_HEADLESS)
    bool previewOption_ = false;
#else
    bool previewOption_ = true;
#endif
    std::atomic<bool> previewPhase_{false}; // the run is in its preview phase
    std::atomic<bool> previewShown_{false}; // the snapshot's B is the preview's
    std::atomic<double> previewResidual_{1.0}; // the preview's residual when it ended
    std::vector<glm::dvec3> previewB_;          // its display B then (tests, docs)
    std::atomic<int> fullSteps_{0};             // the full solve's steps while the preview shows
    std::atomic<bool> frameWanted_{false};      // a picture worth showing at once was published
    double previewSetupSeconds_ = 0; // buildPreview's time (before the run starts: logged)
    bool skipSlice_ = false; // GL run: the next frame is drawn without a slice of steps
    std::atomic<double> shownSeconds_{-1}; // a usable picture first drawn (window), s from start

    // Display.
    std::vector<glm::vec3> patchColour_;
    uint64_t coloursVersion_ = ~uint64_t(0);
    bool coloursDirty_ = true;
    double autoExposure_ = 1.0; // what auto exposure chose last (the slider's centre)
    std::vector<double> history_;
    int steps_ = 0;
    double residual_ = 1.0;
    int lastShooter_ = -1;
    bool drawnPreview_ = false; // the colours are the preview's

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

} // namespace wb
