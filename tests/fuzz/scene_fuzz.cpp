#include "scene_fuzz.h"

#include "core/raytrace/bvh.h"
#include "core/raytrace/nff.h"
#include "core/raytrace/obj_file.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

void fuzzNff(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    std::istringstream in(text);
    wb::rt::NffDocument doc;
    try {
        doc = wb::rt::readNff(in, "fuzz.nff");
    } catch (const wb::rt::SceneFileError&) {
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
        wb::rt::SceneFile sf = wb::rt::toScene(doc);
        wb::rt::Bvh bvh(sf.scene->primitives);
        (void)bvh;
    } catch (const wb::rt::SceneFileError&) {
    }
}

void fuzzObj(const std::uint8_t* data, std::size_t size) {
    // One file per process: libFuzzer runs inputs one after another in a process.
    static const std::string path = [] {
        const char* dir = std::getenv("TMPDIR");
        return std::string(dir ? dir : "/tmp") + "/wb_fuzz_" + std::to_string(getpid()) + ".obj";
    }();
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    }
    try {
        wb::rt::SceneFile sf = wb::rt::loadObjFile(path);
        wb::rt::Bvh bvh(sf.scene->primitives);
        (void)bvh;
    } catch (const wb::rt::SceneFileError&) {
    }
}
