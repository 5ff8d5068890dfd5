// Issue 19 item 12: the converged Cornell box's area-mean radiosity per surface, for comparing
// with an independent path tracer (scripts/bench/radiosity_reference.py, Blender's Cycles).
// Writes a JSON file with the scene (every surface's corners, reflectivity, emission) and, for
// each setting given, the per-surface mean B over the surface's EXPOSED part (points inside a
// block, e.g. the floor under it, are seen by nobody and left out, as the reference's camera
// cannot see them either).
//
//   radiosity_reference --out ours.json [--setting NAME:PATCH_M:METHOD:RES_OR_K[:SHOOTER_M[:TOL]]
//   ...] METHOD = hemicube (CPU hemicube, RES²) or rays (k rays, Auto kernel); SHOOTER_M > PATCH_M:
//   progressive shoots from groups of about that edge (MeshConfig::shooterEdge); TOL: stop at
//   that unshot power / emitted (default 1e-5), B shown with the ambient term as the lab does.
// METHOD grouprays = lab 08's key 1 with groups (rays at the receivers, point_rays.h); gl = lab
// 08's key 3: rows by the lab's GL hemicube (labs/08-radiosity/gl_hemicube.h, drawn through
// OSMesa here, the lab's display triangles and near distance); PATCH_M and SHOOTER_M "lab" =
// lab 08's default edges.
// Default settings: `settings.empty()` below. --conforming (before the settings): mesh with
// MeshConfig::conforming (issue 19 item 10's conforming mesh; "lab" edges then from its count).
// Experiments (docs/bench/radiosity.md, "Why ours was off"): --black-except NAME sets every
// other surface's R to 0 (NAME's direct light only); WB_RADREF_NEAR=r sets
// FormFactorConfig::groupNearField; WB_RADREF_FLOORF=1 prints Σ F(light patch -> floor).
#include "gl_hemicube.h"
#include "patch_view.h"

#include "common/headless_context.h"
#include "core/radiosity/point_rays.h"
#include "core/radiosity/ray_form_factors.h"
#include "core/radiosity/scenes.h"
#include "core/radiosity/solver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace wb::rad;

