// Lab 08: the panel. Its lines say what the student sees in the course's words (§ numbers of
// the course text, seed 002: §1.13 the radiosity method, §1.14 patches, §1.15 form factors,
// §1.15.1 by rays, §1.15.2 the hemicube).
#include "radiosity_lab_class.h"

#include "core/i18n.h"

#include <imgui.h>

#include <cfloat>

#include <algorithm>
#include <cmath>

namespace wb {

void RadiosityLab::gui() {
    ex_.gui();
    if (ex_.on())
        for (const std::string& line : radiosityExerciseLines(ex_))
            ImGui::TextWrapped("%s", line.c_str());
    if (!model_) {
        ImGui::TextWrapped("%s", message_.c_str());
        return;
    }
    // The shell lays the panel out before draw() (which takes the solver's snapshot) and,
    // drawing on change only, gives a run one more frame after it ends: without this the
    // panel kept the last-but-one snapshot ("iterations 303, residual 7.5e-2" after a run that
    // ended at 1198 steps, 1e-3) until the mouse moved. CPU only: colours and counters.
    updateColours();
    const rad::FormFactors& ff = *model_->ff;
    ImGui::TextWrapped("%s", tr(model_->scene.name.c_str()));
    if (!message_.empty()) ImGui::TextWrapped(tr("note: %s"), message_.c_str());
    if (drawnPreview_ && model_->preview.solver) // at the top: it says what the picture is
        // The preview's error against the converged picture: docs/bench/radiosity.md, "l08fast".
        ImGui::TextWrapped(
            "%s", wb::trf("PREVIEW: %zu large shooting patches (%.2f m), F by rays (§1.15.1) "
                          "whatever the method; walls, floor and ceiling within ~6%% of the "
                          "answer, the blocks' faces up to ~40%%. The full solve (%zu shooting patches, "
                          "%d steps so far) replaces it when less of its light is unshot.",
                          model_->preview.mesh.groups.size(), kPreviewGroupScale * s.shooterEdge,
                          model_->mesh.groups.size(), fullSteps_.load())
                      .c_str());
    ImGui::Text(tr("patches %zu (edge <= %.3f m)"), model_->mesh.patches.size(), s.patchSize);
    float edge = float(s.patchSize);
    if (ImGui::SliderFloat(wb::tr("patch edge, m"), &edge, 0.005f, 0.5f, "%.3f",
                           ImGuiSliderFlags_Logarithmic)) {
    }
    if (ImGui::IsItemDeactivatedAfterEdit()) remesh(double(edge)); // the same check as [ ]
    int method = int(s.method);
    ImGui::Text(tr("form factors:"));
    ImGui::RadioButton(tr("1 rays"), &method, 0);
    ImGui::SameLine();
    ImGui::RadioButton(tr("2 CPU"), &method, 1);
    ImGui::SameLine();
    ImGui::RadioButton(tr("3 GL"), &method, 2);
    if (method != int(s.method)) setMethod(FfMethod(method));
    if (s.method == FfMethod::Rays)
        ImGui::TextWrapped("%s",
                           wb::trf("§1.15.1: F by rays: from each patch to the shooting patch, "
                                   "exact where nothing is in the way; %d rays decide what is "
                                   "blocked.",
                                   s.raySamples)
                               .c_str());
    else
        ImGui::TextWrapped("%s", wb::trf("§1.15.2: F by the hemicube, %d×%d pixels a face, %s; "
                                         "each pixel adds its delta form factor.",
                                         hemicubeFor(s), hemicubeFor(s),
                                         s.method == FfMethod::GlHemicube
                                             ? wb::tr("drawn by OpenGL between frames")
                                             : wb::tr("rasterised on the CPU face by face, the nearest patch in each pixel"))
                                     .c_str());
    const bool groups = !model_->mesh.groups.empty() && s.solver == 0;
    ImGui::TextWrapped("%s",
                       wb::trf("§1.15: %lld rows of F computed (%s) in %.2f s", ff.rowsComputed(),
                               groups ? wb::tr("one per shooting patch") : wb::tr("one per patch"),
                               ff.seconds())
                           .c_str());
    if (groups) {
        // Why fewer rows than shooting patches (248 of 252 in the Cornell box): the light's
        // groups are shot member by member to every receiver (form_factors.cpp, nearField).
        size_t lightGroups = 0;
        for (const rad::ShooterGroup& g : model_->mesh.groups)
            if (glm::length(model_->mesh.surfaces[size_t(g.surface)].emission) > 0.0) ++lightGroups;
        if (lightGroups > 0)
            ImGui::TextWrapped(
                "%s", wb::trf("the light's shooting patches (%zu) need no row of F: each of their "
                              "patches shoots to every patch on its own (§1.14)",
                              lightGroups)
                          .c_str());
    }
    ImGui::TextWrapped("%s", wb::trf("memory for F: %.1f MiB (%s)",
                                     double(ff.bytes()) / (1024.0 * 1024.0),
                                     groups        ? wb::tr("the shooting patches' rows")
                                     : ff.stored() ? wb::tr("the whole n×n matrix")
                                                   : wb::tr("a row when a patch shoots"))
                                 .c_str());

    ImGui::Separator();
    const char* solvers[] = {tr("progressive"), tr("Jacobi"), tr("Gauss-Seidel")};
    int solver = s.solver;
    if (ImGui::Combo(tr("solver"), &solver, solvers, 3) && solver != s.solver) {
        s.solver = solver;
        rebuildSolver();
    }
    if (groups)
        ImGui::TextWrapped(
            "%s", wb::trf("§1.14: %zu shooting patches (%.2f m) shoot, %zu patches receive",
                          model_->mesh.groups.size(), s.shooterEdge, model_->mesh.patches.size())
                      .c_str());
    if (s.solver == 0) {
        // Larger shooting patches converge sooner; smaller ones are closer to the answer
        // (docs/bench/radiosity.md, "Lab 08 defaults": block faces 10-30% off at 0.31 m in the
        // Cornell box, ~1-3% at 0.10 m).
        float shooter = float(s.shooterEdge);
        // The longest slider label of the panel: ImGui's default item width (65% of the
        // panel) left it 4 px past the edge on a 1280x800 screen at UI scale 1.5 (shell's
        // --check-panel screens). The slider takes what the label leaves, in any language.
        const char* shooterLabel = wb::tr("shooting patch, m");
        ImGui::SetNextItemWidth(std::min(ImGui::CalcItemWidth(),
                                         ImGui::GetContentRegionAvail().x -
                                             ImGui::CalcTextSize(shooterLabel).x -
                                             ImGui::GetStyle().ItemInnerSpacing.x));
        ImGui::SliderFloat(shooterLabel, &shooter, 0.0f, 1.0f, "%.2f");
        if (ImGui::IsItemDeactivatedAfterEdit()) {
            shooterOption_ = double(shooter);
            s.shooterEdge = double(shooter);
            remesh(s.patchSize);
        }
    }
    ImGui::Text(tr("iterations %d, residual %.2e"), steps_, residual_);
    if (running())
        ImGui::Text(tr("running %.1f s (any key stops)"), secondsSince(runStart_));
    else if (runSeconds_ > 0)
        ImGui::Text(tr("last run %.2f s"), runSeconds_.load());
    if (usableSeconds_ >= 0)
        ImGui::TextWrapped("%s", (model_->preview.solver
                               ? wb::trf("unshot light < 5%% after %.2f s (the preview)",
                                         usableSeconds_.load())
                               : wb::trf("unshot light < 5%% after %.2f s", usableSeconds_.load()))
                              .c_str());
    if (!history_.empty()) {
        std::vector<float> lg(history_.size());
        for (size_t i = 0; i < lg.size(); ++i)
            lg[i] = float(std::log10(std::max(history_[i], 1e-12)));
        const float lo = *std::min_element(lg.begin(), lg.end());
        const float hi = *std::max_element(lg.begin(), lg.end());
        ImGui::PlotLines("##residual", lg.data(), int(lg.size()), 0, tr("log10 residual"), lo - 0.1f,
                         hi + 0.1f, ImVec2(0, 70));
    }
    float tol = float(std::log10(s.tolerance));
    if (ImGui::SliderFloat(tr("log10 tol"), &tol, -8.0f, -1.0f, "%.1f"))
        s.tolerance = std::pow(10.0, double(tol));
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
    ImGui::SameLine();
    ImGui::Checkbox(tr("p outlines"), &s.outlines);
    ImGui::Checkbox(tr("item colours (hemicube's view)"), &s.showItems);
    if (ImGui::Checkbox(wb::tr("auto exposure"), &s.autoExposure)) coloursDirty_ = true;
    ImGui::SameLine();
    if (ImGui::Checkbox(wb::tr("white balance"), &s.whiteBalance)) coloursDirty_ = true;
    const float lo = float(autoExposure_ / 30.0), hi = float(autoExposure_ * 30.0);
    if (ImGui::SliderFloat(tr("exposure"), &s.exposure, lo, hi, "%.3g",
                           ImGuiSliderFlags_Logarithmic)) {
        s.autoExposure = false; // the slider overrides the automatic exposure
        coloursDirty_ = true;
    }
    int res = hemicubeFor(s);
    if (ImGui::SliderInt(tr("hemicube"), &res, 16, 1024) && res != hemicubeFor(s))
        s.hemicubeRes = std::max(8, res & ~1);
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
        ImGui::TextWrapped("%s",
                           wb::trf("Scene: F from this patch, log scale; colour bar on the right: "
                                   "%.1e (bottom) to %.1e (top, white), a tick per decade. Upper "
                                   "right: its hemicube unfolded (top face in the middle).",
                                   selectedRowMax_ * 1e-4, selectedRowMax_)
                               .c_str());
        if (overlayTexture_ && overlaySize_ > 0)
            ImGui::Image(reinterpret_cast<ImTextureID>(uintptr_t(overlayTexture_)),
                         ImVec2(160, 160), ImVec2(0, 1), ImVec2(1, 0));
    } else {
        ImGui::TextWrapped(tr("Click a patch to see its form-factor row and its hemicube."));
    }
}

} // namespace wb
