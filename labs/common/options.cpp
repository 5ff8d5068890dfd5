#include "options.h"

#include "cli_values.h"
#include "keyboard_layout.h"

#include "core/i18n.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace wb {
namespace {

// Largest side we accept for --size: OSMesa's limit is 16384, and 8192² RGBA is already 256 MiB.
constexpr int kMaxSide = 8192;

// The flags the shell declares that take a value (see cli::joinValues).
const std::vector<std::string> kValueFlags = {"--out",    "--size",       "--keys",     "--root",
                                              "--frames", "--screenshot", "--ui-scale", "--lang"};

bool parseScale(const std::string& s, float& out) {
    char* end = nullptr;
    const float v = std::strtof(s.c_str(), &end);
    if (s.empty() || *end != '\0' || !(v >= kMinUiScale && v <= kMaxUiScale)) return false;
    out = v;
    return true;
}

// "en, ru, qps" for the messages about --lang.
std::string languageList() {
    std::string list;
    for (const auto& code : languages())
        list += (list.empty() ? "" : ", ") + code;
    return list;
}

} // namespace

bool applyLanguageFlag(int argc, const char* const* argv) {
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--lang" && i + 1 < argc) return setLanguage(argv[i + 1]);
        if (arg.rfind("--lang=", 0) == 0) return setLanguage(arg.substr(7));
    }
    return true;
}

bool parseOptions(int argc, const char* const* argv, const std::vector<OptionHelp>& labOptions,
                  ShellOptions& o, std::string& error) {
    CLI::App app{"lab"};
    app.set_help_flag(); // --help prints usageText(), our own format with the lab's keys
    app.allow_extras();  // unknown flags and stray words are reported below, in our words
    app.option_defaults()->multi_option_policy(
        CLI::MultiOptionPolicy::TakeLast); // as before: the last wins
    std::string
        valueError; // set by a value check before it throws, so our message is the one shown
    auto check = [&valueError](const std::string& flag, bool ok, const std::string& message) {
        if (ok) return;
        valueError = message;
        throw CLI::ValidationError(flag, message);
    };
    app.add_flag("--headless", o.headless);
    app.add_flag("-h,--help", o.help);
    app.add_option_function<std::string>("--out", [&](const std::string& v) {
        check("--out", !v.empty(), tr("--out needs a file name"));
        o.out = v;
    });
    CLI::Option* size =
        cli::addSizeOption(app, "--size", kMaxSide, o.width, o.height, valueError, "");
    app.add_option_function<std::string>("--keys", [&](const std::string& v) {
        std::vector<int> codes;
        std::string keyError;
        check("--keys", parseKeys(v, codes, keyError), keyError);
        o.keys = v;
    });
    app.add_option("--root", o.root);
    app.add_option_function<std::string>("--frames", [&](const std::string& v) {
        check("--frames", cli::parseInt(v, 1, 1000000, o.frames),
              trf("--frames '%s': expected a positive count", v.c_str()));
    });
    app.add_flag("--smoke", o.smoke);
    app.add_option("--screenshot", o.screenshot);
    app.add_option_function<std::string>("--ui-scale", [&](const std::string& v) {
        check("--ui-scale", parseScale(v, o.uiScale),
              trf("--ui-scale '%s': expected a number from 0.5 to 4 (1 = normal size)", v.c_str()));
    });
    app.add_flag("--check-panel", o.checkPanel);
    app.add_option_function<std::string>("--lang", [&](const std::string& v) {
        check("--lang", setLanguage(v),
              trf("--lang '%s': expected one of %s", v.c_str(), languageList().c_str()));
        o.lang = v;
    });

    // The lab's own options, kept in command-line order for Lab::setOption.
    std::vector<std::string> valueFlags = kValueFlags;
    std::vector<std::vector<std::string>> labValues(labOptions.size());
    std::vector<const CLI::Option*> labFlags(labOptions.size());
    try {
        for (size_t i = 0; i < labOptions.size(); ++i) {
            const std::string flag = "--" + labOptions[i].name;
            if (labOptions[i].argument.empty()) {
                labFlags[i] =
                    app.add_flag(flag)->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
            } else {
                labFlags[i] = app.add_option(flag, labValues[i])
                                  ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
                valueFlags.push_back(flag);
            }
        }
    } catch (const CLI::Error& e) {
        error = trf("the lab's options clash with the shell's: %s", e.what());
        return false;
    }

    error.clear();
    const std::vector<std::string> args = cli::joinValues(argc, argv, valueFlags, error);
    if (!error.empty()) return false;
    try {
        app.parse(
            std::vector<std::string>(args.rbegin(), args.rend())); // CLI11 takes them reversed
    } catch (const CLI::ParseError& e) {
        if (!valueError.empty()) {
            error = valueError;
        } else {
            // The only other failure left: a value flag last on the line, e.g. `--out`.
            std::string what = e.what();
            auto colon = what.find(':');
            error = trf("%s needs a value",
                        (colon != std::string::npos ? what.substr(0, colon) : what).c_str());
        }
        return false;
    }
    o.sizeGiven = size && size->count() > 0;
    const auto extras = app.remaining();
    if (!extras.empty()) {
        const std::string& arg = extras.front();
        error = arg.rfind('-', 0) == 0 ? trf("unknown option %s (see --help)", arg.c_str())
                                       : trf("unexpected argument '%s' (see --help)", arg.c_str());
        return false;
    }
    std::vector<size_t> seen(labOptions.size(), 0);
    for (const CLI::Option* opt : app.parse_order())
        for (size_t i = 0; i < labOptions.size(); ++i)
            if (opt == labFlags[i]) {
                const size_t k = seen[i]++;
                o.labOptions.emplace_back(
                    labOptions[i].name, labOptions[i].argument.empty() ? "1" : labValues[i].at(k));
            }
    if (o.headless && o.out.empty() && !o.help && !o.checkPanel) {
        error = tr("--headless needs --out FILE.png");
        return false;
    }
    return true;
}

