// Text a user gave (an option's value, a study file's key, a path) as an error message may echo
// it: a terminal must show it, never obey it. A study file of random bytes, or a value carrying
// ESC [ 2 J, would otherwise clear the screen, retitle the window or forge the next line.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace dlpverify {

// How many characters of one value an error line shows before cutting it with "…".
inline constexpr std::size_t kEchoedValueLength = 80;

// `text` with every control character (C0 but for none, DEL, C1 U+0080–U+009F) and every byte
// that is not part of well-formed UTF-8 shown as \xNN (\n, \r, \t as themselves escaped), and cut
// to `limit` characters (escapes counted as they are shown) with "…" at the end when longer.
// Printable UTF-8 (Δt, é) passes unchanged. Idempotent on its own output up to the cut.
std::string printable(std::string_view text, std::size_t limit = kEchoedValueLength);

// Text bound for the console (a table, a summary): as printable() with no cut, but its line
// breaks kept, so that a name inside it (a study file's, a label, a tableau's) reaches the
// terminal shown, never obeyed. A name that may hold a line break of its own goes through
// printable() first, or it could forge a line of the table.
std::string console_text(std::string_view text);

// The length of the well-formed UTF-8 sequence at text[i] (RFC 3629: no overlong forms, no
// surrogates, nothing past U+10FFFF), or 0 when the byte there does not start one.
std::size_t utf8_length(std::string_view text, std::size_t i);

}  // namespace dlpverify
