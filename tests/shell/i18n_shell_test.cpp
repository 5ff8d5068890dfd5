// The shell's side of issue 17: the panel font has every character of every catalogue string
// (Cyrillic, ③, ×, —, arrows, the pseudo-language's accents) at the scales a class uses, the
// Russian layout's letters name the US keys in --keys, and Cyrillic typed text reaches ImGui.
#include "common/imgui_input.h"
#include "common/keyboard_layout.h"
#include "common/options.h"
#include "common/panel.h"
#include "core/i18n.h"

#include <catch2/catch.hpp>
#include <imgui.h>

#include <set>

namespace {

// Every character (code point) of every msgid and msgstr of every language.
std::set<char32_t> catalogueChars() {
    std::set<char32_t> chars;
    for (const auto& code : wb::languages())
        for (const auto& m : wb::i18n::messages(code))
            for (std::string_view text : {m.id, m.str}) {
                const std::string s(text);
                for (size_t i = 0; i < s.size();)
                    chars.insert(wb::decodeUtf8(s, i));
            }
    return chars;
}

} // namespace

TEST_CASE("font atlas: every character of every catalogue string has a glyph", "[i18n]") {
    std::set<char32_t> chars = catalogueChars();
    REQUIRE(chars.count(U'ж'));
    REQUIRE(chars.count(U'—'));
    REQUIRE(chars.count(U'ŕ'));                       // the pseudo-language's
    for (char32_t c : {U'③', U'④', U'⑤', U'✓', U'✗'}) // the exercise panel's marks
        chars.insert(c);
    for (float scale : {1.0f, 2.0f}) {
        ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        const std::string message = wb::setupImGuiFonts(scale);
        REQUIRE(message.empty()); // DejaVu Sans is there (fonts-dejavu-core)
        unsigned char* pixels = nullptr;
        int w = 0, h = 0;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
        int missing = 0;
        for (ImFont* font : io.Fonts->Fonts) // DejaVu Sans and DejaVu Sans Mono
            for (char32_t c : chars) {
                if (c < 0x20 || c == U'\n') continue; // control characters are not drawn
                if (!font->FindGlyphNoFallback(ImWchar(c))) {
                    ++missing;
                    FAIL_CHECK("U+" << std::hex << unsigned(c) << " has no glyph at scale "
                                    << scale);
                }
            }
        CHECK(missing == 0);
        INFO(chars.size() << " characters, atlas " << w << "x" << h);
        CHECK(w * h > 0);
        ImGui::DestroyContext();
    }
}

TEST_CASE("keys replay (--keys): Russian-layout letters are the US keys at the same place",
          "[i18n]") {
    std::vector<int> codes;
    std::string error;
    REQUIRE(wb::parseKeys("пПыб{left}юЁх1", codes, error));
    CHECK(codes == std::vector<int>{'g', 'G', 's', ',', wb::kKeyLeft, '.', '~', '[', '1'});
    // Every letter of the alphabet maps, both cases, and onto distinct keys.
    const std::u32string lowerRu = U"йцукенгшщзхъфывапролджэячсмитьбюё";
    std::set<int> seen;
    for (char32_t c : lowerRu) {
        const int us = wb::usKeyForRussian(c);
        CHECK(us > 0);
        seen.insert(us);
        const int upper = wb::usKeyForRussian(c == U'ё' ? U'Ё' : char32_t(c - 0x20));
        CHECK(upper > 0);
        seen.insert(upper);
    }
    CHECK(seen.size() == 2 * lowerRu.size());
    CHECK_FALSE(wb::parseKeys("g€", codes, error));
    CHECK(error.find("€") != std::string::npos);
    CHECK_FALSE(wb::parseKeys("g\xD0", codes, error)); // a cut UTF-8 sequence
}

TEST_CASE("typed Cyrillic reaches ImGui's text input", "[i18n]") {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    wb::ImGuiInput input;
    for (char32_t c : std::u32string(U"привет"))
        input.character(unsigned(c));
    input.applyToFrame(io);
    REQUIRE(io.InputQueueCharacters.Size == 6);
    CHECK(io.InputQueueCharacters[0] == ImWchar(U'п'));
    CHECK(io.InputQueueCharacters[5] == ImWchar(U'т'));
    ImGui::DestroyContext();
}
