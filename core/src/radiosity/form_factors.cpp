#include "core/radiosity/form_factors.h"

#include "core/raytrace/ray.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <limits>
#include <stdexcept>
#include <string>

namespace wb::rad {

namespace {
using Clock = std::chrono::steady_clock;
long long nanosSince(Clock::time_point t0) {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - t0).count();
}
} // namespace

// Wall time while any thread computes a row or near field: the solver and its prefetch worker
// (SolverConfig::prefetch) overlap, and the panel's "rows computed in X s" must not add them.
struct FormFactors::Busy {
    explicit Busy(const FormFactors& ff) : ff_(ff) {
        std::lock_guard<std::mutex> lock(ff_.busyMutex_);
        if (ff_.busy_++ == 0) ff_.busySince_ = Clock::now();
    }
    ~Busy() {
        std::lock_guard<std::mutex> lock(ff_.busyMutex_);
        if (--ff_.busy_ == 0) ff_.nanos_ += nanosSince(ff_.busySince_);
    }
    Busy(const Busy&) = delete;
    Busy& operator=(const Busy&) = delete;
    const FormFactors& ff_;
};

FormFactors::FormFactors(const PatchMesh& mesh, FormFactorConfig config)
    : mesh_(mesh), config_(std::move(config)) {
    const std::size_t n = mesh.patches.size();
    if (n == 0) throw std::invalid_argument("form factors: the mesh has no patches");
    if (config_.threads < 0)
        throw std::invalid_argument("form factors: threads must be >= 0 (0 = all cores)");
    if (config_.method == FormFactorMethod::External && !config_.rowProvider)
        throw std::invalid_argument("form factors: method External needs a rowProvider");
    if (config_.method == FormFactorMethod::Rays &&
        (config_.rays.samples < 1 || config_.rays.samples > 4096))
        throw std::invalid_argument("form factors: ray samples " +
                                    std::to_string(config_.rays.samples) + " outside 1..4096");
    // The delta table is built for every method: the External provider accumulates with it.
    table_ = deltaFormFactors(config_.hemicubeResolution, config_.exactPixels);
    bvh_ = std::make_unique<PatchBvh>(mesh);
    if (n <= config_.maxStoredPatches) {
        store_ = true; // the n² floats are allocated when the first row is stored: progressive
                       // refinement with shooting groups never needs them
        ready_ = std::make_unique<std::atomic<bool>[]>(n);
        for (std::size_t i = 0; i < n; ++i) ready_[i] = false;
    }
    const std::size_t groups = mesh.groups.size();
    if (groups > 0 && static_cast<double>(groups) * static_cast<double>(n) <=
                          static_cast<double>(config_.maxStoredPatches) * static_cast<double>(config_.maxStoredPatches)) {
        groupRows_.assign(groups * n, 0.0f);
        groupReady_ = std::make_unique<std::atomic<bool>[]>(groups);
        for (std::size_t g = 0; g < groups; ++g) groupReady_[g] = false;
    }
    nearFields_.resize(groups);
    groupMutex_ = std::make_unique<std::mutex[]>(groups);
    nearReady_ = std::make_unique<std::atomic<const GroupNearField*>[]>(groups);
    for (std::size_t g = 0; g < groups; ++g) nearReady_[g] = nullptr;
}

const GroupNearField* FormFactors::nearFieldReady(int g) const {
    if (g < 0 || static_cast<std::size_t>(g) >= mesh_.groups.size()) return nullptr;
    return nearReady_[static_cast<std::size_t>(g)].load(std::memory_order_acquire);
}

