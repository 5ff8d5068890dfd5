// The launcher's panel under the headless shell: `workbench-panel-check --check-panel`
// lays it out as the window shows it and fails on clipped text (tests/CMakeLists.txt).
#include "common/shell.h"
#include "launcher.h"

int main(int argc, char** argv) { return wb::runLab(argc, argv, wb::makeLauncher); }
