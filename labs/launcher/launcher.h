#pragma once
// The workbench launcher: a window listing every lab; choosing one starts its
// executable. With no display it renders every lab headless instead.
#include "common/lab.h"

#include <string>

namespace wb {

std::unique_ptr<Lab> makeLauncher();
// Renders every lab with its headless renderer into `outDir`; returns the number that failed.
int renderAllHeadless(const std::string& outDir, const std::string& size);
// The folder holding the lab executables (the launcher's own folder).
std::string binDir();

} // namespace wb
