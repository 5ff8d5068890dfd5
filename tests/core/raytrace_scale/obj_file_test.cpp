// The OBJ pre-pass's one-pass fast path (issue 13 item 5) against its line-by-line
// reference checks (issue 12): the fast path may only accept a line when the reference
// would accept it with the same effects, and hands every other line to the reference,
// so verdicts, messages and lines must be the same for any text. Checked on lines at
// every edge of the number and index grammars, on random texts built from those
// tokens, and on the order of errors in a large file.
#include "core/raytrace/obj_file.h"

#include <catch2/catch.hpp>

#include <fstream>
#include <random>
#include <string>
#include <vector>

using namespace wb::rt;
using Catch::Matchers::StartsWith;

namespace {

// Both ways through the pre-pass; they must agree in everything.
void checkSame(const std::string& text) {
    INFO("text: " << text);
    const detail::ObjPrepass fast = detail::objPrepass(text, "t.obj", false);
    const detail::ObjPrepass ref = detail::objPrepass(text, "t.obj", true);
    CHECK(fast.error == ref.error);
    CHECK(fast.faceLines == ref.faceLines);
    CHECK(fast.droppedLines == ref.droppedLines);
    CHECK(fast.badNormals == ref.badNormals);
    CHECK(fast.badNormalLines == ref.badNormalLines);
    CHECK(fast.triangles == ref.triangles);
}

std::string errorOf(const std::string& text) {
    return detail::objPrepass(text, "t.obj", false).error;
}

// Number words: plain decimals the fast path reads, and every form it must hand over
// (a '+', hex, nan/inf spellings, over- and underflow, cut exponents, trailing bytes).
const std::vector<std::string> kNumbers = {"0",
                                           "1",
                                           "-1",
                                           "0.5",
                                           ".5",
                                           "-.5",
                                           "5.",
                                           "-0",
                                           "00012",
                                           "1e3",
                                           "1E-3",
                                           "1e+3",
                                           "0.12345678901234567",
                                           "-1.2345678901234567e-05",
                                           "1e38",
                                           "-1e38",
                                           "1e-320",
                                           "4.9e-324",
                                           "3.4028234663852886e38",
                                           "1.0000001e38",
                                           "1e39",
                                           "1e308",
                                           "1e400",
                                           "1e-400",
                                           "+1",
                                           "+.5",
                                           "1e",
                                           "1e+",
                                           "-",
                                           ".",
                                           "-.",
                                           "0x10",
                                           "0x1p3",
                                           "nan",
                                           "-nan",
                                           "NaN",
                                           "inf",
                                           "-inf",
                                           "Infinity",
                                           "nan(12)",
                                           "1#",
                                           "1.2.3",
                                           "--1",
                                           "1-",
                                           "1e5x",
                                           "1,5",
                                           "\x01",
                                           "\xc3\xa9",
                                           "1e5.5",
                                           ".e1",
                                           "e1",
                                           "1ee2"};
// Face corners: v, v/vt, v//vn, v/vt/vn, with bad, zero, huge, relative and odd parts.
const std::vector<std::string> kCorners = {"1",           "2",
                                           "3",           "-1",
                                           "-3",          "-4",
                                           "0",           "-0",
                                           "+1",          "2147483647",
                                           "2147483648",  "-2147483647",
                                           "-2147483648", "99999999999999999999",
                                           "x",           "1/1",
                                           "1//1",        "1/1/1",
                                           "1/1/1/1",     "1/1/1/x",
                                           "1/x",         "/1",
                                           "1/",          "1//",
                                           "//",          "1/-1/-1",
                                           "1/2/3x",      "1/0",
                                           "1//0",        "1/+1",
                                           "1/1/+1",      "-2/-2/-2",
                                           "1#",          "1/#",
                                           "3/3/3"};
const std::vector<std::string> kSeps = {" ", "\t", "  ", "\v", "\f", " \t "};
const std::vector<std::string> kEnds = {"\n", "\r\n", "\r", "\r\r\n", "\n\n"};

template <class T> const T& pick(std::mt19937& rng, const std::vector<T>& v) {
    return v[std::uniform_int_distribution<std::size_t>(0, v.size() - 1)(rng)];
}

// A random line: a command (sometimes a near miss), words from the pools, separators,
// sometimes a leading blank or a trailing comment.
std::string randomLine(std::mt19937& rng) {
    static const std::vector<std::string> cmds = {"v", "v", "vt",     "vn", "vn", "f", "f", "f",
                                                  "#", "o", "usemtl", "v#", "vx", "F", ""};
    std::uniform_int_distribution<int> coin(0, 9), count(0, 6);
    std::string l;
    if (coin(rng) == 0) l += pick(rng, kSeps);
    const std::string& cmd = pick(rng, cmds);
    l += cmd;
    const bool face = cmd == "f";
    // Mostly valid words so that lines get past their first word.
    const std::vector<std::string> good =
        face ? std::vector<std::string>{"1", "2", "3", "1/1/1", "2//2", "-1", "3/3"}
             : std::vector<std::string>{"0", "1", "-0.5", "0.12345678901234567", "2e-3"};
    const int n = count(rng) + (coin(rng) < 6 ? 2 : 0);
    for (int i = 0; i < n; ++i) {
        l += pick(rng, kSeps);
        const int c = coin(rng);
        if (c < 7)
            l += pick(rng, good);
        else
            l += face ? pick(rng, kCorners) : pick(rng, kNumbers);
    }
    if (coin(rng) == 0) l += pick(rng, kSeps);
    if (coin(rng) == 0) l += " # comment 1/x nan";
    return l;
}

} // namespace

