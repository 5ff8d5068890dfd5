#pragma once
// Asset and shader paths, resolved once: --root, else $WORKBENCH_ROOT, else the
// source tree CMake configured (WB_DEFAULT_ROOT). Never relative to the working directory.
#include <string>

namespace wb {

void setAssetRoot(const std::string& root); // from --root; empty keeps the default
const std::string& assetRoot();
std::string assetPath(const std::string& relative); // e.g. "shaders/phong.frag"

} // namespace wb
