#pragma once
// The form-factor matrix F (F_ij = fraction of the light leaving P_i that reaches P_j
// directly, 14.17/14.18) by rays or by the CPU hemicube, computed on all cores (TBB).
// Storage: F is kept in float (4 bytes × n²) when n <= maxStoredPatches (default 8192:
// 256 MiB, a twentieth of the share of one engineer's RAM on this 24 GiB machine, and 4k
// patches take 64 MiB); beyond it no matrix is kept and rows are computed when asked for
// (progressive refinement shoots from one patch at a time, so it needs one row per shot).
// Rows are computed lazily and cached when stored; computeAll() fills the whole matrix.
#include "core/radiosity/hemicube.h"
#include "core/radiosity/point_rays.h"
#include "core/radiosity/ray_form_factors.h"

#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <mutex>

namespace wb::rad {

// External: rows come from FormFactorConfig::rowProvider (lab 08's GL hemicube, which fills an
// ItemBuffer with OpenGL and calls accumulate() with deltaTable()).
enum class FormFactorMethod { Rays, Hemicube, External };

struct FormFactorConfig {
    FormFactorMethod method = FormFactorMethod::Hemicube; // how rows are computed
    RayFormFactorConfig rays;                 // for Rays
    int hemicubeResolution = 128;             // for Hemicube: pixels along a face edge (even)
    bool exactPixels = false;                 // hemicube weights: course's midpoint or exact
    std::size_t maxStoredPatches = 8192;      // store F (float) up to this patch count
    int threads = 0;                          // 0 = all cores; 1 = serial (bench)
    // External: called with row i and `out` sized to n, must fill F_i0..F_i,n−1. Called only
    // from the thread calling row()/computeAll() (GL contexts are per thread); computeAll() then
    // runs serially.
    std::function<void(int i, std::vector<float>& out)> rowProvider;
    // Progressive with shooting groups: the row of group g (its hemicube frame has the origin at
    // the group's centroid), `out` sized to n. Empty: core's CPU hemicube at hemicubeResolution.
    // Lab 08 passes its GL hemicube or rays at the receivers (point_rays.h) so the keys' method
    // also shoots the groups. Called from the thread calling shooterRow() (the GL hemicube
    // needs its context).
    std::function<void(int g, const HemicubeFrame& frame, std::vector<float>& out)> groupRowProvider;
    // Progressive with shooting groups: receivers within this many group diagonals (√(2·A_g))
    // of a group's centroid are shot member by member (groupNearField, point_rays.h) instead of
    // by the group's row, whatever the method. 0: off (every receiver gets the pooled row).
    // 2: the Cornell box at lab 08's defaults (0.1 m groups, rays k = 4) is within 2.4% of
    // Cycles on every face (24% at 0, 3.2% at 1: docs/bench/radiosity.md, "Why ours was off").
    double groupNearField = 2.0;
    // Progressive with shooting groups and a near field: a group's far receivers get its pooled
    // ΔB plus the members' ΔB gradient times where they see the members (GroupNearField::du/dv)
    // instead of the flat mean. false: the flat mean (the ceiling in front of the light −2%).
    bool groupGradient = true;
};

class FormFactors {
  public:
    // Keeps a reference to `mesh` (must outlive this and not change). Builds the BVH.
    FormFactors(const PatchMesh& mesh, FormFactorConfig config);
    ~FormFactors();

    int size() const;
    bool stored() const;                // F kept in memory
    const FormFactorConfig& config() const { return config_; }

    // Every row, in parallel. Without storage this only checks the config (nothing to keep).
    void computeAll();
    // Row i (F_i0..F_i,n−1): from the store (computed first if missing) or computed into
    // `scratch`; the pointer is valid until the next call with the same scratch. Thread-safe.
    const float* row(int i, std::vector<float>& scratch) const;
    // Stored value (computes the row if needed). Throws std::logic_error when not stored.
    float at(int i, int j) const;
    // Row of shooting group g (mesh.groups): F from the group's centroid to every patch by
    // groupRowProvider, or the CPU hemicube at hemicubeResolution without one. Cached
    // for all groups when groups × n <= maxStoredPatches². Thread-safe.
    const float* shooterRow(int g, std::vector<float>& scratch) const;
    // Whether group rows are cached at all (groups × n <= maxStoredPatches²), and whether
    // shooterRow(g) is.
    bool shooterRowsCached() const { return !groupRows_.empty(); }
    bool shooterRowReady(int g) const;
    bool rowReady(int i) const;
    // Near field of group g (config.groupNearField), computed on first use and kept; nullptr when
    // off. Thread-safe.
    const GroupNearField* nearField(int g) const;
    // The near field of g if nearField(g) has computed it, else nullptr; takes no lock, so a
    // groupRowProvider (called under the lock) may pass it to groupGatherRow. The solver asks
    // for a group's near field before its row.
    const GroupNearField* nearFieldReady(int g) const;

    std::size_t bytes() const;          // memory held for F (and the BVH's primitives)
    double seconds() const;             // wall time while rows or near fields were computed
                                        // (by any thread, overlaps counted once)
    long long rowsComputed() const;     // rows computed so far (recomputations count)
    const PatchBvh& bvh() const { return *bvh_; }
    const DeltaFormFactors& deltaTable() const { return table_; }
    const PatchMesh& mesh() const { return mesh_; }

  private:
    void computeRow(int i, std::vector<float>& out) const;

    float* storedRow(int i) const; // allocates the matrix on first use (under mutex_)
    const PatchMesh& mesh_;
    FormFactorConfig config_;
    std::unique_ptr<PatchBvh> bvh_;
    DeltaFormFactors table_;
    bool store_ = false;                              // n <= maxStoredPatches
    mutable std::vector<float> matrix_;               // n × n, allocated at the first stored row
    std::unique_ptr<std::atomic<bool>[]> ready_;      // row computed (stored mode)
    mutable std::vector<float> groupRows_;            // groups × n when cached
    std::unique_ptr<std::atomic<bool>[]> groupReady_;
    mutable std::vector<std::unique_ptr<GroupNearField>> nearFields_; // per group, lazily
    std::unique_ptr<std::atomic<const GroupNearField*>[]> nearReady_; // published nearFields_
    mutable std::mutex mutex_;                        // guards lazy row computation
    // Per group: guards its near field and its cached row, so that two threads (the solver
    // and its prefetch worker, SolverConfig::prefetch) prepare different groups at once, and
    // one asking for the group the other is preparing waits for it instead of redoing it.
    std::unique_ptr<std::mutex[]> groupMutex_;
    struct Busy; // counts wall time while any thread computes (seconds())
    mutable std::mutex busyMutex_;
    mutable int busy_ = 0;
    mutable std::chrono::steady_clock::time_point busySince_;
    mutable std::atomic<long long> nanos_{0};
    mutable std::atomic<long long> rows_{0};
};

} // namespace wb::rad
