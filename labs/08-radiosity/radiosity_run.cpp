// Lab 08's solving (issue 10; issue 19 items 5 and 7): one step at a time, or a run — on a
// worker thread for rays and the CPU hemicube, in draw()'s slices for the GL hemicube, whose
// rows need the GL thread — that publishes snapshots for drawing; with the preview first
// (radiosity_preview.cpp). Split from radiosity_lab.cpp, which keeps the scene, mesh and
// options.
#include "radiosity_lab_class.h"

#include "core/i18n.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <mutex>
#include <string>
#include <thread>

namespace wb {

// 2. Solving: one step here, or a run on a worker thread that publishes snapshots.
void RadiosityLab::stepOnce() {
    if (!model_) return;
    const auto t0 = std::chrono::steady_clock::now();
    try {
        model_->solver->step();
    } catch (const std::exception& e) {
        message_ = e.what();
    }
    lastStepSeconds_ = secondsSince(t0);
#if !defined(WB_HEADLESS)
    // Below 5% by hand: said here with the steps, not later by `r` as "after 0.00 s".
    const double before = snapshot().residual, now = model_->solver->residual();
    if (before >= 0.05 && now < 0.05) {
        std::printf("lab08: unshot power < 5%% after %d steps by hand (space)\n",
                    model_->solver->steps());
        std::fflush(stdout);
    }
#endif
    publish();
}

bool RadiosityLab::overBudget() const {
#if defined(WB_HEADLESS)
    return secondsSince(labStart_) > s.budget;
#else
    return false; // in a window any key stops a run
#endif
}

// Steps a run may reach: the solver's own cap, and --steps for the automatic headless solve.
int RadiosityLab::stepLimit() const {
    const int cap = model_->solver->config().maxSteps;
    return autoRun_ && s.maxSteps >= 0 ? std::min(cap, s.maxSteps) : cap;
}

void RadiosityLab::startRun() {
    if (!model_ || running()) return;
    // `r` on a solution already at the tolerance has nothing to run: it used to log "unshot
    // power < 5% after 0.00 s" and put "last run 0.00 s" over the run that converged.
    if (model_->solver->residual() < s.tolerance) {
#if !defined(WB_HEADLESS)
        std::printf(
            "lab08: already converged (residual %.2e < %.0e after %d steps): nothing to run\n",
            model_->solver->residual(), s.tolerance, model_->solver->steps());
        std::fflush(stdout);
#endif
        return;
    }
    // A run that ended by itself leaves its thread joinable: assigning a new one to it would
    // call std::terminate (r after a finished run on a worker method crashed the lab).
    if (worker_.joinable()) worker_.join();
    cancel_ = false;
    running_ = true;
    runStart_ = std::chrono::steady_clock::now();
    runSeconds_ = 0;
    // Already below 5% (a run stopped by a key, then `r`): the times it got there stay.
    if (model_->solver->residual() >= 0.05) {
        usableSeconds_ = -1;
        shownSeconds_ = -1;
    }
    usableBefore_ = usableSeconds_ < 0 && model_->solver->residual() < 0.05;
    stepSeconds_ = 0;
    // A fresh solve starts with the preview (radiosity_preview.cpp); a run resumed after a key
    // stopped it goes on where it was.
    rad::Solver* preview = runPreview() ? model_->preview.solver.get() : nullptr;
    previewPhase_ = preview != nullptr;
    if (s.method == FfMethod::GlHemicube) {
        // GL rows need the GL thread: draw() takes steps for ~30 ms per frame instead.
        mainThreadRun_ = true;
        return;
    }
    rad::Solver* solver = model_->solver.get();
    const double tol = s.tolerance;
    const int limit = stepLimit();
    worker_ = std::thread([this, solver, preview, tol, limit] {
        // One phase: the preview's solver to its tolerance, then the full solve's.
        auto phase = [this](rad::Solver& sol, double tolerance, int cap, bool isPreview) {
            auto lastPublish = std::chrono::steady_clock::now();
            while (!cancel_.load() && sol.residual() >= tolerance && sol.steps() < cap) {
                if (overBudget()) {
                    budgetHit_ = true;
                    return false;
                }
                try {
                    const auto t0 = std::chrono::steady_clock::now();
                    sol.step();
                    stepSeconds_ = stepSeconds_ + secondsSince(t0);
                } catch (const std::exception& e) {
                    std::lock_guard<std::mutex> lock(snapMutex_);
                    workerError_ = e.what();
                    return false;
                }
                // At most ~30 snapshots a second (copying B per shot would dominate at 10k
                // patches), and at once when the picture becomes usable or the full solve
                // overtakes the preview.
                const bool now = (usableSeconds_ < 0 && sol.residual() < 0.05) ||
                                 (!isPreview && previewShown_ && sol.residual() < previewResidual_);
                if (now || secondsSince(lastPublish) > 0.033) {
                    publish(sol, isPreview);
                    lastPublish = std::chrono::steady_clock::now();
                }
            }
            return !cancel_.load();
        };
        bool go = true;
        if (preview) {
            go = phase(*preview, preview->config().tolerance, preview->config().maxSteps, true);
            publish(*preview, true);
            if (go) finishPreview();
        }
        if (go) phase(*solver, tol, limit, false);
        publish(*solver, false, !cancel_.load());
        runSeconds_ = secondsSince(runStart_);
        running_ = false;
        reportRun();
    });
}

void RadiosityLab::stopRun() {
    cancel_ = true;
    if (worker_.joinable()) worker_.join();
    // A worker's run reports its own end; a GL run stopped between slices has no one else to
    // say so (a key stopping it printed nothing).
    const bool stoppedGlRun = mainThreadRun_;
    if (stoppedGlRun) runSeconds_ = secondsSince(runStart_);
    mainThreadRun_ = false;
    if (stoppedGlRun && model_) reportRun();
    previewPhase_ = false;
    skipSlice_ = false;
    running_ = false;
}

// Waits for a run to end by itself (headless scripts).
void RadiosityLab::finishRun() {
    if (worker_.joinable()) worker_.join();
    while (mainThreadRun_)
        stepOnMainThread(true);
    running_ = false;
}

// The GL method's run: steps until the frame's time budget is spent (headless: to the end).
void RadiosityLab::stepOnMainThread(bool headless, bool (*inputWaiting)()) {
    if (!mainThreadRun_ || !model_) return;
    const bool isPreview = previewPhase_ && model_->preview.solver;
    rad::Solver& sol = isPreview ? *model_->preview.solver : *model_->solver;
    const double tol = isPreview ? sol.config().tolerance : s.tolerance;
    const int limit = isPreview ? sol.config().maxSteps : stepLimit();
    const auto t0 = std::chrono::steady_clock::now();
    bool show = false; // a picture to show at once: the next frame skips its slice
    try {
        // Up to 0.25 s of steps a frame: the first shots draw a GL hemicube each (~20 ms at
        // 512², the old default; less at 128²), and a frame of 3.7k patches takes ~50 ms to
        // draw here; 30 ms slices made convergence 3× slower in a window than headless
        // (measured at 512²: 1.2-1.3 s against 0.7 s). The slice ends early when the picture
        // becomes usable or the full solve overtakes the preview, and when the user's input
        // waits (a key, a click, a drag): it used to wait for the rest of the slice, up to
        // 0.25 s. Past kMinSlice only, so that a drag's stream of motion still leaves the run
        // most of the time (docs/bench/radiosity.md, "Input during a GL run").
        constexpr double kSlice = 0.25, kMinSlice = 0.02;
        while (sol.residual() >= tol && sol.steps() < limit &&
               (headless || secondsSince(t0) < kSlice)) {
            if (overBudget()) {
                budgetHit_ = true;
                break;
            }
            sol.step();
            if (!headless && ((usableSeconds_ < 0 && sol.residual() < 0.05) ||
                              (!isPreview && previewShown_ && sol.residual() < previewResidual_))) {
                show = true;
                break;
            }
            if (inputWaiting && secondsSince(t0) >= kMinSlice && inputWaiting()) break;
        }
    } catch (const std::exception& e) {
        message_ = e.what();
        mainThreadRun_ = false;
    }
    const bool ended = sol.residual() < tol || sol.steps() >= limit || budgetHit_;
    if (isPreview) {
        publish(sol, true);
        if (ended && !budgetHit_) finishPreview(); // the full solve goes on in the next slice
        if (budgetHit_) mainThreadRun_ = false;
    } else {
        if (ended) mainThreadRun_ = false;
        publish(sol, false, !mainThreadRun_);
    }
    stepSeconds_ = stepSeconds_ + secondsSince(t0);
    skipSlice_ = show && mainThreadRun_;
    if (!mainThreadRun_) {
        runSeconds_ = secondsSince(runStart_);
        running_ = false;
        reportRun();
    }
}

// In a window, the end of a run on stdout (the figures of docs/bench/radiosity.md's window
// table come from these lines).
void RadiosityLab::reportRun() const {
#if !defined(WB_HEADLESS)
    // The full solve's own figures (the snapshot may still be the preview's when a key stopped
    // the run); called on the thread that stepped it, after its last step.
    const rad::Solver& sol = *model_->solver;
    std::printf("lab08: %s run %.2f s (solving %.2f s), %d steps, residual %.2e%s\n",
                s.method == FfMethod::Rays          ? "rays"
                : s.method == FfMethod::CpuHemicube ? "CPU"
                                                    : "GL",
                runSeconds_.load(), stepSeconds_.load(), sol.steps(), sol.residual(),
                cancel_.load() ? " (stopped)" : "");
    std::fflush(stdout);
#endif
}

// Copies what drawing needs out of a solver (called by the worker while it runs, or here):
// the preview's, or the full solve's once it overtakes the preview (its unshot light below the
// preview's) or at the end of its run (`last`).
void RadiosityLab::publish(const rad::Solver& sol, bool preview, bool last) {
    RadiositySnapshot snap;
    snap.residual = sol.residual();
    snap.steps = sol.steps();
    snap.preview = preview;
    if (!preview && previewShown_) {
        fullSteps_ = snap.steps;
        if (!(snap.residual < previewResidual_) && !last) return; // the preview stays
        previewShown_ = false;
        frameWanted_ = true;
#if !defined(WB_HEADLESS)
        if (running())
            std::printf("lab08: the full solve replaces the preview after %.2f s (unshot %.2e)\n",
                        secondsSince(runStart_), snap.residual);
        std::fflush(stdout);
#endif
    }
    if (preview) previewShown_ = true;
    snap.B = sol.displayRadiosity();
    snap.history = sol.history();
    snap.lastShooter = sol.lastShooter();
    // "Usable": unshot power below 5% of the emitted (docs/bench/radiosity.md §4).
    if (running() && usableSeconds_ < 0 && !usableBefore_ && snap.residual < 0.05) {
        usableSeconds_ = secondsSince(runStart_);
        frameWanted_ = true;
#if !defined(WB_HEADLESS)
        std::printf("lab08: unshot power < 5%% after %.2f s%s\n", usableSeconds_.load(),
                    preview ? " (the preview at coarse shooting patches)" : "");
        std::fflush(stdout);
#endif
    }
    std::lock_guard<std::mutex> lock(snapMutex_);
    snap.version = snapshot_.version + 1;
    snapshot_ = std::move(snap);
}

std::string RadiosityLab::summary() const {
    if (!model_) return message_;
    const RadiositySnapshot snap = snapshot();
    const rad::FormFactors& ff = *model_->ff;
    const char* methods[] = {"rays", "CPU hemicube", "GL hemicube"};
    char line[512];
    std::snprintf(line, sizeof line,
                  "%s: %zu patches (edge %.4f m, %zu shooting), %s, %d steps, residual %.2e, form "
                  "factors %.2f s (%lld rows, %.1f MiB)",
                  model_->scene.name.c_str(), model_->mesh.patches.size(), s.patchSize,
                  model_->mesh.groups.size(), methods[int(s.method)], snap.steps, snap.residual,
                  ff.seconds(), ff.rowsComputed(), double(ff.bytes()) / (1024.0 * 1024.0));
    std::string out = line;
    if (runSeconds_ > 0) out += wb::trf(", last run %.2f s", runSeconds_.load());
    const PreviewError pe = previewError();
    if (pe.ran && !previewShown_)
        out +=
            wb::trf("; the preview was off the answer by %.2f%% RMS, %+.2f%% on %s (worst surface)",
                    100.0 * pe.rms, 100.0 * pe.worst, pe.surface.c_str());
    if (budgetHit_)
        out += wb::trf(
            "; stopped at the budget of %g s (--budget): the picture is the solution so far",
            s.budget);
    return out;
}

// Headless: one line per solution state drawn (the command-line front end's report).
void RadiosityLab::printSummary() {
    const RadiositySnapshot snap = snapshot();
    if (snap.version == printedVersion_) return;
    printedVersion_ = snap.version;
    std::printf("%s\n", summary().c_str());
    std::fflush(stdout);
}

} // namespace wb