namespace {

bool gConforming = false; // --conforming

MeshConfig meshConfig(double maxEdge, double shooterEdge) {
    MeshConfig c{maxEdge, shooterEdge};
    c.conforming = gConforming;
    return c;
}

struct Setting {
    std::string name;
    double patch = 0.05;
    std::string method = "hemicube";
    int resOrK = 128;
    double shooter = 0.0;    // MeshConfig::shooterEdge (0: every patch shoots itself)
    double tolerance = 1e-5; // unshot power / emitted at the stop
};

// Lab 08's default patch edge (RadiosityLab::defaultPatchSize, copied: the lab's class is not
// in core): e = √(A/3700), corrected twice by the count the mesher makes of it. The Cornell
// box: 0.02359 m, 3,658 patches (3,716 before the fifth session's sliver cells); its shooting groups are 4.25 e for every method
// (kShooterPatches).
double labPatch(const Scene& scene) {
    double area = 0;
    for (const Surface& sf : scene.surfaces)
        area += polygonArea(sf.vertices);
    double e = std::sqrt(area / 3700.0);
    for (int pass = 0; pass < 2; ++pass)
        e *= std::sqrt(double(meshScene(scene, meshConfig(e, 0.0)).patches.size()) / 3700.0);
    return e;
}

Setting parse(const std::string& s) {
    Setting out;
    std::stringstream ss(s);
    std::string part;
    std::vector<std::string> parts;
    while (std::getline(ss, part, ':'))
        parts.push_back(part);
    if (parts.size() < 4 || parts.size() > 6)
        throw std::invalid_argument(
            "--setting NAME:PATCH:METHOD:RES_OR_K[:SHOOTER_EDGE[:TOLERANCE]], got " + s);
    // "lab": lab 08's default patch edge; a shooter edge "lab" is 4.25 of it (every method's
    // groups, kShooterPatches).
    const bool labShooter = parts.size() > 4 && parts[4] == "lab";
    const double lab = parts[1] == "lab" || labShooter ? labPatch(cornellBox()) : 0.0;
    if (parts.size() > 4)
        out.shooter = parts[4] == "lab" ? 4.25 * lab : std::stod(parts[4]);
    if (parts.size() > 5) out.tolerance = std::stod(parts[5]);
    out.name = parts[0];
    out.patch = parts[1] == "lab" ? lab : std::stod(parts[1]);
    out.method = parts[2];
    out.resOrK = std::stoi(parts[3]);
    if (out.method != "hemicube" && out.method != "rays" && out.method != "grouprays" &&
        out.method != "p2p" && out.method != "grouppool" && out.method != "gl")
        throw std::invalid_argument("method " + out.method);
    return out;
}

// Per surface: Σ B·A / Σ A over the patches. meshScene already gives each patch its EXPOSED
// area (the part inside a body, e.g. the floor under a block, is seen by nobody and left out,
// as the references leave it out). Before, this bench sampled each patch's exposure again and
// multiplied the (already exposed) area by it: the patches straddling the blocks' outlines,
// darker than the floor's mean, were counted with f² of their area instead of f, and the floor
// read 1-3% bright (the exposed floor area 0.2435 m² instead of 0.2531 at 0.05 m).
std::vector<glm::dvec3> surfaceMeans(const PatchMesh& m, const std::vector<glm::dvec3>& B,
                                     std::vector<double>& exposedArea) {
    const std::size_t ns = m.surfaces.size();
    std::vector<glm::dvec3> sum(ns, glm::dvec3(0.0));
    exposedArea.assign(ns, 0.0);
    for (std::size_t i = 0; i < m.patches.size(); ++i) {
        const Patch& p = m.patches[i];
        sum[static_cast<std::size_t>(p.surface)] += p.area * B[i];
        exposedArea[static_cast<std::size_t>(p.surface)] += p.area;
    }
    for (std::size_t s = 0; s < ns; ++s)
        if (exposedArea[s] > 0) sum[s] /= exposedArea[s];
    return sum;
}

std::string vec(const glm::dvec3& v) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "[%.9g, %.9g, %.9g]", v.x, v.y, v.z);
    return buf;
}

// Experiment (WB_RADREF_POOLDIAG=NAME, p2p settings with groups in the mesh): what pooling in
// the shooting groups would change, to first order, in the mean of the surfaces whose name
// contains NAME. Over the whole solve, member m shoots B_m − E_m in total; pooled, the group
// shoots their area mean along F̄_gj = Σ_m A_m F_mj / A_g instead of each along F_mj, so a
// receiver j outside g's near field gets R_j Σ_m A_m (B_m − E_m)(F̄_gj − F_mj) / A_j too much.
void poolDiagnosis(const PatchMesh& mesh, const FormFactors& ff, const std::vector<glm::dvec3>& B,
                   const std::string& want) {
    const std::size_t n = mesh.patches.size();
    std::vector<float> scratch;
    struct Item {
        double err;
        int g;
        std::string surface;
    };
    for (std::size_t s = 0; s < mesh.surfaces.size(); ++s) {
        const std::string& name = mesh.surfaces[s].name;
        if (name.find(want) == std::string::npos) continue;
        double area = 0, mean = 0;
        for (std::size_t j = 0; j < n; ++j)
            if (mesh.patches[j].surface == static_cast<int>(s)) {
                area += mesh.patches[j].area;
                mean += mesh.patches[j].area * B[j].y;
            }
        mean /= area;
        std::vector<Item> items;
        double total = 0;
        for (std::size_t g = 0; g < mesh.groups.size(); ++g) {
            const ShooterGroup& sg = mesh.groups[g];
            const GroupNearField* nf = ff.nearField(static_cast<int>(g));
            if (nf && nf->everyReceiver) continue;
            std::vector<char> nearJ(n, 0);
            if (nf)
                for (int j : nf->receivers)
                    nearJ[static_cast<std::size_t>(j)] = 1;
            std::vector<double> fbar(n, 0.0);
            std::vector<std::vector<float>> rows;
            for (int m : sg.members) {
                const float* f = ff.row(m, scratch);
                rows.emplace_back(f, f + n);
                for (std::size_t j = 0; j < n; ++j)
                    fbar[j] += mesh.patches[static_cast<std::size_t>(m)].area * f[j] / sg.area;
            }
            double err = 0;
            for (std::size_t j = 0; j < n; ++j) {
                if (mesh.patches[j].surface != static_cast<int>(s) || nearJ[j]) continue;
                for (std::size_t k = 0; k < sg.members.size(); ++k) {
                    const auto m = static_cast<std::size_t>(sg.members[k]);
                    err += mesh.patches[j].reflectivity.y * mesh.patches[m].area *
                           (B[m].y - mesh.patches[m].emission.y) * (fbar[j] - rows[k][j]);
                }
            }
            err /= area * mean;
            total += err;
            items.push_back({err, static_cast<int>(g),
                             mesh.surfaces[static_cast<std::size_t>(sg.surface)].name});
        }
        std::sort(items.begin(), items.end(),
                  [](const Item& a, const Item& b) { return std::abs(a.err) > std::abs(b.err); });
        std::fprintf(stderr, "POOL %s: first-order pooling error of the mean (G) %+.3f%%\n",
                     name.c_str(), 100 * total);
        for (std::size_t k = 0; k < std::min<std::size_t>(items.size(), 10); ++k) {
            const ShooterGroup& sg = mesh.groups[static_cast<std::size_t>(items[k].g)];
            std::fprintf(stderr, "   group %3d %-26s centre %.3f %.3f %.3f members %zu: %+.3f%%\n",
                         items[k].g, items[k].surface.c_str(), sg.centre.x, sg.centre.y,
                         sg.centre.z, sg.members.size(), 100 * items[k].err);
        }
    }
}

} // namespace

