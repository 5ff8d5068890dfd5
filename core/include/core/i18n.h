#pragma once
// The workbench's user-visible text in the student's language. Every string a user
// reads (panel, key lists, --help, status lines, warnings, the readers' file:line
// errors) is written in English in the source and passed through tr(): the English
// text is the key (gettext's msgid), the active catalogue gives its translation.
// xgettext extracts the calls: keywords tr, trf, N_ (see docs/i18n.md).
//
// The catalogues are gettext .po files (i18n/ru/*.po) compiled by msgfmt at build time into
// GNU .mo files that are embedded in the library and read here, without glibc's gettext:
// the language switches while the program runs and does not depend on which locales the
// machine has installed (docs/i18n.md says why).
#include <string>
#include <string_view>
#include <vector>

namespace wb {

// The translation of `english` in the active language, or `english` itself when the
// catalogue lacks it. The pointer stays valid until exit (catalogues are never freed).
// format_arg: a printf format passed through tr() is still checked against its arguments.
const char* tr(const char* english) __attribute__((format_arg(1)));
inline const char* tr(const std::string& english) = delete; // translate literals only

// tr(fmt) then printf-style formatting; a translation may reorder arguments with %1$s.
std::string trf(const char* fmt, ...) __attribute__((format(printf, 1, 2)));

// Marks a literal for extraction where it cannot be translated yet (a static table):
// translate it with tr() where it is shown.
#define N_(text) text

// The active language's code ("en", "ru", "qps"). Until setLanguage() is called it is the
// one the environment asks for (languageFromEnvironment()).
const std::string& language();

// Switches the language while the program runs; returns false (and keeps the current one)
// when no catalogue for `code` exists. "en" always succeeds.
bool setLanguage(const std::string& code);

// The language the environment asks for, in the order gettext reads it: the first entry of
// LANGUAGE (a colon-separated list) that we have, else the first of LC_ALL, LC_MESSAGES, LANG
// that is set ("ru_RU.UTF-8" -> "ru"), else "en".
std::string languageFromEnvironment();

// The codes setLanguage() accepts, "en" first: the compiled catalogues and the pseudo-language.
std::vector<std::string> languages();

// A language's own name for itself, shown in the language menu ("Русский", "English").
const char* languageName(const std::string& code);

namespace i18n {

// One message of a catalogue: the English msgid and its translation.
struct Message {
    std::string_view id;
    std::string_view str;
};

// Reads a GNU .mo file (as msgfmt writes it, either byte order). The views point into `data`,
// which must outlive them. The header entry (empty msgid) is skipped. False with a message
// when the file is not a well-formed .mo.
bool parseMo(const unsigned char* data, size_t size, std::vector<Message>& out, std::string& error);

// Every message of a language's catalogue ("ru"; for "qps", the Russian catalogue's msgids with
// their pseudo-translations); empty for "en" or an unknown code.
std::vector<Message> messages(const std::string& code);

// The pseudo-language's form of an English string: every letter accented, the whole in
// brackets and padded to ~140% of its length, so untranslated or clipped text stands out.
// printf conversions (%d, %1$s, %.2f), ImGui ids after "##" and line breaks are kept.
std::string pseudo(std::string_view english);

} // namespace i18n
} // namespace wb
