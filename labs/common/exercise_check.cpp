#include "common/exercise_check.h"

#include "core/i18n.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace wb::ex {

int labGrade(const LabExercises& lab, const std::vector<TaskResult>& results) {
    auto passes = [&](const Task& t) {
        for (const TaskResult& r : results)
            if (r.id == t.id) return r.status == Status::Passes;
        return false;
    };
    int grade = 0;
    for (int m = 3; m <= 5; ++m) {
        bool all = true, any = false;
        for (const Task& t : lab.tasks) {
            if (t.grade > m) continue;
            any = true;
            all = all && passes(t);
        }
        if (!any || !all) break;
        grade = m;
    }
    return grade;
}

std::optional<Verdict> compareHomogeneous(const Values& expected, const Values& got, int n,
                                          double tol, const char* nonFinite, const char* transposed,
                                          const char* zero) {
    const size_t size = size_t(n) * size_t(n);
    if (got.size() != size) return Verdict::fail(trf("not a %dx%d matrix", n, n));
    for (double x : got)
        if (!std::isfinite(x)) return Verdict::fail(nonFinite);
    if (equalUpToFactor(expected, got, tol)) return Verdict::pass();
    Values t(size);
    for (int c = 0; c < n; ++c)
        for (int r = 0; r < n; ++r)
            t[size_t(r * n + c)] = got[size_t(c * n + r)];
    if (equalUpToFactor(expected, t, tol)) return Verdict::fail(transposed);
    bool allZero = true;
    for (double x : got)
        allZero = allZero && x == 0;
    if (allZero) return Verdict::fail(zero);
    return std::nullopt;
}

std::string showNumbers(const Values& v) {
    std::string s = "(";
    char buf[40];
    for (size_t i = 0; i < v.size(); ++i) {
        std::snprintf(buf, sizeof buf, "%s%.6g", i ? ", " : "", v[i]);
        s += buf;
    }
    return s + ")";
}

std::string showMatrix(const Values& m, int n) {
    if (m.size() != size_t(n) * size_t(n)) return showNumbers(m);
    std::string s = "[";
    char buf[40];
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) {
            std::snprintf(buf, sizeof buf, "%.4g%s", m[size_t(c * n + r)],
                          c + 1 < n ? " " : (r + 1 < n ? "; " : "]"));
            s += buf;
        }
    return s;
}

bool allNear(const Values& a, const Values& b, double tol) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
        if (!std::isfinite(b[i]) && a[i] != b[i]) return false;
        const double scale = std::max({1.0, std::abs(a[i]), std::abs(b[i])});
        if (!(std::abs(a[i] - b[i]) <= tol * scale)) return false;
    }
    return true;
}

namespace {
bool upToFactor(const Values& e, const Values& g, double tol, bool positive) {
    if (e.size() != g.size()) return false;
    size_t ie = 0, ig = 0;
    for (size_t i = 0; i < e.size(); ++i) {
        if (!std::isfinite(g[i])) return false;
        if (std::abs(e[i]) > std::abs(e[ie])) ie = i;
        if (std::abs(g[i]) > std::abs(g[ig])) ig = i;
    }
    const double me = e.empty() ? 0 : std::abs(e[ie]), mg = g.empty() ? 0 : std::abs(g[ig]);
    if (me == 0 || mg == 0) return me == 0 && mg == 0;
    // Scale both so their largest entries are ±1, with the sign of e's largest entry in
    // e; then k is fixed by that entry, and only k > 0 is allowed when `positive`.
    const double k = g[ie] / e[ie];
    if (!std::isfinite(k) || k == 0 || (positive && k < 0)) return false;
    for (size_t i = 0; i < e.size(); ++i)
        if (!(std::abs(e[i] * k - g[i]) <= tol * mg)) return false;
    return true;
}
} // namespace

bool equalUpToFactor(const Values& expected, const Values& got, double tol) {
    return upToFactor(expected, got, tol, false);
}
bool equalUpToPositiveFactor(const Values& expected, const Values& got, double tol) {
    return upToFactor(expected, got, tol, true);
}

} // namespace wb::ex
