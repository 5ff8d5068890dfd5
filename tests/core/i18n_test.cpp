// The catalogues (issue 17): the .mo reader, language choice and switching, the pseudo-language,
// and the course's terms (i18n/glossary.tsv) in every Russian translation.
#include "core/i18n.h"

#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

// A .mo file as msgfmt writes it: header, msgid table, msgstr table, strings (no hash table).
std::vector<unsigned char> makeMo(const std::vector<std::pair<std::string, std::string>>& msgs,
                                  bool bigEndian) {
    std::vector<unsigned char> out;
    auto word = [&](uint32_t v) {
        for (int i = 0; i < 4; ++i)
            out.push_back(static_cast<unsigned char>(bigEndian ? v >> (24 - 8 * i) : v >> (8 * i)));
    };
    const uint32_t n = uint32_t(msgs.size());
    const uint32_t ids = 28, strs = ids + 8 * n;
    uint32_t data = strs + 8 * n;
    word(0x950412de);
    word(0);
    word(n);
    word(ids);
    word(strs);
    word(0);
    word(0);
    std::string blob;
    std::vector<uint32_t> idOff, strOff;
    for (const auto& m : msgs) {
        idOff.push_back(data + uint32_t(blob.size()));
        blob += m.first + '\0';
    }
    for (const auto& m : msgs) {
        strOff.push_back(data + uint32_t(blob.size()));
        blob += m.second + '\0';
    }
    for (uint32_t i = 0; i < n; ++i) {
        word(uint32_t(msgs[i].first.size()));
        word(idOff[i]);
    }
    for (uint32_t i = 0; i < n; ++i) {
        word(uint32_t(msgs[i].second.size()));
        word(strOff[i]);
    }
    out.insert(out.end(), blob.begin(), blob.end());
    return out;
}

// Lower case for ASCII and the Russian alphabet (Ё too), enough to compare stems.
std::string lower(const std::string& s) {
    std::string out;
    for (size_t i = 0; i < s.size(); ++i) {
        const auto b = static_cast<unsigned char>(s[i]);
        if (b == 0xD0 && i + 1 < s.size()) {
            const auto c = static_cast<unsigned char>(s[i + 1]);
            if (c >= 0x90 && c <= 0x9F) { // А..П -> а..п
                out += char(0xD0), out += char(c + 0x20), ++i;
                continue;
            }
            if (c >= 0xA0 && c <= 0xAF) { // Р..Я -> р..я (next block)
                out += char(0xD1), out += char(c - 0x20), ++i;
                continue;
            }
            if (c == 0x81) { // Ё -> ё
                out += char(0xD1), out += char(0x91), ++i;
                continue;
            }
        }
        out += char(b < 0x80 ? std::tolower(b) : b);
    }
    return out;
}

std::vector<std::string> split(const std::string& s, char sep) {
    std::vector<std::string> out;
    std::stringstream in(s);
    std::string part;
    while (std::getline(in, part, sep))
        out.push_back(part);
    return out;
}

struct LanguageGuard { // each test leaves the language as it found it
    std::string saved = wb::language();
    ~LanguageGuard() { wb::setLanguage(saved); }
};

} // namespace

TEST_CASE(".mo reader: both byte orders, the header skipped") {
    const std::vector<std::pair<std::string, std::string>> msgs = {
        {"", "Content-Type: text/plain; charset=UTF-8\n"}, {"quit", "выход"}, {"a\0b", "x\0y"}};
    for (bool big : {false, true}) {
        const auto mo = makeMo(msgs, big);
        std::vector<wb::i18n::Message> out;
        std::string error;
        REQUIRE(wb::i18n::parseMo(mo.data(), mo.size(), out, error));
        REQUIRE(out.size() == 2);
        CHECK(out[0].id == "quit");
        CHECK(out[0].str == "выход");
        CHECK(out[1].id == "a"); // a plural entry: looked up by its singular
    }
}