bool parseKeys(const std::string& keys, std::vector<int>& codes, std::string& error) {
    static const std::pair<const char*, int> named[] = {
        {"left", kKeyLeft},   {"right", kKeyRight},   {"up", kKeyUp},     {"down", kKeyDown},
        {"pgup", kKeyPageUp}, {"pgdn", kKeyPageDown}, {"home", kKeyHome}, {"end", kKeyEnd},
        {"esc", 27},          {"space", ' '},         {"{", '{'},
    };
    codes.clear();
    for (size_t i = 0; i < keys.size(); ++i) {
        char c = keys[i];
        if (static_cast<unsigned char>(c) >= 0x80) { // typed on the Russian layout: 'п' is 'g'
            const size_t at = i;
            const int us = usKeyForRussian(decodeUtf8(keys, i));
            if (us < 0) {
                error = trf("--keys: '%s' is not a key of the US or Russian layout",
                            keys.substr(at, i - at).c_str());
                return false;
            }
            codes.push_back(us);
            --i; // the loop steps past the character's last byte
            continue;
        }
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
            error = trf("--keys: unclosed '{' at position %zu", i);
            return false;
        }
        std::string name = keys.substr(i + 1, end - i - 1);
        int code = -1;
        for (const auto& [n, k] : named)
            if (name == n) code = k;
        int f = 0;
        if (code < 0 && name.size() >= 2 && name[0] == 'f' &&
            cli::parseInt(name.substr(1), 1, 12, f))
            code = kKeyF1 + f - 1;
        if (code < 0) {
            error = trf("--keys: unknown key name {%s}", name.c_str());
            return false;
        }
        codes.push_back(code);
        i = end;
    }
    return true;
}

float maxUiScaleFor(int width) {
    return std::floor(float(width) * kMaxPanelShare / float(kPanelWidth) * 100.0f) / 100.0f;
}

int sceneViewHeight(int sceneWidth, int sceneHeight) {
    const int most = int(float(sceneWidth) / kMinSceneAspect + 0.5f);
    return std::max(1, std::min(sceneHeight, most));
}

WindowFit fitWindow(const ShellOptions& opts, bool panelFillsWindow, int screenWidth,
                    int screenHeight, float uiScale) {
    WindowFit f;
    const int maxW = std::max(320, screenWidth - kScreenMarginX);
    const int maxH = std::max(240, screenHeight - kScreenMarginY);
    const float grow = std::max(1.0f, uiScale);
    if (panelFillsWindow) { // the launcher: its cards want room as the text grows, and no more
        // (they keep their size: a taller window would show an empty lower half)
        f.height =
            std::min(maxH, opts.sizeGiven ? opts.height : int(float(opts.height) * grow + 0.5f));
        f.width =
            std::min(maxW, opts.sizeGiven ? opts.width : int(float(opts.width) * grow + 0.5f));
        f.uiScale = uiScale;
        return f;
    }
    // By default a lab's window is as tall as the screen allows: the panel gets its lines and
    // the scene its height at any scale. An explicit --size asks for that scene size.
    f.height = std::min(maxH, opts.sizeGiven ? opts.height : maxH);
    // The scene 4:3 at the window's height, never narrower than the headless image's width.
    const int wide = std::max(opts.width, int(float(f.height) * kMinSceneAspect + 0.5f));
    const int scene = opts.sizeGiven ? opts.width : wide;
    const int panel = int(float(kPanelWidth) * uiScale + 0.5f);
    f.width = std::min(maxW, scene + panel);
    f.uiScale = std::max(kMinUiScale, std::min(uiScale, maxUiScaleFor(f.width)));
    f.panelWidth = int(float(kPanelWidth) * f.uiScale + 0.5f);
    return f;
}

