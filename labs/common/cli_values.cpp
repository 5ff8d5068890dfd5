#include "cli_values.h"

#include "core/i18n.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdlib>

namespace wb::cli {

bool parseInt(const std::string& s, int lo, int hi, int& out) {
    if (s.empty() || s.size() > 9) return false; // 9 digits fit an int without overflow
    for (char c : s)
        if (c < '0' || c > '9') return false;
    const long v = std::strtol(s.c_str(), nullptr, 10);
    if (v < lo || v > hi) return false;
    out = int(v);
    return true;
}

bool parseSize(const std::string& s, int maxSide, int& width, int& height) {
    const auto x = s.find('x');
    if (x == std::string::npos) return false;
    int w = 0, h = 0;
    if (!parseInt(s.substr(0, x), 1, maxSide, w) || !parseInt(s.substr(x + 1), 1, maxSide, h))
        return false;
    width = w;
    height = h;
    return true;
}

std::string sizeError(const std::string& flag, const std::string& value, int maxSide) {
    return trf("%s '%s': expected WxH with 1 <= W,H <= %d", flag.c_str(), value.c_str(), maxSide);
}

bool parseThreads(const std::string& flag, const std::string& s, int& threads, std::string& error) {
    if (parseInt(s, 0, kMaxThreads, threads)) return true;
    error = trf("%s '%s': expected a thread count 0..%d (0 = all cores)", flag.c_str(), s.c_str(),
                int(kMaxThreads));
    return false;
}

CLI::Option* addSizeOption(CLI::App& app, const std::string& flag, int maxSide, int& width,
                           int& height, std::string& error, const std::string& help) {
    return app
        .add_option_function<std::string>(
            flag,
            [flag, maxSide, &width, &height, &error](const std::string& v) {
                if (!parseSize(v, maxSide, width, height)) {
                    error = sizeError(flag, v, maxSide);
                    throw CLI::ValidationError(flag, error);
                }
            },
            help)
        ->type_name("WxH");
}

CLI::Option* addThreadsOption(CLI::App& app, const std::string& flag, int& threads,
                              std::string& error, const std::string& help) {
    return app
        .add_option_function<std::string>(
            flag,
            [flag, &threads, &error](const std::string& v) {
                if (!parseThreads(flag, v, threads, error)) throw CLI::ValidationError(flag, error);
            },
            help)
        ->type_name("N");
}

std::vector<std::string> joinValues(int argc, const char* const* argv,
                                    const std::vector<std::string>& valueFlags,
                                    std::string& error) {
    std::vector<std::string> args;
    auto isValueFlag = [&](const std::string& f) {
        return std::find(valueFlags.begin(), valueFlags.end(), f) != valueFlags.end();
    };
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        // An empty value ("--out ''" or "--out=") made CLI11 take the next flag as the
        // value: `--out "" --size 16x16` wrote a file named "--size=16x16" (issue 20
        // point 12). Refused here, for every front end, naming the flag.
        const auto eq = a.find('=');
        if (eq != std::string::npos && eq + 1 == a.size() && isValueFlag(a.substr(0, eq))) {
            error = trf("%s: the value is empty", a.substr(0, eq).c_str());
            return {};
        }
        if (isValueFlag(a)) {
            if (i + 1 < argc && argv[i + 1][0] == '\0') {
                error = trf("%s: the value is empty", a.c_str());
                return {};
            }
            if (i + 1 < argc) {
                args.push_back(a + "=" + argv[++i]);
                continue;
            }
        }
        args.push_back(a);
    }
    return args;
}

} // namespace wb::cli
