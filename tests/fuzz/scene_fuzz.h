#pragma once
// The bodies of the libFuzzer harnesses for the scene readers, shared by the clang
// fuzz targets (-DWORKBENCH_FUZZ=ON) and the corpus runner of the normal build.
// Each takes any bytes and must return without a crash, a hang or unbounded memory;
// bad input may only end in wb::rt::SceneFileError.
#include <cstddef>
#include <cstdint>

// Both (issue 12): every error message and warning must be free of control bytes (the
// file's bytes are escaped), and a scene that loads renders without a NaN/Inf pixel.
//
// NFF: read; if it parses, write it, read it back and write again — the two texts
// must be equal (abort otherwise) — and build and render the scene.
void fuzzNff(const std::uint8_t* data, std::size_t size);
// OBJ: the bytes become a .obj file loaded by loadObjFile; bytes after a line "#MTL"
// become a .mtl file that the .obj names with mtllib.
void fuzzObj(const std::uint8_t* data, std::size_t size);