TEST_CASE("rt_obj_file: fast and reference pre-pass agree on every edge of the grammar",
          "[raytrace][obj]") {
    const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n";
    for (const std::string& x : kNumbers) {
        checkSame("v " + x + " 0 0\n");
        checkSame("v 0 0 " + x + "\n");
        checkSame("v 0 0 0 " + x + "\n"); // a 4th number: checked, no limit
        checkSame("vt " + x + "\n");
        checkSame("vn 0 " + x + " 1\n");
        checkSame("vn 0 0 1 " + x + "\n"); // words after the third: not read
    }
    for (const std::string& c : kCorners) {
        checkSame(tri + "f " + c + " 2 3\n");
        checkSame(tri + "f 1 2 " + c + "\n");
        checkSame(tri + "f " + c + "\n"); // dropped, but its index still checked
    }
    for (const std::string& end : kEnds)
        checkSame("v 0 0 0" + end + "v 1 0 0" + end + "\rv 0 1 0" + end + "f 1 2 3 # c" + end +
                  "f 1 2 x" + end);
    // Lines that are nothing but blanks, comments or other commands.
    checkSame(" \t\n#\n# v nan\nv # 1 2 3\nv#1 2 3\ng x\ns off\nusemtl m\n\n \r\n");
    checkSame(""); // empty text: no faces, no error from the pre-pass

    // What the reference says for forms only it reads (pinned, so a change shows).
    CHECK(errorOf("v +1 2 3\nvt +1\nvn +1 0 0\n" + tri + "f +1 2 3\n").empty());
    CHECK(errorOf("v 1e-400 4.9e-324 0\n").empty()); // underflow: read as 0 / subnormal
    CHECK_THAT(errorOf("v 0 1e 0\n"), StartsWith("t.obj:1: bad number '1e'"));
    CHECK_THAT(errorOf("v 0 -nan 0\n"), StartsWith("t.obj:1: non-finite vertex coordinate"));
    CHECK_THAT(errorOf("v 0 1e400 0\n"), StartsWith("t.obj:1: vertex coordinate '1e400' is"));
    CHECK_THAT(errorOf("v 0 0 0#\n"), StartsWith("t.obj:1: bad number '0#'"));
    CHECK_THAT(errorOf(tri + "f 1 2 3/3/3x\n"), StartsWith("t.obj:6: bad index '3/3/3x'"));
    CHECK(errorOf(tri + "f 1/1/1/x 2 3\n").empty()); // a 4th part is not read
    const detail::ObjPrepass vn = detail::objPrepass("vn 0 0 1\nvn 0x1p3 -nan 1\n", "t.obj", false);
    CHECK(vn.error.empty());
    CHECK(vn.badNormals == std::vector<std::size_t>{1}); // the nan: repaired later
    CHECK(vn.badNormalLines == std::vector<int>{2});
}

TEST_CASE("rt_obj_file: fast and reference pre-pass agree on random texts", "[raytrace][obj]") {
    // 3000 texts of 1-12 random lines with random line ends (fixed seed: reproducible).
    std::mt19937 rng(13005);
    std::uniform_int_distribution<int> lines(1, 12);
    for (int t = 0; t < 3000; ++t) {
        std::string text = (t % 7 == 0) ? "\xEF\xBB\xBF" : "";
        const int n = lines(rng);
        for (int i = 0; i < n; ++i)
            text += randomLine(rng) + (i + 1 < n || t % 3 ? pick(rng, kEnds) : "");
        if (t % 50 == 0) text.insert(text.size() / 2, 1, '\0'); // a NUL: reference only
        checkSame(text);
    }
}

TEST_CASE("rt_obj_file: in a large file the first problem by line is the one reported",
          "[raytrace][obj]") {
    // 30,000 good lines (taken by the fast path), then problems: the earliest line wins,
    // whichever way its line went.
    std::string big;
    for (int i = 0; i < 10000; ++i)
        big += "v 0.12345678901234567 -1.5e-3 2\nvn 0 0 1\nf -1//-1 -1//-1 -1//-1\n";
    const int next = 30001;
    CHECK(errorOf(big).empty());
    CHECK(detail::objPrepass(big, "t.obj", false).triangles == 10000);
    CHECK_THAT(errorOf(big + "v 0 1e99 0\nv 0 0 nan\n"),
               StartsWith("t.obj:" + std::to_string(next) + ": vertex coordinate 1e+99"));
    CHECK_THAT(errorOf(big + "f 1 2 3\nv 1 2\n" + std::string("v 0 0 0\0\n", 9)),
               StartsWith("t.obj:" + std::to_string(next + 1) + ": a vertex needs 3 numbers"));
    CHECK_THAT(errorOf(big + std::string("# \0\n", 4) + "v 1 2\n"),
               StartsWith("t.obj:" + std::to_string(next) + ": NUL byte"));
    CHECK_THAT(errorOf(big + "f 1 2 -30000\n"),
               StartsWith("t.obj:" + std::to_string(next) + ": relative index -30000 points"));
    CHECK_THAT(errorOf("\r\n\rv 0 0 0\r\r\nv 1\n"),
               StartsWith("t.obj:5: a vertex needs")); // CR LF, CR, CR, CR LF end lines 1-4
}
