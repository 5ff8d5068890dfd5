#include "scene_fuzz.h"

#include "core/raytrace/bvh.h"
#include "core/raytrace/nff.h"
#include "core/raytrace/obj_file.h"
#include "core/raytrace/phong_model.h"
#include "core/raytrace/render.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

namespace {

// Issue 12: bytes from a file reach messages escaped, so no control byte (an escape
// sequence, a NUL that cuts the text) may appear in one.
void checkMessage(const std::string& msg) {
    for (const char ch : msg) {
        const auto c = static_cast<unsigned char>(ch);
        if (c < 0x20 || c == 0x7f) {
            std::fprintf(stderr, "control byte 0x%02x in a message: %s\n", unsigned(c),
                         msg.c_str());
            std::abort();
        }
    }
}

// Issue 12: no NaN or Inf may reach a pixel of any scene a reader accepts. A few rays
// through the scene's own view (every file is small: the fuzzers cap inputs at 4 KB).
void renderFinite(const wb::rt::SceneFile& sf) {
    wb::rt::Bvh bvh(sf.scene->primitives);
    sf.scene->setAggregate(&bvh);
    const wb::rt::PhongModel model;
    wb::rt::RenderStats st;
    wb::rt::TraceSettings ts;
    ts.maxRaysPerSample = 64; // bounded work per input; the budget itself is exercised too
    wb::rt::render(*sf.scene, sf.camera(), model, 4, 3, ts, &st);
    sf.scene->setAggregate(nullptr);
    if (st.nonFinitePixels != 0) {
        std::fprintf(stderr, "%lld non-finite pixels from an accepted scene\n", st.nonFinitePixels);
        std::abort();
    }
    for (const std::string& w : sf.warnings)
        checkMessage(w);
}

std::string tempBase() {
    const char* dir = std::getenv("TMPDIR");
    return std::string(dir ? dir : "/tmp") + "/wb_fuzz_" + std::to_string(getpid());
}

} // namespace

void fuzzNff(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    std::istringstream in(text);
    wb::rt::NffDocument doc;
    try {
        doc = wb::rt::readNff(in, "fuzz.nff");
    } catch (const wb::rt::SceneFileError& e) {
        checkMessage(e.what());
        return;
    }
    std::ostringstream once;
    wb::rt::writeNff(once, doc);
    std::istringstream back(once.str());
    const wb::rt::NffDocument doc2 = wb::rt::readNff(back, "fuzz-rewritten.nff"); // must parse
    std::ostringstream twice;
    wb::rt::writeNff(twice, doc2);
    if (once.str() != twice.str()) {
        std::fprintf(stderr, "NFF write/read/write is not stable\n");
        std::abort();
    }
    try {
        const wb::rt::SceneFile sf = wb::rt::toScene(doc);
        renderFinite(sf);
    } catch (const wb::rt::SceneFileError& e) {
        checkMessage(e.what());
    }
}

void fuzzObj(const std::uint8_t* data, std::size_t size) {
    // One .obj and one .mtl per process: libFuzzer runs inputs one after another in a
    // process. Input after a line "#MTL" becomes the .mtl that the .obj names (so .mtl
    // values and missing/odd material files are fuzzed too); without it there is none.
    static const std::string base = tempBase();
    static const std::string objPath = base + ".obj", mtlPath = base + ".mtl";
    static const std::string mtlName = mtlPath.substr(mtlPath.find_last_of('/') + 1);
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    const std::string marker = "#MTL\n";
    const auto at = bytes.find(marker);
    std::string obj = bytes;
    std::remove(mtlPath.c_str());
    if (at != std::string::npos) {
        std::ofstream(mtlPath, std::ios::binary | std::ios::trunc)
            .write(bytes.data() + at + marker.size(),
                   std::streamsize(bytes.size() - at - marker.size()));
        obj = "mtllib " + mtlName + "\n" + bytes.substr(0, at);
    }
    std::ofstream(objPath, std::ios::binary | std::ios::trunc)
        .write(obj.data(), std::streamsize(obj.size()));
    try {
        const wb::rt::SceneFile sf = wb::rt::loadObjFile(objPath);
        renderFinite(sf);
    } catch (const wb::rt::SceneFileError& e) {
        checkMessage(e.what());
    }
}
