#pragma once
// Finds text the panel cuts off. Linked with -Wl,--wrap for ImGui's RenderText,
// RenderTextWrapped and RenderTextClipped (see labs/CMakeLists.txt, wb_panel_check), so
// every label, value and line of text any widget draws passes through here with its
// position; text whose extent runs past the clip rectangle it is drawn into (the panel's
// edge, a table cell, a button or slider frame) is recorded. ImGui's item rectangles alone
// miss text clipped inside a frame; this sees the string itself, so the report names it.
#include <string>
#include <vector>

namespace wb::panelcheck {

struct ClippedText {
    std::string text;   // the string as drawn (shortened)
    std::string window; // the ImGui window it belongs to
    float overflow;     // pixels of it beyond the visible edge (right or left)
};

void start();                    // from now on, record clipped text
std::vector<ClippedText> stop(); // stop recording; what was clipped, each string once

// Every text drawn between start() and stop(), each once (for the pseudo-language check).
const std::vector<std::string>& drawnTexts();

// Under the pseudo-language (--lang qps) every catalogue string is drawn in [brackets]
// (core/i18n.h, i18n::pseudo): the words of `text` outside brackets that are English, i.e. did
// not come through the catalogue. Runs of Latin letters are allowed when they are one letter
// (key names, variables: g, K, x), part of a value (a token with a digit, '_', '.' or '\':
// numbers with units, file names, GL_LIGHT0; or a hyphenated-name: scene names), in a token
// with a non-ASCII letter (a pseudo-translated word cut off from its brackets where a lab wraps
// lines itself; Cyrillic) or named in kAllowedWords (key caps, language names).
// Empty when the text is clean.
std::string untranslatedWords(const std::string& text);

} // namespace wb::panelcheck