TEST_CASE(".mo reader: damaged files are refused, never read past the end") {
    const auto good = makeMo({{"quit", "выход"}}, false);
    std::vector<wb::i18n::Message> out;
    std::string error;
    for (size_t n = 0; n < good.size(); ++n) // every truncation
        CHECK_FALSE(wb::i18n::parseMo(good.data(), n, out, error));
    auto bad = good;
    bad[0] ^= 1;
    CHECK_FALSE(wb::i18n::parseMo(bad.data(), bad.size(), out, error));
    CHECK(error.find("magic") != std::string::npos);
    bad = good;
    bad[32] = 0xff; // the msgid's offset far outside the file
    CHECK_FALSE(wb::i18n::parseMo(bad.data(), bad.size(), out, error));
    bad = good;
    bad[8] = 0xff; // a string count the tables cannot hold
    CHECK_FALSE(wb::i18n::parseMo(bad.data(), bad.size(), out, error));
}

TEST_CASE("tr: Russian, English and back while running; unknown text stays English") {
    LanguageGuard guard;
    REQUIRE(wb::setLanguage("ru"));
    CHECK(std::string(wb::tr("quit")) == "выход");
    CHECK(wb::trf("%.2f ms/frame", 1.5) == "1.50 мс/кадр");
    const char* unknown = "not in any catalogue";
    CHECK(wb::tr(unknown) == unknown);
    CHECK(std::string(wb::tr("")).empty()); // never the catalogue's header
    CHECK_FALSE(wb::setLanguage("xx"));
    CHECK(wb::language() == "ru");
    REQUIRE(wb::setLanguage("en"));
    CHECK(std::string(wb::tr("quit")) == "quit");
    const auto langs = wb::languages();
    CHECK(langs.front() == "en");
    CHECK(std::find(langs.begin(), langs.end(), "ru") != langs.end());
    CHECK(std::find(langs.begin(), langs.end(), "qps") != langs.end());
}

TEST_CASE("language from the environment: LANGUAGE, then LC_ALL, LC_MESSAGES, LANG") {
    const char* names[] = {"LANGUAGE", "LC_ALL", "LC_MESSAGES", "LANG"};
    std::vector<std::pair<std::string, bool>> saved;
    for (const char* n : names) {
        const char* v = std::getenv(n);
        saved.emplace_back(v ? v : "", v != nullptr);
    }
    auto set = [&](const char* language, const char* all, const char* messages, const char* lang) {
        const char* values[] = {language, all, messages, lang};
        for (int i = 0; i < 4; ++i)
            values[i] ? setenv(names[i], values[i], 1) : unsetenv(names[i]);
    };
    set(nullptr, nullptr, nullptr, nullptr);
    CHECK(wb::languageFromEnvironment() == "en");
    set(nullptr, nullptr, nullptr, "ru_RU.UTF-8");
    CHECK(wb::languageFromEnvironment() == "ru");
    set(nullptr, "C.UTF-8", nullptr, "ru_RU.UTF-8"); // LC_ALL wins over LANG
    CHECK(wb::languageFromEnvironment() == "en");
    set(nullptr, nullptr, "ru_RU.UTF-8", "en_GB.UTF-8"); // LC_MESSAGES over LANG
    CHECK(wb::languageFromEnvironment() == "ru");
    set("de:ru:en", "C", nullptr, nullptr); // LANGUAGE: the first we have
    CHECK(wb::languageFromEnvironment() == "ru");
    set(nullptr, nullptr, nullptr, "de_DE.UTF-8"); // a language we lack: English
    CHECK(wb::languageFromEnvironment() == "en");
    for (int i = 0; i < 4; ++i)
        saved[size_t(i)].second ? setenv(names[i], saved[size_t(i)].first.c_str(), 1)
                                : unsetenv(names[i]);
}

