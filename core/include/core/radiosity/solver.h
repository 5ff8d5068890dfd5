#pragma once
// Solving B = E + R·F·B (14.16 with 14.18) for each colour channel:
//  - Jacobi: B ← E + R·(F·B_old) (gathering, all patches at once);
//  - Gauss–Seidel: the same, each patch using the values already updated in this sweep;
//  - Progressive refinement (Cohen, Chen, Wallace, Greenberg 1988): shoot the unshot radiosity
//    ΔB_s of the patch with the most unshot POWER (A_s·ΔB_s summed over channels): every j gets
//    R_j·ΔB_s·F_sj·A_s/A_j (reciprocity), needing only row s of F (computed on demand). For
//    display an ambient term R_j·(Σ A·ΔB / Σ A)/(1 − R_avg) stands for the light not yet shot.
// Residual, reported after every step (and kept in history()), in "fraction of the emitted
// power": Jacobi and Gauss–Seidel: Σ_i A_i Σ_c |E + R(F·B) − B|_ic / Σ_i A_i Σ_c E_ic of the
// current B (one extra matrix–vector product for Gauss–Seidel); progressive: the unshot power
// Σ_i A_i Σ_c ΔB_ic / Σ_i A_i Σ_c E_ic. The lab steps one iteration / one shot at a time, or
// runs with a cancel flag from another thread.
#include "core/radiosity/form_factors.h"

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

namespace wb::rad {

enum class SolverKind { Jacobi, GaussSeidel, Progressive };

struct SolverConfig {
    SolverKind kind = SolverKind::Progressive;
    bool ambient = true;       // progressive: add the ambient term to displayRadiosity()
    // Progressive on a mesh with shooting groups (MeshConfig::shooterEdge): shoot a group's pooled
    // unshot power from its centroid (FormFactors::shooterRow), receive at every patch. Rows of
    // groups are few and cached, so later shots cost O(n). false: every patch shoots itself.
    bool groupShooting = true;
    // Progressive with shooting groups: a worker thread prepares the groups next in line (the
    // few with the most unshot power that have not shot yet): their near fields, and their rows
    // unless the method is External (lab 08's GL rows are drawn on the GL thread, the caller's).
    // A group's near field and row depend on the group only, never on who computed them or
    // when, so B and the steps are the same with it on or off (tested bit for bit); it only
    // moves work onto the second core while this thread shoots or draws GL rows. The worker
    // runs in a TBB arena as wide as the one the solver was made in.
    bool prefetch = false;
    double tolerance = 1e-6;   // run(): stop when residual() < tolerance
    int maxSteps = 1000000;    // run(): stop after this many steps (sweeps or shots)
};

class Solver {
  public:
    // Keeps references to mesh and form factors (must outlive the solver). B starts at E.
    Solver(const PatchMesh& mesh, const FormFactors& ff, SolverConfig config);
    ~Solver(); // stops the prefetch worker (waits for the group it is preparing)
    Solver(const Solver&) = delete;
    Solver& operator=(const Solver&) = delete;

    // One Jacobi/Gauss–Seidel sweep or one progressive shot; returns the new residual.
    double step();
    // Steps until residual < tolerance, maxSteps, or *cancel becomes true (checked between
    // steps; may be null). Returns the number of steps taken.
    int run(const std::atomic<bool>* cancel = nullptr);

    int steps() const { return steps_; }
    double residual() const { return residual_; }
    const std::vector<double>& history() const { return history_; } // residual after each step
    const std::vector<glm::dvec3>& radiosity() const { return B_; }   // B per patch
    std::vector<glm::dvec3> displayRadiosity() const; // B (+ ambient when progressive & on)
    const std::vector<glm::dvec3>& unshot() const { return dB_; }   // progressive ΔB
    int lastShooter() const { return lastShooter_; }  // progressive: last patch shot (a group's
                                                      // first member), −1 before
    int lastGroup() const { return lastGroup_; }      // progressive with groups, else −1
    // Power balance: emitted Σ A·E and absorbed Σ A·(1−R)·B_in (per channel, W).
    glm::dvec3 emittedPower() const;
    glm::dvec3 absorbedPower() const;
    const SolverConfig& config() const { return config_; }

  private:
    // A group's plane-fit moments (area-weighted, its members' centres in its u, v axes): they
    // depend on the geometry only, so they are made at the group's first shot and kept.
    struct PlaneFit {
        bool ready = false;
        std::vector<double> ax, ay;     // per member: A·x, A·y
        double suu = 0, suv = 0, svv = 0; // Σ A x², Σ A x y, Σ A y²
    };
    double computeResidual();
    void jacobiSweep(); // one sweep of B = E + R·F·B from the old B
    void shootGroup();  // one progressive shot from the group with the most unshot power
    const PlaneFit& planeFit(int g);
    void prefetchAfter(int best, const std::vector<double>& power);
    void prefetchLoop(int concurrency);
    const PatchMesh& mesh_;
    const FormFactors& ff_;
    SolverConfig config_;
    std::vector<glm::dvec3> B_, dB_, FB_;
    std::vector<double> history_;
    std::vector<float> scratch_;
    std::vector<glm::dvec3> memberShot_; // a group's members' ΔB at its shot
    std::vector<char> nearMark_;         // receivers of the shooting group's near field
    std::vector<PlaneFit> fits_;         // per group, made at its first shot
    std::vector<double> groupPower_;     // per group: unshot power A·ΔB (this step's ranking)
    // Prefetch (SolverConfig::prefetch): queue_ holds the groups the worker should prepare next,
    // best first, replaced after every ranking; queued_ marks the groups ever handed to it.
    std::thread prefetcher_;
    std::mutex prefetchMutex_;
    std::condition_variable prefetchWake_;
    std::vector<int> queue_;
    bool stopPrefetch_ = false;
    std::vector<char> queued_;
    double emittedSum_ = 0.0;
    double residual_ = 1.0;
    int steps_ = 0;
    int lastShooter_ = -1;
    int lastGroup_ = -1;
};

} // namespace wb::rad
