// The test lab as a headless executable, to test the shell's command line.
#include "common/shell.h"
#include "test_lab.h"

static std::unique_ptr<wb::Lab> make() { return wb::test::makeTestLab(); }
int main(int argc, char** argv) { return wb::runLab(argc, argv, make); }