TEST_CASE("pseudo-language: brackets, accents, +40%, printf conversions and ImGui ids kept") {
    const std::string p = wb::i18n::pseudo("seed %d of %1$s, %.3f%% done, %zu left##seed");
    CHECK(p.rfind("[", 0) == 0);
    CHECK(p.substr(p.size() - 7) == "]##seed");
    for (const char* conv : {"%d", "%1$s", "%.3f", "%%", "%zu"})
        CHECK(p.find(conv) != std::string::npos);
    CHECK(p.find("šééď") != std::string::npos);
    const std::string plain = "measure fps";
    CHECK(wb::i18n::pseudo(plain).size() >= plain.size() * 14 / 10);
    LanguageGuard guard;
    REQUIRE(wb::setLanguage("qps"));
    CHECK(std::string(wb::tr("quit")) == wb::i18n::pseudo("quit"));
    const char* unknown = "not in any catalogue";
    CHECK(wb::tr(unknown) == unknown); // untranslated text stays visible as English
}

TEST_CASE("catalogue: every Russian translation keeps its msgid's printf conversions") {
    const std::regex conv(
        R"(%(?:\d+\$)?[-+ #0']*\d*(?:\.\d+)?(?:hh|h|ll|l|z|j|t|L)?[diouxXeEfFgGcsp%])");
    auto conversions = [&](std::string_view s) {
        std::vector<std::string> out;
        const std::string str(s);
        for (auto it = std::sregex_iterator(str.begin(), str.end(), conv);
             it != std::sregex_iterator(); ++it) {
            std::string c = it->str();
            // The kind only: %1$s reorders, %.0s prints nothing (an English plural "s" the
            // translation does not need) - the argument's type is what must match.
            c = std::regex_replace(c, std::regex(R"(%(?:\d+\$)?[-+ #0']*\d*(?:\.\d+)?)"), "%");
            out.push_back(c);
        }
        std::sort(out.begin(), out.end());
        return out;
    };
    const auto msgs = wb::i18n::messages("ru");
    REQUIRE(msgs.size() > 400);
    for (const auto& m : msgs) {
        INFO(std::string(m.id));
        CHECK(conversions(m.id) == conversions(m.str));
    }
}

TEST_CASE("glossary: every course term of an English string is in its Russian translation") {
    std::ifstream in(WB_SOURCE_DIR "/i18n/glossary.tsv");
    REQUIRE(in);
    const auto msgs = wb::i18n::messages("ru");
    std::string line;
    int terms = 0, checked = 0, failures = 0;
    bool header = true;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        if (header) { // the column names
            header = false;
            continue;
        }
        const auto cols = split(line, '\t');
        REQUIRE(cols.size() >= 4);
        ++terms;
        std::string english = cols[0];
        const bool prefix = !english.empty() && english.back() == '*';
        if (prefix) english.pop_back();
        // A whole word or phrase, not part of an identifier (GL_SPECULAR); with * any ending.
        // Case-insensitive, except names (Phong, Bezier: "phong" is a command-line value).
        const bool name = english[0] >= 'A' && english[0] <= 'Z';
        const std::regex term("(^|[^A-Za-z_])" + english + (prefix ? "" : "($|[^A-Za-z_])"),
                              name ? std::regex::ECMAScript : std::regex::icase);
        const auto stems = split(cols[2], ' ');
        const auto excepts = cols.size() > 4 ? split(cols[4], '|') : std::vector<std::string>{};
        for (const auto& m : msgs) {
            const std::string id(m.id);
            if (!std::regex_search(id, term)) continue;
            bool excepted = false;
            for (const auto& e : excepts)
                excepted =
                    excepted || (!e.empty() && lower(id).find(lower(e)) != std::string::npos);
            if (excepted) continue;
            ++checked;
            const std::string str = lower(std::string(m.str));
            for (const auto& stem : stems) {
                bool found = false; // "a|b": either
                for (const auto& alternative : split(stem, '|'))
                    found = found || str.find(lower(alternative)) != std::string::npos;
                if (!found) {
                    ++failures;
                    FAIL_CHECK("glossary term '" << cols[0] << "' (" << cols[1] << ", " << cols[3]
                                                 << "): '" << stem << "' missing from\n  msgid  "
                                                 << id << "\n  msgstr " << m.str);
                }
            }
        }
    }
    INFO(terms << " glossary terms, " << checked << " uses checked");
    CHECK(terms >= 40);
    CHECK(checked >= 100);
    CHECK(failures == 0);
}
