#include "core/raytrace/obj_file.h"

#include "core/file_read.h"
#include "core/i18n.h"
#include "core/raytrace/smooth_triangle.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <istream>
#include <map>
#include <sstream>
#include <streambuf>
#include <string_view>
#include <sys/stat.h>
#include <unordered_map>

namespace wb::rt {

namespace {

// CPU time of the calling thread (ObjLoadTimes): a load runs on one thread, and on a
// shared machine wall time measures the queue as much as the code.
double threadSeconds() {
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

bool finite3(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Shortest text that reads back to v (1.0000001e38 is not shown as "1e+38").
std::string fmt(double v) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

// An istream over text already in memory (tinyobjloader reads from a stream), without
// copying it.
struct MemoryBuf : std::streambuf {
    MemoryBuf(const char* b, std::size_t n) {
        char* p = const_cast<char*>(b); // read only: the get area is never written
        setg(p, p, p + n);
    }
};

std::string_view skipBom(std::string_view t) {
    if (t.substr(0, 3) == "\xEF\xBB\xBF") t.remove_prefix(3);
    return t;
}

// Calls f(lineNumber, line) for every line; lines end at LF, CR LF or CR, as in
// tinyobjloader's safeGetline, so both count lines alike.
template <class F> void forEachLine(std::string_view t, F&& f) {
    std::size_t at = 0;
    int line = 0;
    while (at < t.size()) {
        std::size_t e = at;
        while (e < t.size() && t[e] != '\n' && t[e] != '\r')
            ++e;
        f(++line, t.substr(at, e - at));
        at = e;
        if (at < t.size()) {
            if (t[at] == '\r' && at + 1 < t.size() && t[at + 1] == '\n') ++at;
            ++at;
        }
    }
}

// Whitespace-separated words of a line up to a `#` comment (tinyobjloader splits at
// space and tab; VT and FF are treated as space here and refused nowhere).
std::vector<std::string_view> words(std::string_view l) {
    std::vector<std::string_view> w;
    auto space = [](char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; };
    std::size_t i = 0;
    while (i < l.size()) {
        while (i < l.size() && space(l[i]))
            ++i;
        if (i == l.size() || l[i] == '#') break;
        std::size_t j = i;
        while (j < l.size() && !space(l[j]))
            ++j;
        w.push_back(l.substr(i, j - i));
        i = j;
    }
    return w;
}

class FileErrors {
  public:
    explicit FileErrors(const std::string& path) : path_(path) {}
    [[noreturn]] void fail(int line, const std::string& what) const {
        throw SceneFileError(path_ + ":" + std::to_string(line) + ": " + what);
    }
    // A decimal number as tinyobjloader reads it ([+-]digits[.digits][e[+-]digits]):
    // anything else (hex, "nan", trailing bytes, a NUL) would be read differently or as 0.
    double number(std::string_view w, int line, const char* what) const {
        const std::string s(w);
        std::string lower = s;
        std::transform(lower.begin(), lower.end(), lower.begin(),
                       [](unsigned char c) { return char(std::tolower(c)); });
        const auto sign = lower.find_first_not_of("+-");
        if (sign != std::string::npos &&
            (lower.compare(sign, 3, "nan") == 0 || lower.compare(sign, 3, "inf") == 0))
            fail(line, trf("non-finite %s '%s'", tr(what), escapeForMessage(s).c_str()));
        const bool decimal =
            !s.empty() && s.find_first_not_of("0123456789+-.eE") == std::string::npos;
        char* end = nullptr;
        errno = 0;
        const double v = decimal ? std::strtod(s.c_str(), &end) : 0.0;
        if (!decimal || end != s.c_str() + s.size())
            fail(line, trf("bad number '%s' (%s)", escapeForMessage(s).c_str(), tr(what)));
        if (std::isinf(v))
            fail(line, trf("%s '%s' is beyond the range of a double", tr(what),
                           escapeForMessage(s).c_str()));
        return v;
    }

  private:
    const std::string& path_;
};

// What the pre-pass learns (tinyobjloader reads malformed numbers and indices as 0 or
// wraps them, and gives no line numbers; this pass checks the text first and names the
// line).
struct ObjScan {
    std::vector<int> faceLines;          // line of the k-th `f` with 3 or more vertices
    std::vector<int> droppedLines;       // `f` with fewer (tinyobjloader drops them)
    std::vector<std::size_t> badNormals; // indices of `vn` records to repair
    std::vector<int> badNormalLines;     // their lines
    std::size_t triangles = 0;           // after fan triangulation
};

// The pre-pass, line by line. Two ways through each line:
//  - checkedLine: the reference. It splits the line into words and checks each with
//    strtod/strtoll, and names the line of the first problem (every message comes from
//    here);
//  - fastLine: one pass over the bytes with std::from_chars and no allocation, for the
//    lines of a large file. It only ever says "this line is fine" when checkedLine
//    would accept it with the same effects (see fastNumber and fastCorner); on anything
//    else — a bad or unusual number, a limit crossed, a `+1`, a hex or `nan` word — it
//    gives up before any effect and the line goes to checkedLine, so verdicts, messages
//    and the order of errors stay those of checkedLine alone.
// Measured (docs/bench/obj_load.md, 18 MB OBJ, 78,400 triangles): the pre-pass took
// 115 ms, more than tinyobjloader's own parse (96 ms); now 12 ms.
class ObjScanner {
  public:
    explicit ObjScanner(const std::string& path) : err_(path) {}

    ObjScan run(std::string_view text, bool checkedOnly = false) {
        // A NUL anywhere: every line the checked way, which names the line that holds it
        // with the NFF reader's message, in line order with the other problems (one
        // memchr over the file; the fast path need not look for NUL bytes).
        if (checkedOnly || std::memchr(text.data(), '\0', text.size()) != nullptr) {
            forEachLine(text, [&](int line, std::string_view l) { checkedLine(line, l); });
            return std::move(scan_);
        }
        const char* p = text.data();
        const char* const e = p + text.size();
        int line = 0;
        // Lines end at LF, CR LF or CR, as in forEachLine.
        while (p < e) {
            ++line;
            const char* const start = p;
            if (!fastLine(p, e, line)) {
                p = start;
                while (p < e && !eol(*p))
                    ++p;
                checkedLine(line, std::string_view(start, std::size_t(p - start)));
            }
            if (p < e) {
                if (*p == '\r' && p + 1 < e && p[1] == '\n') ++p;
                ++p;
            }
        }
        return std::move(scan_);
    }

  private:
    static bool sep(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }
    static bool eol(char c) { return c == '\n' || c == '\r'; }
    static bool digit(char c) { return c >= '0' && c <= '9'; }
    static void toEol(const char*& q, const char* e) {
        while (q < e && !eol(*q))
            ++q;
    }

    // The reference check of one line (issue 12): every error message is made here.
    void checkedLine(int line, std::string_view l) {
        const FileErrors& err = err_;
        ObjScan& scan = scan_;
        if (l.find('\0') != std::string_view::npos) err.fail(line, nulByteMessage());
        const std::vector<std::string_view> w = words(l);
        if (w.empty()) return;
        const std::string_view cmd = w[0];
        if (cmd == "v") {
            if (w.size() < 4) err.fail(line, tr("a vertex needs 3 numbers (v x y z)"));
            for (std::size_t i = 1; i < w.size(); ++i) {
                const double c = err.number(w[i], line, "vertex coordinate");
                if (i <= 3 && !(std::abs(c) <= kObjMaxCoordinate))
                    err.fail(line, trf("vertex coordinate %s is beyond the limit ±1e38 (OBJ "
                                       "coordinates are read as 32-bit floats)",
                                       fmt(c).c_str()));
            }
            ++nv_;
        } else if (cmd == "vn") {
            if (w.size() < 4) err.fail(line, tr("a normal needs 3 numbers (vn x y z)"));
            bool bad = false;
            for (std::size_t i = 1; i < 4; ++i) {
                // A normal only gives a direction: a non-finite or huge one is the
                // documented repair (the face normal is used), not an error.
                const std::string s(w[i]);
                char* end = nullptr;
                const double c = std::strtod(s.c_str(), &end);
                if (end == s.c_str() || end != s.c_str() + s.size())
                    err.fail(line, trf("bad number '%s' (normal component)",
                                       escapeForMessage(s).c_str()));
                if (!(std::abs(c) <= kObjMaxCoordinate)) bad = true;
            }
            if (bad) {
                scan.badNormals.push_back(std::size_t(nvn_));
                scan.badNormalLines.push_back(line);
            }
            ++nvn_;
        } else if (cmd == "vt") {
            if (w.size() < 2) err.fail(line, tr("a texture coordinate needs a number (vt u [v])"));
            for (std::size_t i = 1; i < w.size(); ++i)
                err.number(w[i], line, "texture coordinate");
            ++nvt_;
        } else if (cmd == "f") {
            const std::size_t n = w.size() - 1;
            if (n > kObjMaxFaceVertices)
                err.fail(line, trf("face with %zu vertices: at most %zu per face (the OBJ "
                                   "library stores the count in one byte); split the face",
                                   n, kObjMaxFaceVertices));
            (n >= 3 ? scan.faceLines : scan.droppedLines).push_back(line);
            for (std::size_t i = 1; i < w.size(); ++i) {
                // v, v/vt, v//vn or v/vt/vn: each given index a non-zero int.
                std::string_view rest = w[i];
                const long long counts[3] = {nv_, nvt_, nvn_};
                for (int k = 0; k < 3; ++k) {
                    const std::size_t slash = rest.find('/');
                    const std::string part(rest.substr(0, slash));
                    if (!part.empty() || k == 0) {
                        char* end = nullptr;
                        errno = 0;
                        const long long ix = std::strtoll(part.c_str(), &end, 10);
                        if (part.empty() || end != part.c_str() + part.size())
                            err.fail(line, trf("bad index '%s' in a face",
                                               escapeForMessage(std::string(w[i])).c_str()));
                        if (errno == ERANGE || ix > INT_MAX || ix < -INT_MAX)
                            err.fail(line, trf("index %s out of range (more than 2^31 - 1)",
                                               escapeForMessage(part).c_str()));
                        if (ix == 0)
                            err.fail(line, tr("index 0 in a face (OBJ indices start at 1)"));
                        if (ix < 0 && -ix > counts[k])
                            err.fail(
                                line,
                                k == 0   ? trf("relative index %s points before the first vertex",
                                               part.c_str())
                                : k == 1 ? trf("relative index %s points before the first texture "
                                               "coordinate",
                                               part.c_str())
                                         : trf("relative index %s points before the first normal",
                                               part.c_str()));
                    }
                    if (slash == std::string_view::npos) break;
                    rest = rest.substr(slash + 1);
                }
            }
            if (n >= 3) {
                scan.triangles += n - 2;
                if (scan.triangles > kObjMaxTriangles)
                    err.fail(line,
                             trf("more than %zu triangles (the limit for one file, see obj_file.h)",
                                 std::size_t(kObjMaxTriangles)));
            }
        }
    }

    // A number word at q that checkedLine accepts, read to its end: a plain decimal
    // ([-]digits[.digits][e[+-]digits], the word's first byte a digit, '-' or '.'), read
    // whole by from_chars and finite. Such a word passes FileErrors::number's tests (only
    // the bytes 0-9 + - . e E; strtod reads it whole) and strtod's value is the same double
    // (both round correctly). Anything else (a leading '+', hex, nan, inf, out of range,
    // trailing bytes) returns false.
    static bool fastNumber(const char*& q, const char* e, double& v) {
        if (!(digit(*q) || *q == '-' || *q == '.')) return false;
        const std::from_chars_result r = std::from_chars(q, e, v);
        if (r.ec != std::errc{} || !std::isfinite(v)) return false;
        if (r.ptr < e && !sep(*r.ptr) && !eol(*r.ptr)) return false;
        q = r.ptr;
        return true;
    }

    // Skips separators; false at the end of the line (or a `#` word: a comment), with q
    // at the line's end.
    static bool nextWord(const char*& q, const char* e) {
        while (q < e && sep(*q))
            ++q;
        if (q < e && *q == '#') toEol(q, e);
        return q < e && !eol(*q);
    }

    // `v`/`vt` (minWords numbers at least, limit on the first three for `v`): all numbers.
    bool fastNumbers(const char*& q, const char* e, std::size_t minNumbers, bool limit) {
        std::size_t i = 0;
        double v = 0;
        while (nextWord(q, e)) {
            if (!fastNumber(q, e, v)) return false;
            if (limit && ++i <= 3 && !(std::abs(v) <= kObjMaxCoordinate)) return false;
            if (!limit) ++i;
        }
        return i >= minNumbers;
    }

    // One face word (v, v/vt, v//vn, v/vt/vn; bytes after a third '/' part are not read,
    // as in checkedLine): true when each given index is a plain decimal int
    // (from_chars, whole part), non-zero, within ±(2^31 − 1) and, if relative, not before
    // the first element.
    bool fastCorner(const char*& q, const char* e) const {
        const long long counts[3] = {nv_, nvt_, nvn_};
        const char* r = q;
        auto partEnd = [e](const char* x) { return x == e || *x == '/' || sep(*x) || eol(*x); };
        for (int k = 0;; ++k) {
            if (!partEnd(r)) {
                long long ix = 0;
                const std::from_chars_result fc = std::from_chars(r, e, ix);
                if (fc.ec != std::errc{} || !partEnd(fc.ptr)) return false;
                if (ix == 0 || ix > INT_MAX || ix < -INT_MAX || (ix < 0 && -ix > counts[k]))
                    return false;
                r = fc.ptr;
            } else if (k == 0) {
                return false; // no vertex index
            }
            if (k == 2) {
                while (r < e && !sep(*r) && !eol(*r))
                    ++r;
                break;
            }
            if (r == e || *r != '/') break;
            ++r;
        }
        q = r;
        return true;
    }

    // Checks the line at p in one pass; true (p at its end) when checkedLine would
    // accept it, and then has the same effects; false, with no effect, otherwise.
    bool fastLine(const char*& p, const char* e, int line) {
        const char* q = p;
        if (!nextWord(q, e)) {
            p = q;
            return true;
        }
        const char* const c = q;
        while (q < e && !sep(*q) && !eol(*q))
            ++q;
        const std::string_view cmd(c, std::size_t(q - c));
        if (cmd == "v") {
            if (!fastNumbers(q, e, 3, true)) return false;
            ++nv_;
        } else if (cmd == "vt") {
            if (!fastNumbers(q, e, 1, false)) return false;
            ++nvt_;
        } else if (cmd == "vn") {
            double v = 0;
            for (int i = 0; i < 3; ++i) // a bad normal (the repair) goes the checked way
                if (!nextWord(q, e) || !fastNumber(q, e, v) || !(std::abs(v) <= kObjMaxCoordinate))
                    return false;
            toEol(q, e); // words after the third are not read (as in checkedLine)
            ++nvn_;
        } else if (cmd == "f") {
            std::size_t n = 0;
            while (nextWord(q, e)) {
                if (!fastCorner(q, e)) return false;
                ++n;
            }
            if (n > kObjMaxFaceVertices) return false; // refused, with its line, the checked way
            if (n >= 3) {
                if (scan_.triangles + (n - 2) > kObjMaxTriangles) return false;
                scan_.triangles += n - 2;
                scan_.faceLines.push_back(line);
            } else {
                scan_.droppedLines.push_back(line);
            }
        } else {
            toEol(q, e); // not checked
        }
        p = q;
        return true;
    }

    FileErrors err_;
    ObjScan scan_;
    long long nv_ = 0, nvt_ = 0, nvn_ = 0; // records so far (relative indices)
};

ObjScan scanObj(std::string_view text, const std::string& path) {
    return ObjScanner(path).run(text);
}

// The .mtl values tinyobjloader would take unchecked (`d nan` hid the object): each within
// its meaning, named by the .mtl's own line.
// `materials` counts `newmtl` lines over every .mtl of the scene (kObjMaxMaterials).
void checkMtl(std::string_view text, const std::string& path, std::size_t& materials) {
    const FileErrors err(path);
    if (const int nulLine = firstNulLine(text)) err.fail(nulLine, nulByteMessage());
    forEachLine(text, [&](int line, std::string_view l) {
        const std::vector<std::string_view> w = words(l);
        if (w.empty()) return;
        if (w[0] == "newmtl" && ++materials > kObjMaxMaterials)
            err.fail(line, trf("more than %zu materials in the scene's .mtl files (the limit "
                               "for one scene, see obj_file.h)",
                               kObjMaxMaterials));
        if (w.size() < 2) return;
        const std::string cmd(w[0]);
        double lo = 0, hi = 1;
        const char* range = "[0, 1]";
        if (cmd == "Ka" || cmd == "Kd" || cmd == "Ks" || cmd == "Tf") {
            if (w[1] == "spectral" || w[1] == "xyz") return; // other colour forms: not used
        } else if (cmd == "Ke") {
            hi = 1e6;
            range = "[0, 1e6]";
        } else if (cmd == "Ns") {
            hi = 1e6;
            range = "[0, 1e6]";
        } else if (cmd == "Ni") {
            lo = -1e6;
            hi = 1e6;
            range = "[-1e6, 1e6]";
        } else if (cmd == "d" || cmd == "Tr") {
            if (w[1] == "-halo") return;
        } else {
            return;
        }
        for (std::size_t i = 1; i < w.size(); ++i) {
            const double v = err.number(w[i], line, (cmd + " value").c_str());
            if (!(v >= lo && v <= hi)) err.fail(line, cmd + " " + fmt(v) + " outside " + range);
        }
    });
}

// Reads each mtllib through readRegularFile and checkMtl. A missing .mtl is the
// documented repair (a warning, default material); one that is not a regular file, too
// large or malformed is an error, kept here and thrown after tinyobjloader returns.
class SafeMaterialReader : public tinyobj::MaterialReader {
  public:
    explicit SafeMaterialReader(std::string dir) : dir_(std::move(dir)) {}
    bool operator()(const std::string& matId, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* matMap, std::string* warn,
                    std::string* err) override {
        const std::string path = (!matId.empty() && matId[0] == '/') ? matId : dir_ + matId;
        // The name comes from the file: escaped wherever it is shown (fuzz_obj found a
        // control byte of a mtllib name in the "not found" warning).
        const std::string shown = escapeForMessage(path, 200);
        std::string text, why;
        // What is left of the scene's .mtl budget (kMtlMaxBytes for all files together).
        const std::size_t left = kMtlMaxBytes - std::min(bytes_, kMtlMaxBytes);
        if (!readRegularFile(path, left, text, why)) {
            if (why.find("No such file") != std::string::npos) {
                missing_.push_back(shown + ": material file not found; default material used");
            } else if (error_.empty()) {
                error_ = shown + ":0: " +
                         (why.rfind(shown + ": ", 0) == 0 ? why.substr(shown.size() + 2) : why);
                if (bytes_ > 0 && why.find("larger than") != std::string::npos)
                    error_ += trf(" (%zu MB for all the scene's .mtl files together; %zu bytes "
                                  "were read before this one)",
                                  kMtlMaxBytes >> 20, bytes_);
            }
            return false;
        }
        bytes_ += text.size();
        try {
            checkMtl(skipBom(text), shown, materials_);
        } catch (const SceneFileError& e) {
            if (error_.empty()) error_ = e.what();
            return false;
        }
        const std::string_view body = skipBom(text);
        MemoryBuf buf(body.data(), body.size());
        std::istream in(&buf);
        tinyobj::LoadMtl(matMap, materials, &in, warn, err);
        return true;
    }
    const std::string& error() const { return error_; }
    const std::vector<std::string>& missing() const { return missing_; }

  private:
    std::string dir_;
    std::string error_;
    std::vector<std::string> missing_;
    std::size_t bytes_ = 0;     // .mtl bytes read for this scene so far
    std::size_t materials_ = 0; // newmtl lines so far
};

void warn(ObjLoadReport& rep, const std::string& w) {
    ++rep.warningCount;
    if (rep.warnings.size() < kSceneMaxKeptWarnings) rep.warnings.push_back(w);
}

} // namespace

namespace detail {
ObjPrepass objPrepass(const std::string& text, const std::string& path, bool checkedOnly) {
    ObjPrepass r;
    try {
        ObjScan s = ObjScanner(path).run(skipBom(text), checkedOnly);
        r.faceLines = std::move(s.faceLines);
        r.droppedLines = std::move(s.droppedLines);
        r.badNormals = std::move(s.badNormals);
        r.badNormalLines = std::move(s.badNormalLines);
        r.triangles = s.triangles;
    } catch (const SceneFileError& e) {
        r.error = e.what();
    }
    return r;
}
} // namespace detail

SceneFile loadObjFile(const std::string& path, ObjLoadReport* report) {
    ObjLoadReport local;
    ObjLoadReport& rep = report ? *report : local;
    rep = ObjLoadReport{};
    // The path as messages show it: escape bytes and newlines (issue 20 point 16).
    const std::string shown = escapeForMessage(path, 4096);
    // 1. The whole file, if it is a regular file within the cap (tinyobjloader holds it
    //    and its arrays in memory anyway).
    double t0 = threadSeconds();
    auto lap = [&t0](double& into) {
        const double t = threadSeconds();
        into = t - t0;
        t0 = t;
    };
    std::string raw, why;
    if (!readRegularFile(path, kObjMaxBytes, raw, why))
        throw SceneFileError(
            shown +
            ":0: " + (why.rfind(shown + ": ", 0) == 0 ? why.substr(shown.size() + 2) : why));
    const std::string_view text = skipBom(raw);
    lap(rep.times.read);
    // 2. Numbers, indices and the triangle cap, with line numbers.
    const ObjScan scan = scanObj(text, shown);
    lap(rep.times.scan);
    // 3. tinyobjloader on the checked text; materials through SafeMaterialReader.
    const auto slash = path.find_last_of('/');
    SafeMaterialReader mtl(slash == std::string::npos ? std::string() : path.substr(0, slash + 1));
    tinyobj::attrib_t at;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string tinyWarn, tinyErr;
    MemoryBuf buf(text.data(), text.size());
    std::istream in(&buf);
    const bool ok = tinyobj::LoadObj(&at, &shapes, &materials, &tinyWarn, &tinyErr, &in, &mtl,
                                     /*triangulate=*/false, /*default_vcols_fallback=*/false);
    lap(rep.times.parse);
    if (!mtl.error().empty()) throw SceneFileError(mtl.error());
    for (const std::string& m : mtl.missing())
        warn(rep, m);
    for (const int line : scan.droppedLines)
        warn(rep, shown + ":" + std::to_string(line) + ": face with fewer than 3 vertices dropped");
    {
        std::istringstream ws(tinyWarn);
        std::string w;
        while (std::getline(ws, w)) {
            // Said above with the file's name and line.
            if (w.empty() || w == "." || w.find("Degenerated face found") != std::string::npos ||
                (!mtl.missing().empty() && w.rfind("Failed to load material", 0) == 0))
                continue;
            warn(rep, shown + ": " + escapeForMessage(w, 200));
        }
    }
    if (!ok) {
        std::string e = tinyErr;
        while (!e.empty() && (e.back() == '\n' || e.back() == '\r'))
            e.pop_back();
        throw SceneFileError(shown +
                             ":0: " + (e.empty() ? "cannot parse" : escapeForMessage(e, 200)));
    }
    const std::size_t nv = at.vertices.size() / 3, nn = at.normals.size() / 3;
    std::vector<glm::dvec3> verts(nv), norms(nn);
    for (std::size_t i = 0; i < nv; ++i) {
        verts[i] = {at.vertices[3 * i], at.vertices[3 * i + 1], at.vertices[3 * i + 2]};
        if (!finite3(verts[i])) // scanObj checked the text; a float rounding to inf is caught here
            throw SceneFileError(shown + ":0: vertex " + std::to_string(i + 1) +
                                 " is not finite as a 32-bit float");
    }
    for (std::size_t i = 0; i < nn; ++i) {
        norms[i] = {at.normals[3 * i], at.normals[3 * i + 1], at.normals[3 * i + 2]};
        if (!finite3(norms[i])) norms[i] = glm::dvec3(0.0); // repair: use the face normal
    }
    for (std::size_t k = 0; k < scan.badNormals.size(); ++k) {
        if (scan.badNormals[k] < nn) norms[scan.badNormals[k]] = glm::dvec3(0.0);
        warn(rep, shown + ":" + std::to_string(scan.badNormalLines[k]) +
                      ": normal not finite or beyond ±1e38; faces using it get their face normal");
    }

    SceneFile sf;
    sf.scene = std::make_unique<Scene>();
    Scene& s = *sf.scene;
    s.background = glm::dvec3(0.05);
    std::vector<int> mats;
    for (const tinyobj::material_t& mt : materials) {
        Material m;
        m.colour = {mt.diffuse[0], mt.diffuse[1], mt.diffuse[2]};
        m.ka = 0.1;
        m.kd = 1.0;
        m.ks = (mt.specular[0] + mt.specular[1] + mt.specular[2]) / 3.0;
        m.kr = 0.0;
        m.phongExp = mt.shininess;
        const double d = mt.dissolve;
        m.kt = std::isfinite(d) ? std::clamp(1.0 - d, 0.0, 1.0) : 0.0;
        m.medium.refract = (std::isfinite(mt.ior) && mt.ior > 0) ? mt.ior : 1.0;
        // checkMtl refused values outside their meaning; these guard what it cannot see.
        if (!finite3(m.colour)) m.colour = glm::dvec3(0.8);
        if (!std::isfinite(m.ks)) m.ks = 0;
        if (!std::isfinite(m.phongExp) || m.phongExp < 0) m.phongExp = 0;
        mats.push_back(s.addMaterial(m));
    }
    // Textures are not drawn (the tracer has no texture lookup for OBJ materials): said
    // once, naming the first, rather than ignored without a word (issue 20 point 14).
    {
        std::size_t textured = 0;
        std::string first;
        for (const tinyobj::material_t& mt : materials)
            if (!mt.diffuse_texname.empty() && textured++ == 0) first = mt.diffuse_texname;
        if (textured > 0) {
            const std::string dir =
                slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
            struct stat st {};
            const std::string firstPath = (!first.empty() && first[0] == '/') ? first : dir + first;
            const bool exists = ::stat(firstPath.c_str(), &st) == 0;
            warn(rep, shown + ": " +
                          (exists ? trf("materials naming a map_Kd texture: %zu (the first: "
                                        "'%s'); textures are not drawn by the tracer: the Kd "
                                        "colour is used",
                                        textured, escapeForMessage(first, 200).c_str())
                                  : trf("materials naming a map_Kd texture: %zu (the first: "
                                        "'%s', which does not exist); textures are not drawn "
                                        "by the tracer: the Kd colour is used",
                                        textured, escapeForMessage(first, 200).c_str())));
        }
    }
    Material def;
    def.colour = glm::dvec3(0.8);
    def.ka = 0.1;
    def.kd = 1.0;
    def.ks = 0.2;
    def.phongExp = 20;
    const int defaultMat = s.addMaterial(def);

    s.primitives.reserve(scan.triangles); // one allocation, no regrowth
    auto faceLine = [&](std::size_t k) {
        return k < scan.faceLines.size() ? scan.faceLines[k] : 0;
    };
    std::size_t faceNo = 0, dropped = 0;
    // Exact duplicates (issue 20 point 2): 1M copies of one triangle took over a minute
    // at 64x64 (a BVH cannot split identical boxes) and add nothing to the picture. A
    // triangle is the same when its corners (and normals, when smooth) are the same
    // doubles in the same order and its material is the same; the FNV-1a hash of those
    // bytes finds candidates, the coordinates confirm. Only the first triangle of each
    // hash is kept for comparison (a colliding different triangle is simply kept).
    struct TriKey {
        int v[3], n[3], m; // vertex and normal indices (n = -1: flat), material
    };
    std::vector<TriKey> kept;
    std::unordered_map<std::uint64_t, std::uint32_t> firstOfHash;
    std::size_t duplicates = 0;
    auto cornersOf = [&](const TriKey& t, int k) {
        return std::pair<glm::dvec3, glm::dvec3>(
            verts[size_t(t.v[k])], t.n[k] >= 0 ? norms[size_t(t.n[k])] : glm::dvec3(0.0));
    };
    auto isDuplicate = [&](const TriKey& t) {
        std::uint64_t h = 1469598103934665603ull;
        auto mix = [&h](const void* p, std::size_t bytes) {
            const auto* b = static_cast<const unsigned char*>(p);
            for (std::size_t i = 0; i < bytes; ++i) {
                h ^= b[i];
                h *= 1099511628211ull;
            }
        };
        for (int k = 0; k < 3; ++k) {
            const auto [pv, nv_] = cornersOf(t, k);
            const double c[6] = {pv.x + 0.0,  pv.y + 0.0,  pv.z + 0.0,
                                 nv_.x + 0.0, nv_.y + 0.0, nv_.z + 0.0}; // -0 as +0
            mix(c, sizeof c);
        }
        mix(&t.m, sizeof t.m);
        const auto [it, inserted] = firstOfHash.emplace(h, std::uint32_t(kept.size()));
        if (!inserted) {
            const TriKey& o = kept[it->second];
            bool same = o.m == t.m;
            for (int k = 0; k < 3 && same; ++k)
                same = cornersOf(o, k) == cornersOf(t, k) && (o.n[k] >= 0) == (t.n[k] >= 0);
            if (same) return true;
        }
        kept.push_back(t);
        return false;
    };
    for (const tinyobj::shape_t& shape : shapes) {
        const auto& mesh = shape.mesh;
        std::size_t base = 0;
        for (std::size_t f = 0; f < mesh.num_face_vertices.size(); ++f, ++faceNo) {
            const std::size_t n = mesh.num_face_vertices[f];
            if (base + n > mesh.indices.size())
                throw SceneFileError(shown + ":" + std::to_string(faceLine(faceNo)) +
                                     ": face index list truncated");
            if (n < 3) {
                ++dropped;
                warn(rep, shown + ":" + std::to_string(faceLine(faceNo)) +
                              ": face with fewer than 3 vertices dropped");
                base += n;
                continue;
            }
            const int mid = f < mesh.material_ids.size() ? mesh.material_ids[f] : -1;
            const int m =
                (mid >= 0 && std::size_t(mid) < mats.size()) ? mats[size_t(mid)] : defaultMat;
            bool smooth = true;
            for (std::size_t k = 0; k < n; ++k) {
                const tinyobj::index_t& ix = mesh.indices[base + k];
                if (ix.vertex_index < 0 || std::size_t(ix.vertex_index) >= nv)
                    throw SceneFileError(shown + ":" + std::to_string(faceLine(faceNo)) +
                                         ": vertex index out of range (the file has " +
                                         std::to_string(nv) + " vertices)");
                if (ix.normal_index < 0 || std::size_t(ix.normal_index) >= nn) smooth = false;
            }
            auto V = [&](std::size_t k) {
                return verts[size_t(mesh.indices[base + k].vertex_index)];
            };
            auto N = [&](std::size_t k) {
                return norms[size_t(mesh.indices[base + k].normal_index)];
            };
            for (std::size_t k = 1; k + 1 < n; ++k) {
                const std::size_t c3[3] = {0, k, k + 1};
                TriKey key{};
                key.m = m;
                for (int j = 0; j < 3; ++j) {
                    key.v[j] = mesh.indices[base + c3[j]].vertex_index;
                    key.n[j] = smooth ? mesh.indices[base + c3[j]].normal_index : -1;
                }
                if (isDuplicate(key)) {
                    ++duplicates;
                    continue;
                }
                if (smooth)
                    s.add(SmoothTriangle(V(0), V(k), V(k + 1), N(0), N(k), N(k + 1)), m);
                else
                    s.add(Triangle(V(0), V(k), V(k + 1)), m);
                ++rep.triangles;
            }
            base += n;
        }
    }
    if (duplicates > 0)
        warn(rep, shown + ": " +
                      trf("exact duplicate triangles dropped: %zu (same corners and material "
                          "as an earlier one: they add nothing to the picture)",
                          duplicates));
    // 4. Nothing to draw is an error, not an empty picture (issue 12 point 7).
    if (rep.triangles == 0) {
        std::string what = "nothing to draw: no faces with 3 or more vertices";
        dropped += scan.droppedLines.size();
        if (dropped)
            what += " (" + std::to_string(dropped) + " smaller faces dropped)";
        else if (scan.faceLines.empty())
            what += " (no `f` lines: is this an OBJ file?)";
        throw SceneFileError(shown + ":0: " + what);
    }
    sf.hasView = false;
    sf.view = frameScene(s);
    addDefaultLight(s, sf.view);
    sf.warnings = rep.warnings;
    sf.warningCount = rep.warningCount;
    lap(rep.times.build);
    return sf;
}

} // namespace wb::rt
