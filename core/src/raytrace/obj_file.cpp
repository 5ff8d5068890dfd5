#include "core/raytrace/obj_file.h"

#include "core/raytrace/smooth_triangle.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string_view>

namespace wb::rt {

namespace {

// Line of the k-th (0-based) line starting with `tag` ("v", "vn", "f"): only on the
// error path, so the normal load does not pay for it.
int lineOf(const std::string& path, const std::string& tag, std::size_t k) {
    std::ifstream in(path);
    std::string text;
    int line = 0;
    std::size_t seen = 0;
    while (std::getline(in, text)) {
        ++line;
        std::istringstream ls(text);
        std::string w;
        if (ls >> w && w == tag && seen++ == k) return line;
    }
    return 0;
}

bool finite3(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// tinyobjloader reads a malformed number as 0; this pass finds them first and names
// the line. Only the numeric records (v, vn, vt) are checked. One read of the whole
// file and a scan of its bytes (tokens split at the same whitespace as `>>`, each number
// checked by strtod as before): an istringstream per line cost as much as the parse.
void checkNumbers(const std::string& path) {
    std::string buf;
    {
        std::ifstream in(path, std::ios::binary);
        in.seekg(0, std::ios::end);
        buf.resize(std::size_t(std::max<std::streamoff>(in.tellg(), 0)));
        in.seekg(0);
        in.read(buf.data(), std::streamsize(buf.size()));
        buf.resize(std::size_t(in.gcount()));
    }
    auto space = [](char c) {
        return c == ' ' || c == '\t' || c == '\v' || c == '\f' || c == '\r';
    };
    const char* p = buf.data();
    const char* const end = p + buf.size();
    char token[128];
    int line = 0;
    while (p < end) {
        ++line;
        const char* eol = static_cast<const char*>(std::memchr(p, '\n', std::size_t(end - p)));
        if (!eol) eol = end;
        auto next = [&](const char*& q, std::size_t& len) { // next token of the line
            while (q < eol && space(*q))
                ++q;
            const char* t = q;
            while (q < eol && !space(*q))
                ++q;
            len = std::size_t(q - t);
            return t;
        };
        const char* q = p;
        std::size_t len;
        const char* w = next(q, len);
        const bool v = len == 1 && w[0] == 'v';
        const bool vn = len == 2 && w[0] == 'v' && w[1] == 'n';
        const bool vt = len == 2 && w[0] == 'v' && w[1] == 't';
        if (v || vn || vt) {
            int n = 0;
            while (true) {
                w = next(q, len);
                if (len == 0 || w[0] == '#') break;
                const std::string_view word(w, len);
                // The usual plain decimal: from_chars (exact, no locale, no copy). Anything
                // it does not take whole (a leading '+', hex, out of range) is judged by
                // strtod as before; both round correctly, so verdicts are unchanged.
                double x = 0;
                const auto fc = std::from_chars(w, w + len, x);
                if (fc.ec != std::errc() || fc.ptr != w + len) {
                    std::string longWord; // only for tokens that do not fit `token`
                    const char* str = token;
                    if (len < sizeof token) {
                        std::memcpy(token, w, len);
                        token[len] = '\0';
                    } else {
                        longWord.assign(w, len);
                        str = longWord.c_str();
                    }
                    char* stop = nullptr;
                    x = std::strtod(str, &stop);
                    if (stop == str || *stop != '\0')
                        throw SceneFileError(path + ":" + std::to_string(line) + ": bad number '" +
                                             std::string(word) + "'");
                }
                if (!std::isfinite(x))
                    throw SceneFileError(path + ":" + std::to_string(line) +
                                         ": non-finite vertex coordinate");
                ++n;
            }
            const int need = vt ? 1 : 3;
            if (n < need)
                throw SceneFileError(path + ":" + std::to_string(line) + ": expected " +
                                     std::to_string(need) + " numbers");
        }
        p = eol + 1;
    }
}

} // namespace

SceneFile loadObjFile(const std::string& path, ObjLoadReport* report) {
    {
        std::ifstream probe(path, std::ios::binary | std::ios::ate);
        if (!probe) throw SceneFileError(path + ":0: cannot open the file");
        // tinyobjloader holds the whole file and its arrays in memory: cap the input so
        // an enormous file is an error, not an out-of-memory.
        if (probe.tellg() > std::streamoff(kObjMaxBytes))
            throw SceneFileError(path + ":0: file larger than " +
                                 std::to_string(kObjMaxBytes >> 20) + " MB");
    }
    checkNumbers(path);
    tinyobj::ObjReaderConfig config;
    config.triangulate = false; // fans are made here, after the indices are checked
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    const bool ok = reader.ParseFromFile(path, config);
    ObjLoadReport local;
    ObjLoadReport& rep = report ? *report : local;
    if (!reader.Warning().empty()) {
        std::istringstream ws(reader.Warning());
        std::string w;
        while (std::getline(ws, w))
            if (!w.empty()) rep.warnings.push_back(path + ": " + w);
    }
    if (!ok) {
        std::string err = reader.Error();
        while (!err.empty() && (err.back() == '\n' || err.back() == '\r'))
            err.pop_back();
        throw SceneFileError(path + ":0: " + (err.empty() ? "cannot parse" : err));
    }
    const tinyobj::attrib_t& at = reader.GetAttrib();
    const std::size_t nv = at.vertices.size() / 3, nn = at.normals.size() / 3;
    std::vector<glm::dvec3> verts(nv), norms(nn);
    for (std::size_t i = 0; i < nv; ++i) {
        verts[i] = {at.vertices[3 * i], at.vertices[3 * i + 1], at.vertices[3 * i + 2]};
        if (!finite3(verts[i]))
            throw SceneFileError(path + ":" + std::to_string(lineOf(path, "v", i)) +
                                 ": non-finite vertex coordinate");
    }
    for (std::size_t i = 0; i < nn; ++i) {
        norms[i] = {at.normals[3 * i], at.normals[3 * i + 1], at.normals[3 * i + 2]};
        if (!finite3(norms[i])) norms[i] = glm::dvec3(0.0); // repair: use the face normal
    }

    SceneFile sf;
    sf.scene = std::make_unique<Scene>();
    Scene& s = *sf.scene;
    s.background = glm::dvec3(0.05);
    std::vector<int> mats;
    for (const tinyobj::material_t& mt : reader.GetMaterials()) {
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
        if (!finite3(m.colour)) m.colour = glm::dvec3(0.8);
        if (!std::isfinite(m.ks)) m.ks = 0;
        if (!std::isfinite(m.phongExp)) m.phongExp = 0;
        mats.push_back(s.addMaterial(m));
    }
    Material def;
    def.colour = glm::dvec3(0.8);
    def.ka = 0.1;
    def.kd = 1.0;
    def.ks = 0.2;
    def.phongExp = 20;
    const int defaultMat = s.addMaterial(def);

    std::size_t faceNo = 0;
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        const auto& mesh = shape.mesh;
        std::size_t base = 0;
        for (std::size_t f = 0; f < mesh.num_face_vertices.size(); ++f, ++faceNo) {
            const std::size_t n = mesh.num_face_vertices[f];
            if (base + n > mesh.indices.size())
                throw SceneFileError(path + ":" + std::to_string(lineOf(path, "f", faceNo)) +
                                     ": face index list truncated");
            if (n < 3) {
                rep.warnings.push_back(path + ":" + std::to_string(lineOf(path, "f", faceNo)) +
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
                    throw SceneFileError(path + ":" + std::to_string(lineOf(path, "f", faceNo)) +
                                         ": vertex index out of range");
                if (ix.normal_index < 0 || std::size_t(ix.normal_index) >= nn) smooth = false;
            }
            auto V = [&](std::size_t k) {
                return verts[size_t(mesh.indices[base + k].vertex_index)];
            };
            auto N = [&](std::size_t k) {
                return norms[size_t(mesh.indices[base + k].normal_index)];
            };
            for (std::size_t k = 1; k + 1 < n; ++k) {
                if (smooth)
                    s.add(SmoothTriangle(V(0), V(k), V(k + 1), N(0), N(k), N(k + 1)), m);
                else
                    s.add(Triangle(V(0), V(k), V(k + 1)), m);
                ++rep.triangles;
            }
            base += n;
        }
    }
    sf.hasView = false;
    sf.view = frameScene(s);
    addDefaultLight(s, sf.view);
    return sf;
}

} // namespace wb::rt
