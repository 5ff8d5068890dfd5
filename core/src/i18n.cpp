// Placeholder until the catalogues land (issue 17): English only.
#include "core/i18n.h"

#include <cstdarg>
#include <cstdio>
#include <vector>

namespace wb {

const char* tr(const char* english) { return english; }

std::string trf(const char* fmt, ...) {
    const char* translated = tr(fmt);
    va_list args;
    va_start(args, fmt);
    va_list copy;
    va_copy(copy, args);
    int n = std::vsnprintf(nullptr, 0, translated, copy);
    va_end(copy);
    std::string out;
    if (n > 0) {
        std::vector<char> buffer(static_cast<size_t>(n) + 1);
        std::vsnprintf(buffer.data(), buffer.size(), translated, args);
        out.assign(buffer.data(), static_cast<size_t>(n));
    }
    va_end(args);
    return out;
}

const std::string& language() {
    static const std::string kEnglish = "en";
    return kEnglish;
}

bool setLanguage(const std::string& code) { return code == "en"; }

} // namespace wb
