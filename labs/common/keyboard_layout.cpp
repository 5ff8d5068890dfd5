#include "keyboard_layout.h"

namespace wb {

int usKeyForRussian(char32_t c) {
    // xkeyboard-config's "ru" symbols, key by key, against "us" (rows from the top).
    static const struct {
        char32_t ru;
        char us;
    } kTable[] = {
        {U'ё', '`'}, {U'Ё', '~'}, {U'№', '#'}, {U'й', 'q'}, {U'ц', 'w'},  {U'у', 'e'}, {U'к', 'r'},
        {U'е', 't'}, {U'н', 'y'}, {U'г', 'u'}, {U'ш', 'i'}, {U'щ', 'o'},  {U'з', 'p'}, {U'х', '['},
        {U'ъ', ']'}, {U'ф', 'a'}, {U'ы', 's'}, {U'в', 'd'}, {U'а', 'f'},  {U'п', 'g'}, {U'р', 'h'},
        {U'о', 'j'}, {U'л', 'k'}, {U'д', 'l'}, {U'ж', ';'}, {U'э', '\''}, {U'я', 'z'}, {U'ч', 'x'},
        {U'с', 'c'}, {U'м', 'v'}, {U'и', 'b'}, {U'т', 'n'}, {U'ь', 'm'},  {U'б', ','}, {U'ю', '.'},
        {U'Й', 'Q'}, {U'Ц', 'W'}, {U'У', 'E'}, {U'К', 'R'}, {U'Е', 'T'},  {U'Н', 'Y'}, {U'Г', 'U'},
        {U'Ш', 'I'}, {U'Щ', 'O'}, {U'З', 'P'}, {U'Х', '{'}, {U'Ъ', '}'},  {U'Ф', 'A'}, {U'Ы', 'S'},
        {U'В', 'D'}, {U'А', 'F'}, {U'П', 'G'}, {U'Р', 'H'}, {U'О', 'J'},  {U'Л', 'K'}, {U'Д', 'L'},
        {U'Ж', ':'}, {U'Э', '"'}, {U'Я', 'Z'}, {U'Ч', 'X'}, {U'С', 'C'},  {U'М', 'V'}, {U'И', 'B'},
        {U'Т', 'N'}, {U'Ь', 'M'}, {U'Б', '<'}, {U'Ю', '>'},
    };
    // ASCII characters mean themselves (ru's " ; : ? on Shift+2/4/6/7 are left out: in --keys a
    // '?' is the '?' key); the window path maps those physical keys through X, not this table.
    if (c < 0x80) return -1;
    for (const auto& e : kTable)
        if (e.ru == c) return e.us;
    return -1;
}

char32_t decodeUtf8(const std::string& s, size_t& i) {
    const auto byte = [&](size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char b = byte(i);
    int extra = b < 0x80 ? 0 : (b >> 5) == 6 ? 1 : (b >> 4) == 14 ? 2 : (b >> 3) == 30 ? 3 : -1;
    if (extra < 0 || i + size_t(extra) >= s.size()) {
        ++i;
        return U'\uFFFD';
    }
    char32_t c = extra == 0 ? b : b & (0x3F >> extra);
    for (int k = 1; k <= extra; ++k) {
        if ((byte(i + size_t(k)) & 0xC0) != 0x80) {
            ++i;
            return U'\uFFFD';
        }
        c = (c << 6) | (byte(i + size_t(k)) & 0x3F);
    }
    i += size_t(extra) + 1;
    return c;
}

} // namespace wb
