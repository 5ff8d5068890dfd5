#pragma once
// Lab keys on the Russian layout (issue 17): a lab key is a PHYSICAL key, named by what the US
// layout gives there, so `п` (where US has `g`) acts as `g`, `П` as `G`, `ы` as `s`.
// The window path reads the physical key from X (x_keyboard.h); this table serves --keys
// replays and anything else that only has the character.
#include <string>

namespace wb {

// The character the US layout gives at the key where the standard Russian (ЙЦУКЕН) layout gives
// `c` at the same shift level: 'п' -> 'g', 'П' -> 'G', 'б' -> ',', 'Ю' -> '>', 'ё' -> '`',
// '№' -> '#'. -1 when `c` is not a Russian-layout character that differs from the US one.
int usKeyForRussian(char32_t c);

// Decodes one UTF-8 character of `s` at `i` (advancing i past it); U+FFFD on a bad sequence.
char32_t decodeUtf8(const std::string& s, size_t& i);

} // namespace wb
