#include "paths.h"
#include "shell.h"

namespace wb {

bool shellKey(int code, View& view, bool& panelVisible) {
    switch (code) {
    case '+':
    case '=':
        view.zoom *= 1.1f;
        return true;
    case '-':
        view.zoom /= 1.1f;
        return true;
    case 'h':
        panelVisible = !panelVisible;
        return true;
    default:
        return false;
    }
}

bool applyOptions(const ShellOptions& opts, Lab& lab, std::string& error) {
    setAssetRoot(opts.root);
    for (const auto& [name, value] : opts.labOptions)
        if (!lab.setOption(name, value, error)) {
            error = "--" + name + ": " + error;
            return false;
        }
    return true;
}

} // namespace wb
