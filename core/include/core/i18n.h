#pragma once
// The workbench's user-visible text in the student's language. Every string a user
// reads (panel, key lists, --help, status lines, warnings, the readers' file:line
// errors) is written in English in the source and passed through tr(): the English
// text is the key (gettext's msgid), the active catalogue gives its translation.
// xgettext extracts the calls: keywords tr, trf, N_ (see i18n/README.md when present).
// Until a language is chosen (setLanguage) tr() returns its argument unchanged.
#include <string>

namespace wb {

// The translation of `english` in the active language, or `english` itself when the
// catalogue lacks it. The pointer stays valid until exit (catalogues are never freed).
const char* tr(const char* english);
inline const char* tr(const std::string& english) = delete; // translate literals only

// tr(fmt) then printf-style formatting; a translation may reorder arguments with %1$s.
std::string trf(const char* fmt, ...) __attribute__((format(printf, 1, 2)));

// Marks a literal for extraction where it cannot be translated yet (a static table):
// translate it with tr() where it is shown.
#define N_(text) text

// The active language's code ("en", "ru", ...); "en" by default.
const std::string& language();

// Switches the language while the program runs; returns false (and keeps the current one)
// when no catalogue for `code` exists. "en" always succeeds.
bool setLanguage(const std::string& code);

} // namespace wb
