#pragma once
// Wavefront OBJ through tinyobjloader: v, vt, vn, faces of any size (fans), negative
// indices, mtllib/usemtl (Kd, Ks, Ns, Ni, d -> colour, ks, Phong exponent, refraction
// index, kt = 1 − d). Faces with vertex normals are shaded with interpolated normals.
// A file without lights or camera gets a default view that frames the model and a
// light near the eye. A missing .mtl is a documented repair: a warning, the default
// material. Errors name the file, the line (when tinyobjloader gives one) and the problem.
#include "core/raytrace/scene_file.h"

#include <string>
#include <vector>

namespace wb::rt {

// Largest .obj accepted (about 5 million triangles; tinyobjloader keeps it all in memory).
constexpr std::size_t kObjMaxBytes = std::size_t(256) << 20;

struct ObjLoadReport {
    std::vector<std::string> warnings; // repairs made (missing .mtl, degenerate faces dropped)
    std::size_t triangles = 0;         // after fan triangulation
};

SceneFile loadObjFile(const std::string& path, ObjLoadReport* report = nullptr);

} // namespace wb::rt
