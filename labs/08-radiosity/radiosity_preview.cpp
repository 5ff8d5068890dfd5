// Lab 08: the preview phase of a run (issue 19 item 7: a usable picture in < 1 s for every
// method). With the default 0.10 m shooting patches nearly every one of the 252 groups must
// shoot once before the unshot light is under 5% of the emitted (239 of 252 in the Cornell box),
// so "usable" came at ~95% of "converged". A run therefore first solves the same patches
// shooting from coarse groups (kPreviewGroupScale × the default's edge: 0.30 m, 37 groups in
// the Cornell box, the configuration of issue 10's bench goal) by rays, with the near field of
// the light only, and shows that as soon as its unshot light is < 5%; the full solve follows and
// replaces it once its own unshot light is below the preview's (or it has converged). The full
// solve's answer is exactly what it was without a preview (its own mesh, form factors and
// solver; the tests compare it bit for bit). The preview's error against the converged answer
// is in docs/bench/radiosity.md, "l08fast: a preview at coarse shooting patches".
#include "radiosity_lab_class.h"

#include "core/radiosity/point_rays.h"

#include <cmath>
#include <map>
#include <tuple>

namespace wb {

namespace {

// The fine mesh's groups binned into coarse ones: per surface, a grid of ~edge-sized cells in
// the surface's u, v axes (split evenly over its extent), each fine group going to the cell of
// its centroid. The patches are the same (the preview's B is drawn on them). A coarse group's
// centre is its member centre nearest to the area-weighted centroid: where bodies stand on a
// surface the centroid of what is left can lie under a body, and a hemicube from there would
// see its inside.
rad::PatchMesh coarseGroups(const rad::PatchMesh& fine, double edge) {
    rad::PatchMesh out = fine;
    out.groups.clear();
    for (rad::Patch& p : out.patches) p.group = -1;
    struct Axes {
        glm::dvec3 o{0.0}, u{0.0}, v{0.0};
        double lu = 0, lv = 0;
        int nu = 1, nv = 1;
    };
    std::map<int, Axes> axes; // per surface with groups
    std::map<std::tuple<int, int, int>, int> cellGroup;
    for (const rad::ShooterGroup& sg : fine.groups) {
        // The light's groups stay as they are (few, and shot member by member anyway).
        if (glm::length(fine.surfaces[size_t(sg.surface)].emission) > 0.0) {
            for (int m : sg.members) out.patches[size_t(m)].group = int(out.groups.size());
            out.groups.push_back(sg);
            continue;
        }
        auto it = axes.find(sg.surface);
        if (it == axes.end()) {
            Axes a;
            const rad::Surface& sf = fine.surfaces[size_t(sg.surface)];
            a.u = sg.u;
            a.v = glm::cross(sg.normal, sg.u);
            double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
            for (const glm::dvec3& c : sf.vertices) {
                u0 = std::min(u0, glm::dot(c, a.u));
                u1 = std::max(u1, glm::dot(c, a.u));
                v0 = std::min(v0, glm::dot(c, a.v));
                v1 = std::max(v1, glm::dot(c, a.v));
            }
            a.o = glm::dvec3(u0, v0, 0.0);
            a.lu = u1 - u0;
            a.lv = v1 - v0;
            a.nu = std::max(1, int(std::ceil(a.lu / edge - 1e-9)));
            a.nv = std::max(1, int(std::ceil(a.lv / edge - 1e-9)));
            it = axes.emplace(sg.surface, a).first;
        }
        const Axes& a = it->second;
        const double x = (glm::dot(sg.centre, a.u) - a.o.x) / std::max(a.lu, 1e-300);
        const double y = (glm::dot(sg.centre, a.v) - a.o.y) / std::max(a.lv, 1e-300);
        const int iu = std::clamp(int(std::floor(x * a.nu)), 0, a.nu - 1);
        const int iv = std::clamp(int(std::floor(y * a.nv)), 0, a.nv - 1);
        auto [cell, added] =
            cellGroup.emplace(std::make_tuple(sg.surface, iu, iv), int(out.groups.size()));
        if (added) {
            rad::ShooterGroup g;
            g.surface = sg.surface;
            g.normal = sg.normal;
            g.u = sg.u;
            out.groups.push_back(g);
        }
        rad::ShooterGroup& g = out.groups[size_t(cell->second)];
        for (int m : sg.members) {
            g.members.push_back(m);
            out.patches[size_t(m)].group = cell->second;
        }
        g.area += sg.area;
        g.centre += sg.area * sg.centre;
    }
    for (rad::ShooterGroup& g : out.groups) {
        if (glm::length(fine.surfaces[size_t(g.surface)].emission) > 0.0) continue;
        const glm::dvec3 centroid = g.centre / g.area;
        double best = 1e300;
        for (int m : g.members) {
            const double d = glm::length(out.patches[size_t(m)].centre - centroid);
            if (d < best) {
                best = d;
                g.centre = out.patches[size_t(m)].centre;
            }
        }
    }
    return out;
}

} // namespace

void RadiosityLab::buildPreview(const rad::FormFactorConfig& full, const rad::SolverConfig& sc) {
    Model::Preview& pv = model_->preview;
    pv.solver.reset();
    pv.ff.reset();
    pv.mesh = rad::PatchMesh{};
    previewPhase_ = false;
    previewShown_ = false;
    previewResidual_ = 1.0;
    previewB_.clear();
    // Progressive with shooting groups only; and only when the coarse groups are much fewer
    // (a mesh whose groups are already coarse gains nothing from a preview).
    if (!previewOption_ || sc.kind != rad::SolverKind::Progressive || model_->mesh.groups.empty())
        return;
    pv.mesh = coarseGroups(model_->mesh, kPreviewGroupScale * s.shooterEdge);
    if (pv.mesh.groups.size() * 2 > model_->mesh.groups.size()) {
        pv.mesh = rad::PatchMesh{};
        return;
    }
    rad::FormFactorConfig fc = full;
    // Only the light's near field (every receiver, member by member: an emitter's groups always
    // get it, form_factors.cpp): from the light's centre by the hemicube the tall block's front
    // came out speckled. Around the other groups none: at 0.30 m two group diagonals would hold
    // most of the box and cost more than the full solve's near fields together. No gradient
    // (its offsets cost a kernel per member and receiver: ~100 members a coarse group).
    fc.groupNearField = 1e-9;
    fc.groupGradient = false;
    fc.groupNearField = 0.0;
    // By rays gathered at the receivers for every method (keys 1 2 3): a hemicube sees the
    // group from one point, which for a 0.30 m group next to a block's face is far from the
    // group's F (the Cornell box's preview by the hemicube was 19.8% RMS off the converged
    // picture, a block face +206%; by rays 6.1%: docs/bench/radiosity.md, "l08fast"). The
    // rays are cast on the CPU, so the GL method's preview is too.
    fc.method = rad::FormFactorMethod::Rays;
    fc.rowProvider = nullptr;
    const Model::Preview* p = &pv;
    const int k = s.raySamples;
    fc.groupRowProvider = [p, k](int g, const rad::HemicubeFrame&, std::vector<float>& out) {
        rad::groupGatherRow(p->mesh, p->ff->bvh(), g, k, out, p->ff->nearFieldReady(g), false);
    };
    pv.ff = std::make_unique<rad::FormFactors>(pv.mesh, fc);
    rad::SolverConfig pc = sc;
    pc.tolerance = std::max(kPreviewTolerance, sc.tolerance);
    pv.solver = std::make_unique<rad::Solver>(pv.mesh, *pv.ff, pc);
}

bool RadiosityLab::runPreview() const {
    return model_ && model_->preview.solver && model_->solver->steps() == 0 &&
           model_->preview.solver->residual() >= model_->preview.solver->config().tolerance;
}

void RadiosityLab::finishPreview() {
    const rad::Solver& pv = *model_->preview.solver;
    previewResidual_ = pv.residual();
    previewB_ = pv.displayRadiosity();
    previewPhase_ = false;
#if !defined(WB_HEADLESS)
    std::printf("lab08: preview (%zu shooting patches of %.2f m, set up in %.3f s before the run) "
                "done after %.2f s, %d steps, unshot %.2e; the full solve (%zu shooting patches) "
                "goes on\n",
                model_->preview.mesh.groups.size(), kPreviewGroupScale * s.shooterEdge,
                previewSetupSeconds_, secondsSince(runStart_), pv.steps(), pv.residual(),
                model_->mesh.groups.size());
    std::fflush(stdout);
#endif
}

PreviewError RadiosityLab::previewError() const {
    PreviewError e;
    const std::vector<glm::dvec3> B = snapshot().B;
    if (!model_ || previewB_.size() != B.size() || B.size() != model_->mesh.patches.size())
        return e;
    const rad::PatchMesh& m = model_->mesh;
    double num = 0, den = 0;
    std::vector<double> sp(m.surfaces.size(), 0.0), sc(m.surfaces.size(), 0.0);
    for (size_t i = 0; i < B.size(); ++i) {
        const rad::Patch& p = m.patches[i];
        if (glm::length(p.emission) > 0.0) continue; // the light is E, the same in both
        const double yp = luminance(previewB_[i]), yc = luminance(B[i]);
        num += p.area * (yp - yc) * (yp - yc);
        den += p.area * yc * yc;
        sp[size_t(p.surface)] += p.area * yp;
        sc[size_t(p.surface)] += p.area * yc;
    }
    e.ran = den > 0.0;
    e.rms = e.ran ? std::sqrt(num / den) : 0.0;
    for (size_t k = 0; k < sc.size(); ++k) {
        if (!(sc[k] > 0.0)) continue;
        const double d = sp[k] / sc[k] - 1.0;
        if (std::fabs(d) > std::fabs(e.worst)) {
            e.worst = d;
            e.surface = m.surfaces[k].name;
        }
    }
    return e;
}

} // namespace wb