int main(int argc, char** argv) {
    std::string outPath = "radiosity_reference_ours.json";
    std::vector<Setting> settings;
    std::string keepLit; // --black-except NAME: every other surface's R set to 0 (experiments)
    try {
        for (int a = 1; a < argc; ++a) {
            const std::string arg = argv[a];
            if (arg == "--out" && a + 1 < argc)
                outPath = argv[++a];
            else if (arg == "--conforming")
                gConforming = true;
            else if (arg == "--black-except" && a + 1 < argc)
                keepLit = argv[++a];
            else if (arg == "--setting" && a + 1 < argc)
                settings.push_back(parse(argv[++a]));
            else
                throw std::invalid_argument("unknown argument " + arg);
        }
    } catch (const std::exception& e) {
        std::cerr << "radiosity_reference: " << e.what() << "\n";
        return 2;
    }
    if (settings.empty())
        settings = {// Lab 08's defaults (radiosity_lab.h): the lab's patch edge (3,658 patches),
                    // shooting groups of 4.25 patches (0.10 m), stop at unshot 1e-4, rows by the
                    // keys' methods: rays k = 4
                    // gathered at the receivers (key 1, the default), CPU hemicube 128² (key 2),
                    // GL hemicube 128² (key 3: the lab's GL hemicube, drawn through OSMesa;
                    // until the fifth session core's CPU hemicube stood in for it and this
                    // column repeated the CPU one).
                    parse("default, rays k=4:lab:grouprays:4:lab:1e-4"),
                    // 0.14 m groups for the hemicubes (lab08fast) put the ceiling left of the
                    // light 1.13% off once the plane fit came (docs/bench/radiosity.md).
                    parse("default, CPU hemicube 128:lab:hemicube:128:lab:1e-4"),
                    parse("default, GL hemicube 128:lab:gl:128:lab:1e-4"),
                    // Finer: patches and groups √2 smaller, k = 16, stop at 1e-4.
                    parse("fine, rays k=16:0.0167:grouprays:16:0.071:1e-4")};
    Scene scene = cornellBox();
    if (!keepLit.empty())
        for (Surface& f : scene.surfaces)
            if (f.name.find(keepLit) == std::string::npos) f.reflectivity = glm::dvec3(0.0);
    std::ostringstream js;
    js << "{\n  \"scene\": \"" << scene.name << "\",\n  \"surfaces\": [\n";
    for (std::size_t s = 0; s < scene.surfaces.size(); ++s) {
        const Surface& f = scene.surfaces[s];
        js << "    {\"name\": \"" << f.name << "\", \"vertices\": [";
        for (std::size_t k = 0; k < f.vertices.size(); ++k)
            js << (k ? ", " : "") << vec(f.vertices[k]);
        js << "], \"reflectivity\": " << vec(f.reflectivity)
           << ", \"emission\": " << vec(f.emission) << "}"
           << (s + 1 < scene.surfaces.size() ? "," : "") << "\n";
    }
    js << "  ],\n  \"settings\": [\n";
    for (std::size_t k = 0; k < settings.size(); ++k) {
        const Setting& st = settings[k];
        const auto t0 = std::chrono::steady_clock::now();
        const PatchMesh mesh = meshScene(scene, meshConfig(st.patch, st.shooter));
        FormFactorConfig fc;
        if (st.method == "rays" || st.method == "grouprays" || st.method == "p2p" ||
            st.method == "grouppool") {
            fc.method = FormFactorMethod::Rays;
            fc.rays.samples = st.resOrK;
            // p2p: every pair by the exact point-to-polygon kernel (k points on the shooter,
            // visibility rays), the nearest to exact F the core has for a whole mesh.
            if (st.method != "rays" && st.method != "grouprays")
                fc.rays.kernel = RayKernel::PointToPolygon;
        } else {
            fc.method = st.method == "gl" ? FormFactorMethod::External : FormFactorMethod::Hemicube;
            fc.hemicubeResolution = st.resOrK;
        }
        const FormFactors* ffp = nullptr;
        // gl: as RadiosityLab::rebuildSolver and glRow do for key 3: the lab's display triangles
        // (PatchView::hemicubeGeometry), near distance kNearFraction × the mesh's radius, the
        // delta table's resolution; patch rows and group rows both drawn by GL, on this thread.
        std::unique_ptr<wb::HeadlessContext> glContext;
        std::unique_ptr<wb::GlHemicube> glHemicube;
        ItemBuffer glItems;
        double glNear = 0.0;
        if (st.method == "gl") {
            glContext = std::make_unique<wb::HeadlessContext>(64, 64); // the hemicube has its own FBO
            if (!glContext->ok()) {
                std::cerr << "radiosity_reference: no OSMesa context for the GL hemicube\n";
                return 1;
            }
            wb::PatchView view;
            view.setMesh(mesh);
            std::vector<glm::vec3> verts;
            std::vector<uint32_t> items;
            view.hemicubeGeometry(verts, items);
            glHemicube = std::make_unique<wb::GlHemicube>();
            std::string err;
            if (!glHemicube->setGeometry(verts, items, err)) {
                std::cerr << "radiosity_reference: " << err << "\n";
                return 1;
            }
            glm::dvec3 lo(1e300), hi(-1e300);
            for (const glm::dvec3& v : mesh.vertices) {
                lo = glm::min(lo, v);
                hi = glm::max(hi, v);
            }
            glNear = wb::GlHemicube::kNearFraction * std::max(0.5 * glm::length(hi - lo), 1e-9);
        }
        auto glRow = [&](const HemicubeFrame& frame, int self, std::vector<float>& out) {
            std::string err;
            const int res = ffp->deltaTable().resolution;
            if (!glHemicube->render(frame, res, glNear, glItems, err)) throw std::runtime_error(err);
            accumulate(glItems, ffp->deltaTable(), static_cast<int>(mesh.patches.size()), self, out);
        };
        if (st.method == "gl") {
            fc.rowProvider = [&](int i, std::vector<float>& out) { glRow(hemicubeFrame(mesh, i), i, out); };
            fc.groupRowProvider = [&](int, const HemicubeFrame& fr, std::vector<float>& out) { glRow(fr, -1, out); };
        }
        // grouprays: lab 08's rays method (key 1) with shooting groups: each receiver gathers
        // from the group's outline (core/radiosity/point_rays.h), as the lab's provider does.
        if (st.method == "grouprays")
            fc.groupRowProvider = [&mesh, &ffp, k = st.resOrK](int g, const HemicubeFrame&,
                                                               std::vector<float>& out) {
                groupGatherRow(mesh, ffp->bvh(), g, k, out, ffp->nearFieldReady(g));
            };
        // grouppool: a group's row is the area-weighted sum of its members' p2p rows (the
        // pooled row made exact: what is left is the pooling itself, not how rows are made).
        if (st.method == "grouppool")
            fc.groupRowProvider = [&mesh, &ffp, fc](int g, const HemicubeFrame&,
                                                    std::vector<float>& out) {
                const ShooterGroup& sg = mesh.groups[static_cast<std::size_t>(g)];
                out.assign(mesh.patches.size(), 0.0f);
                std::vector<double> acc(mesh.patches.size(), 0.0);
                std::vector<float> row;
                for (int m : sg.members) {
                    rayFormFactorRow(mesh, ffp->bvh(), m, fc.rays, row);
                    const double a = mesh.patches[static_cast<std::size_t>(m)].area;
                    for (std::size_t j = 0; j < row.size(); ++j)
                        acc[j] += a * row[j];
                }
                for (std::size_t j = 0; j < acc.size(); ++j)
                    out[j] = static_cast<float>(acc[j] / sg.area);
            };
        if (const char* nf = std::getenv("WB_RADREF_NEAR")) fc.groupNearField = std::atof(nf);
        FormFactors ff(mesh, fc);
        ffp = &ff;
        SolverConfig sc;
        sc.kind = SolverKind::Progressive;
        sc.ambient = true;
        sc.tolerance = st.tolerance;
        if (std::getenv("WB_RADREF_FLOORF")) { // experiment: Σ F(light patch -> floor) per row
            std::vector<float> scratch;
            for (std::size_t i = 0; i < mesh.patches.size(); ++i) {
                if (glm::length(mesh.patches[i].emission) == 0) continue;
                const float* f = ff.row(static_cast<int>(i), scratch);
                double sf = 0, all = 0;
                for (std::size_t j = 0; j < mesh.patches.size(); ++j) {
                    all += f[j];
                    if (mesh.patches[j].surface == 0) sf += f[j];
                }
                std::fprintf(stderr, "row %zu centre %.4f %.4f floor %.6f all %.6f\n", i,
                             mesh.patches[i].centre.x, mesh.patches[i].centre.z, sf, all);
            }
        }
        // p2p with groups in the mesh: still every patch shooting itself.
        if (st.method == "p2p") sc.groupShooting = false;
        Solver solver(mesh, ff, sc);
        solver.run();
        if (const char* want = std::getenv("WB_RADREF_POOLDIAG"); want && st.method == "p2p")
            poolDiagnosis(mesh, ff, solver.radiosity(), want);
        const double secs =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::vector<double> area;
        const auto means = surfaceMeans(mesh, solver.displayRadiosity(), area);
        std::cerr << st.name << ": " << mesh.patches.size() << " patches, " << mesh.groups.size()
                  << " groups, " << solver.steps() << " shots, residual " << solver.residual()
                  << ", " << secs << " s\n";
        js << "    {\"name\": \"" << st.name << "\", \"patch\": " << st.patch << ", \"method\": \""
           << st.method << "\", \"res_or_k\": " << st.resOrK << ", \"shooter\": " << st.shooter
           << ", \"groups\": " << mesh.groups.size() << ", \"tolerance\": " << st.tolerance
           << ", \"patches\": " << mesh.patches.size() << ", \"residual\": " << solver.residual()
           << ", \"seconds\": " << secs << ", \"means\": [";
        for (std::size_t s = 0; s < means.size(); ++s)
            js << (s ? ", " : "") << vec(means[s]);
        js << "], \"exposed_area\": [";
        for (std::size_t s = 0; s < area.size(); ++s)
            js << (s ? ", " : "") << area[s];
        js << "]}" << (k + 1 < settings.size() ? "," : "") << "\n";
    }
    js << "  ]\n}\n";
    std::ofstream(outPath) << js.str();
    std::cerr << "wrote " << outPath << "\n";
    return 0;
}