std::string usageText(const std::string& program, const Lab& lab) {
    const bool fills = lab.panelFillsWindow();
    const std::string image = std::to_string(kDefaultWidth) + "x" + std::to_string(kDefaultHeight);
    std::ostringstream s;
    s << lab.title() << "\n\n" << trf("usage: %s [options]", program.c_str()) << "\n\n";
    // One flag and its help, the help starting in column 24 (continuation lines too).
    auto flag = [&s](const std::string& name, const std::string& help) {
        s << "  " << name << std::string(name.size() < 22 ? 22 - name.size() : 1, ' ');
        for (char c : help)
            s << c << (c == '\n' ? std::string(24, ' ') : "");
        s << "\n";
    };
    flag("--headless", tr("render with OSMesa (no window) and exit; needs --out"));
    flag("--out FILE.png", tr("where the headless render goes"));
    if (fills)
        flag("--size WxH", trf("window size in pixels (default %s)", image.c_str()));
    else
        flag("--size WxH", trf("headless: image size (default %s); windowed: the scene's\nsize, "
                               "the panel (%d px at --ui-scale 1) is added beside it;\nwithout "
                               "--size the window takes the screen's height less\n%d px, the "
                               "scene 4:3 beside the panel, within the screen",
                               image.c_str(), kPanelWidth, kScreenMarginY));
    flag("--ui-scale X", tr("panel text and widgets X times larger, 0.5..4 (projector: 2);\nin the "
                            "window also Ctrl+= / Ctrl+- or the panel's View slider"));
    flag("--lang ru|en", tr("the language of the window and messages (else LANGUAGE, LC_ALL,\n"
                            "LC_MESSAGES, LANG; qps: the pseudo-language that shows\n"
                            "untranslated text)"));
    flag("--keys \"...\"", tr("keys replayed before drawing, e.g. \"1g{left}\"; Russian-layout\n"
                              "letters mean the key at the same place (\"п\" is g)"));
    flag("--root DIR", tr("folder with assets/ and shaders/ (default: the source tree;\nthe "
                          "WORKBENCH_ROOT environment variable also sets it)"));
    flag("--frames N", tr("windowed: quit after N frames (smoke tests)"));
    flag("--screenshot FILE.png", tr("windowed: save the last frame before quitting"));
    flag("--smoke", tr("windowed: press each one-letter key of the lab twice, a frame apart"));
    flag("--check-panel", tr("lay the panel out as the window has it on 1024x768, 1280x800,\n"
                             "1600x1000 and 1920x1080 screens (after --keys, then after each\n"
                             "one-letter key) and fail if any text is clipped (no window)"));
    for (const auto& o : lab.options())
        flag("--" + o.name + (o.argument.empty() ? "" : " " + o.argument), o.what);
    s << "\n" << tr("Keys:") << "\n";
    // Padded by characters, not bytes: "← →" and "перетаскивание" are UTF-8.
    auto key = [&s](const std::string& name, const std::string& what) {
        size_t width = 0;
        for (unsigned char c : name)
            width += (c & 0xC0) != 0x80;
        s << "  " << name << std::string(width < 10 ? 10 - width : 1, ' ') << what << "\n";
    };
    for (const auto& k : lab.keys())
        key(k.key, k.what);
    if (!fills) {
        key("h", tr("hide/show the panel"));
        key("+/-", tr("zoom (also the wheel)"));
        key(tr("drag"), tr("rotate the scene"));
    }
    s << "  Ctrl+= / Ctrl+-  " << tr("larger / smaller panel text") << "\n";
    s << "  Esc       " << tr("quit") << "\n";
    return s.str();
}

} // namespace wb
