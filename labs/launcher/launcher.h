#pragma once
// The workbench launcher: a window listing every lab; choosing one starts its
// executable. With no display it renders every lab headless instead.
#include "common/lab.h"

#include <string>
#include <vector>

namespace wb {

std::unique_ptr<Lab> makeLauncher();
// Renders every lab with its headless renderer into `outDir`; returns the number that failed.
int renderAllHeadless(const std::string& outDir, const std::string& size);
// The flags every lab the launcher starts gets (the launcher's own command line less what
// only concerns its window or its headless run: --ui-scale, --lang, --root pass on).
void setLabFlags(std::vector<std::string> flags);
std::vector<std::string> labFlagsFrom(int argc, const char* const* argv);
// The folder holding the lab executables (the launcher's own folder).
std::string binDir();

} // namespace wb
