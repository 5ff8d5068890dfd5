#pragma once
// Asset and shader paths, resolved once: --root, else $WORKBENCH_ROOT, else an installed
// workbench's share folder beside its executable (kInstalledRootFromBin, when it holds
// shaders/), else the source tree CMake configured (WB_DEFAULT_ROOT). Never relative to the
// working directory.
#include <string>

namespace wb {

// Where the package installs the root, relative to the folder of the executables
// (CMake's install rules use the same: bin/ and share/workbench/).
constexpr const char* kInstalledRootFromBin = "../share/workbench";

void setAssetRoot(const std::string& root); // from --root; empty keeps the default
const std::string& assetRoot();
std::string assetPath(const std::string& relative); // e.g. "shaders/phong.frag"

} // namespace wb
