#pragma once
// Wavefront OBJ through tinyobjloader: v, vt, vn, faces of any size (fans), negative
// indices, mtllib/usemtl (Kd, Ks, Ns, Ni, d -> colour, ks, Phong exponent, refraction
// index, kt = 1 − d). Faces with vertex normals are shaded with interpolated normals.
// A file without lights or camera gets a default view that frames the model and a
// light near the eye. A missing .mtl is a documented repair: a warning, the default
// material. Errors name the file, the line and the problem (issue 12: a pre-pass checks
// every number and index with its line, since tinyobjloader reads a bad number as 0 and
// wraps a huge index); .mtl values are checked the same way, each in its meaning (Ka, Kd,
// Ks, Tf, d, Tr in [0, 1]; Ke, Ns in [0, 1e6]; Ni in [-1e6, 1e6]). Line ends may be LF,
// CR LF or CR; a UTF-8 byte order mark is skipped; a line with a NUL byte is refused.
// Only regular files are read (core/file_read.h). A file without faces is an error.
#include "core/raytrace/scene_file.h"

#include <string>
#include <vector>

namespace wb::rt {

// Largest .obj accepted (about 5 million triangles; tinyobjloader keeps it all in memory).
constexpr std::size_t kObjMaxBytes = std::size_t(256) << 20;
// Largest .mtl: a material is a few lines, so 16 MB is thousands of materials; /dev/zero
// or /dev/urandom as a .mtl used to be read until memory ran out.
// The cap is per scene, not per file (issue 20 point 5: eight mtllib lines naming eight
// 12 MB files reached 3.9 GB and a bare std::bad_alloc): all .mtl files of one OBJ
// together.
constexpr std::size_t kMtlMaxBytes = std::size_t(16) << 20;
// Materials per scene: tinyobjloader's material_t takes 1,864 bytes (textures, options,
// strings) before it is turned into a Material, so 500,000 materials took 1.0 GB; 10,000
// (far more than a scene has) take 19 MB.
constexpr std::size_t kObjMaxMaterials = 10000;
// Vertices per face: tinyobjloader stores a face's count in one byte, so a 259-gon
// became 3 primitives and corrupted the faces after it (issue 20 point 8): refused.
constexpr std::size_t kObjMaxFaceVertices = 255;
// Triangles per file, the NFF cap (kNffMaxPrimitives): about 1.5 GB at peak with the BVH.
// A 256 MB file of small triangles holds about 7 million.
constexpr std::size_t kObjMaxTriangles = 4000000;
// Largest |vertex coordinate|: tinyobjloader reads 32-bit floats (FLT_MAX ≈ 3.4e38), so a
// larger value would become infinite.
constexpr double kObjMaxCoordinate = 1e38;

// Thread CPU seconds of each step of one load, so tests/bench/obj_load_bench can show
// where the time goes without a profiler.
struct ObjLoadTimes {
    double read = 0;  // the file into memory (readRegularFile)
    double scan = 0;  // the checking pre-pass: numbers, indices, line numbers
    double parse = 0; // tinyobjloader's LoadObj on the text in memory (and any .mtl)
    double build = 0; // arrays to triangles, materials, default view and light
};

struct ObjLoadReport {
    // Repairs made (missing .mtl, faces with < 3 vertices dropped, normals repaired): the
    // first kSceneMaxKeptWarnings messages, "file:line: what".
    std::vector<std::string> warnings;
    std::size_t warningCount = 0; // all warnings, kept or not
    std::size_t triangles = 0;    // after fan triangulation
    ObjLoadTimes times;           // of this load (steps that ran; an error stops the clock)
};

SceneFile loadObjFile(const std::string& path, ObjLoadReport* report = nullptr);

namespace detail {
// The checking pre-pass of loadObjFile alone, for tests: what it found, or the error it
// raised. `checkedOnly` sends every line through the line-by-line reference checks;
// otherwise lines take the one-pass fast path that loadObjFile uses (which hands any
// line it is unsure of to the reference), so the two must always agree.
struct ObjPrepass {
    std::string error;                   // the SceneFileError's message, or empty
    std::vector<int> faceLines;          // lines of faces with 3 or more vertices
    std::vector<int> droppedLines;       // lines of faces with fewer
    std::vector<std::size_t> badNormals; // `vn` records repaired (0-based)
    std::vector<int> badNormalLines;     // and their lines
    std::size_t triangles = 0;           // after fan triangulation
};
ObjPrepass objPrepass(const std::string& text, const std::string& path, bool checkedOnly);
} // namespace detail

} // namespace wb::rt