const GroupNearField* FormFactors::nearField(int g) const {
    if (!(config_.groupNearField > 0.0)) return nullptr;
    if (g < 0 || static_cast<std::size_t>(g) >= mesh_.groups.size())
        throw std::out_of_range("form factors: shooting group " + std::to_string(g) + " out of range");
    std::lock_guard<std::mutex> lock(groupMutex_[static_cast<std::size_t>(g)]);
    auto& slot = nearFields_[static_cast<std::size_t>(g)];
    if (!slot) {
        const Busy busy(*this);
        const ShooterGroup& sg = mesh_.groups[static_cast<std::size_t>(g)];
        const double diagonal = std::sqrt(2.0 * sg.area);
        // An emitter's groups (the light: 1-2 of them) reach every receiver member by member:
        // the direct light is most of every B, and the hemicube from the group's centre put
        // it 1-3% off per row (the box's edges alias at one sub-pixel phase) and speckled the
        // tall block's front face, lit at a grazing angle (a few pixels per patch at 128²).
        const bool emits =
            glm::length(mesh_.surfaces[static_cast<std::size_t>(sg.surface)].emission) > 0.0;
        const double radius =
            emits ? std::numeric_limits<double>::infinity() : config_.groupNearField * diagonal;
        slot = std::make_unique<GroupNearField>(
            groupNearField(mesh_, *bvh_, g, radius, config_.groupGradient));
        nearReady_[static_cast<std::size_t>(g)].store(slot.get(), std::memory_order_release);
    }
    return slot.get();
}

const float* FormFactors::shooterRow(int g, std::vector<float>& scratch) const {
    if (g < 0 || static_cast<std::size_t>(g) >= mesh_.groups.size())
        throw std::out_of_range("form factors: shooting group " + std::to_string(g) + " out of range");
    const std::size_t n = mesh_.patches.size();
    auto compute = [&](std::vector<float>& out) {
        const Busy busy(*this);
        const ShooterGroup& sg = mesh_.groups[static_cast<std::size_t>(g)];
        HemicubeFrame fr;
        fr.n = sg.normal;
        fr.u = sg.u;
        fr.v = glm::cross(sg.normal, sg.u);
        fr.origin = rt::offsetRayOrigin(sg.centre, sg.normal);
        if (config_.groupRowProvider) {
            out.assign(n, 0.0f);
            config_.groupRowProvider(g, fr, out);
            ++rows_;
            return;
        }
        ItemBuffer items;
        auto cast = [&] { castItemBuffer(*bvh_, fr, table_.resolution, items, config_.threads != 1); };
        if (config_.threads > 1) {
            tbb::task_arena arena(config_.threads);
            arena.execute(cast);
        } else {
            cast();
        }
        accumulate(items, table_, static_cast<int>(n), -1, out);
        ++rows_;
    };
    if (groupRows_.empty()) {
        compute(scratch);
        return scratch.data();
    }
    float* dst = groupRows_.data() + static_cast<std::ptrdiff_t>(g) * static_cast<std::ptrdiff_t>(n);
    if (!groupReady_[static_cast<std::size_t>(g)]) {
        std::lock_guard<std::mutex> lock(groupMutex_[static_cast<std::size_t>(g)]);
        if (!groupReady_[static_cast<std::size_t>(g)]) {
            compute(scratch);
            std::copy(scratch.begin(), scratch.end(), dst);
            groupReady_[static_cast<std::size_t>(g)] = true;
        }
    }
    return dst;
}

bool FormFactors::shooterRowReady(int g) const {
    return !groupRows_.empty() && g >= 0 && static_cast<std::size_t>(g) < mesh_.groups.size() &&
           groupReady_[static_cast<std::size_t>(g)];
}

FormFactors::~FormFactors() = default;

int FormFactors::size() const { return static_cast<int>(mesh_.patches.size()); }
bool FormFactors::stored() const { return store_; }

float* FormFactors::storedRow(int i) const {
    auto& m = matrix_;
    if (m.empty()) m.assign(mesh_.patches.size() * mesh_.patches.size(), 0.0f);
    return m.data() + static_cast<std::ptrdiff_t>(i) * size();
}

void FormFactors::computeRow(int i, std::vector<float>& out) const {
    const Busy busy(*this);
    const bool inner = config_.threads != 1; // parallel inside the row (hemicube pixel rows)
    switch (config_.method) {
    case FormFactorMethod::Rays:
        rayFormFactorRow(mesh_, *bvh_, i, config_.rays, out);
        break;
    case FormFactorMethod::Hemicube:
        hemicubeRow(mesh_, *bvh_, table_, i, out, inner);
        break;
    case FormFactorMethod::External:
        out.assign(mesh_.patches.size(), 0.0f);
        config_.rowProvider(i, out);
        if (out.size() != mesh_.patches.size())
            throw std::runtime_error("form factors: rowProvider resized row " + std::to_string(i));
        out[static_cast<std::size_t>(i)] = 0.0f;
        break;
    }
    ++rows_;
}

