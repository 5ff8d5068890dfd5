#include "options.h"

#include <cerrno>
#include <cstdlib>
#include <sstream>

namespace wb {
namespace {

// Largest side we accept for --size: OSMesa's limit is 16384, and 8192² RGBA is already 256 MiB.
constexpr int kMaxSide = 8192;

bool parseInt(const std::string& s, int lo, int hi, int& out) {
    if (s.empty() || s.size() > 9) return false;
    for (char c : s)
        if (c < '0' || c > '9') return false;
    long v = std::strtol(s.c_str(), nullptr, 10);
    if (v < lo || v > hi) return false;
    out = int(v);
    return true;
}

bool parseSize(const std::string& s, int& w, int& h) {
    auto x = s.find('x');
    if (x == std::string::npos) return false;
    return parseInt(s.substr(0, x), 1, kMaxSide, w) && parseInt(s.substr(x + 1), 1, kMaxSide, h);
}

} // namespace

bool parseOptions(int argc, const char* const* argv, const std::vector<OptionHelp>& labOptions,
                  ShellOptions& o, std::string& error) {
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        auto value = [&](std::string& v) {
            if (i + 1 >= argc) {
                error = arg + " needs a value";
                return false;
            }
            v = argv[++i];
            return true;
        };
        std::string v;
        if (arg == "--headless") {
            o.headless = true;
        } else if (arg == "--help" || arg == "-h") {
            o.help = true;
        } else if (arg == "--out") {
            if (!value(o.out)) return false;
            if (o.out.empty()) {
                error = "--out needs a file name";
                return false;
            }
        } else if (arg == "--size") {
            if (!value(v)) return false;
            if (!parseSize(v, o.width, o.height)) {
                error = "--size '" + v + "': expected WxH with 1 <= W,H <= " + std::to_string(kMaxSide);
                return false;
            }
        } else if (arg == "--keys") {
            if (!value(o.keys)) return false;
            std::vector<int> codes;
            if (!parseKeys(o.keys, codes, error)) return false;
        } else if (arg == "--root") {
            if (!value(o.root)) return false;
        } else if (arg == "--frames") {
            if (!value(v)) return false;
            if (!parseInt(v, 1, 1000000, o.frames)) {
                error = "--frames '" + v + "': expected a positive count";
                return false;
            }
        } else if (arg == "--smoke") {
            o.smoke = true;
        } else if (arg == "--screenshot") {
            if (!value(o.screenshot)) return false;
        } else if (arg.rfind("--", 0) == 0) {
            std::string name = arg.substr(2);
            const OptionHelp* found = nullptr;
            for (const auto& opt : labOptions)
                if (opt.name == name) found = &opt;
            if (!found) {
                error = "unknown option " + arg + " (see --help)";
                return false;
            }
            if (!found->argument.empty() && !value(v)) return false;
            o.labOptions.emplace_back(name, found->argument.empty() ? "1" : v);
        } else {
            error = "unexpected argument '" + arg + "' (see --help)";
            return false;
        }
    }
    if (o.headless && o.out.empty() && !o.help) {
        error = "--headless needs --out FILE.png";
        return false;
    }
    return true;
}

bool parseKeys(const std::string& keys, std::vector<int>& codes, std::string& error) {
    static const std::pair<const char*, int> named[] = {
        {"left", kKeyLeft}, {"right", kKeyRight},   {"up", kKeyUp},     {"down", kKeyDown},
        {"pgup", kKeyPageUp}, {"pgdn", kKeyPageDown}, {"home", kKeyHome}, {"end", kKeyEnd},
        {"esc", 27},        {"space", ' '},         {"{", '{'},
    };
    codes.clear();
    for (size_t i = 0; i < keys.size(); ++i) {
        char c = keys[i];
        if (c != '{') {
            codes.push_back(static_cast<unsigned char>(c));
            continue;
        }
        if (i + 1 < keys.size() && keys[i + 1] == '{') { // "{{" is a literal brace
            codes.push_back('{');
            ++i;
            continue;
        }
        auto end = keys.find('}', i);
        if (end == std::string::npos) {
            error = "--keys: unclosed '{' at position " + std::to_string(i);
            return false;
        }
        std::string name = keys.substr(i + 1, end - i - 1);
        int code = -1;
        for (const auto& [n, k] : named)
            if (name == n) code = k;
        int f = 0;
        if (code < 0 && name.size() >= 2 && name[0] == 'f' && parseInt(name.substr(1), 1, 12, f))
            code = kKeyF1 + f - 1;
        if (code < 0) {
            error = "--keys: unknown key name {" + name + "}";
            return false;
        }
        codes.push_back(code);
        i = end;
    }
    return true;
}

std::string usageText(const std::string& program, const Lab& lab) {
    std::ostringstream s;
    s << lab.title() << "\n\n"
      << "usage: " << program << " [options]\n\n"
      << "  --headless            render with OSMesa (no window) and exit; needs --out\n"
      << "  --out FILE.png        where the headless render goes\n"
      << "  --size WxH            image/window size in pixels (default 800x600)\n"
      << "  --keys \"...\"          keys replayed before drawing, e.g. \"1g{left}\"\n"
      << "  --root DIR            folder with assets/ and shaders/ (default: the source tree;\n"
      << "                        the WORKBENCH_ROOT environment variable also sets it)\n"
      << "  --frames N            windowed: quit after N frames (smoke tests)\n"
      << "  --screenshot FILE.png windowed: save the last frame before quitting\n"
      << "  --smoke               windowed: press each one-letter key of the lab twice, a frame apart\n";
    for (const auto& o : lab.options()) {
        std::string flag = "--" + o.name + (o.argument.empty() ? "" : " " + o.argument);
        s << "  " << flag << std::string(flag.size() < 22 ? 22 - flag.size() : 1, ' ') << o.what << "\n";
    }
    s << "\nKeys:\n";
    for (const auto& k : lab.keys())
        s << "  " << k.key << std::string(k.key.size() < 10 ? 10 - k.key.size() : 1, ' ') << k.what << "\n";
    s << "  h         hide/show the panel\n  +/-       zoom\n  Esc       quit\n";
    return s.str();
}

} // namespace wb