void FormFactors::computeAll() {
    if (!stored()) return;
    const int n = size();
    {
        std::lock_guard<std::mutex> lock(mutex_);
        storedRow(0); // allocate before the parallel writers
    }
    const auto t0 = Clock::now();
    const long long before = nanos_.load();
    auto one = [&](int i) {
        if (ready_[static_cast<std::size_t>(i)]) return;
        std::vector<float> out;
        switch (config_.method) {
        case FormFactorMethod::Rays:
            rayFormFactorRow(mesh_, *bvh_, i, config_.rays, out);
            break;
        case FormFactorMethod::Hemicube:
            hemicubeRow(mesh_, *bvh_, table_, i, out, false); // rows are the parallel unit
            break;
        case FormFactorMethod::External:
            out.assign(mesh_.patches.size(), 0.0f);
            config_.rowProvider(i, out);
            out.resize(mesh_.patches.size());
            out[static_cast<std::size_t>(i)] = 0.0f;
            break;
        }
        std::copy(out.begin(), out.end(), matrix_.begin() + static_cast<std::ptrdiff_t>(i) * n);
        ready_[static_cast<std::size_t>(i)] = true;
        ++rows_;
    };
    if (config_.method == FormFactorMethod::External || config_.threads == 1) {
        for (int i = 0; i < n; ++i) one(i);
    } else {
        tbb::task_arena arena(config_.threads > 0 ? config_.threads
                                                  : tbb::task_arena::automatic);
        arena.execute([&] { tbb::parallel_for(0, n, one); });
    }
    nanos_ = before + nanosSince(t0);
}

const float* FormFactors::row(int i, std::vector<float>& scratch) const {
    if (i < 0 || i >= size())
        throw std::out_of_range("form factors: row " + std::to_string(i) + " out of range");
    if (!stored()) {
        if (config_.threads > 1 && config_.method == FormFactorMethod::Hemicube) {
            tbb::task_arena arena(config_.threads);
            arena.execute([&] { computeRow(i, scratch); });
        } else {
            computeRow(i, scratch);
        }
        return scratch.data();
    }
    if (!ready_[static_cast<std::size_t>(i)]) {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!ready_[static_cast<std::size_t>(i)]) {
            float* dst = storedRow(i);
            if (config_.threads > 1 && config_.method == FormFactorMethod::Hemicube) {
                tbb::task_arena arena(config_.threads);
                arena.execute([&] { computeRow(i, scratch); });
            } else {
                computeRow(i, scratch);
            }
            std::copy(scratch.begin(), scratch.end(), dst);
            ready_[static_cast<std::size_t>(i)] = true;
        }
    }
    return matrix_.data() + static_cast<std::ptrdiff_t>(i) * size();
}

float FormFactors::at(int i, int j) const {
    if (!stored()) throw std::logic_error("form factors: F is not stored (n > maxStoredPatches)");
    if (j < 0 || j >= size())
        throw std::out_of_range("form factors: column " + std::to_string(j) + " out of range");
    std::vector<float> scratch;
    return row(i, scratch)[j];
}

bool FormFactors::rowReady(int i) const {
    return stored() && i >= 0 && i < size() && ready_[static_cast<std::size_t>(i)];
}

std::size_t FormFactors::bytes() const {
    std::size_t b = (matrix_.capacity() + groupRows_.capacity()) * sizeof(float);
    for (const auto& f : table_.faces) b += f.capacity() * sizeof(double);
    // The BVH's primitives and nodes: about 300 bytes per patch (rt::Rectangle ~200 B, node share).
    b += mesh_.patches.size() * 300;
    return b;
}

double FormFactors::seconds() const { return static_cast<double>(nanos_.load()) * 1e-9; }
long long FormFactors::rowsComputed() const { return rows_.load(); }

} // namespace wb::rad
