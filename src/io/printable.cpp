#include "io/printable.hpp"

#include <cstdint>
#include <algorithm>
#include <cstdio>

namespace dlpverify {

namespace {

std::string escaped(std::uint8_t b) {
  if (b == '\n') return "\\n";
  if (b == '\r') return "\\r";
  if (b == '\t') return "\\t";
  char code[5];
  std::snprintf(code, sizeof code, "\\x%02x", b);
  return code;
}

}  // namespace

std::size_t utf8_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<std::uint8_t>(text[k]); };
  const std::uint8_t b = byte(i);
  if (b < 0x80) return 1;
  std::size_t n = 0;
  std::uint8_t low = 0x80, high = 0xBF;  // the range of the second byte
  if (b >= 0xC2 && b <= 0xDF) n = 2;
  else if (b == 0xE0) n = 3, low = 0xA0;
  else if (b >= 0xE1 && b <= 0xEC) n = 3;
  else if (b == 0xED) n = 3, high = 0x9F;
  else if (b >= 0xEE && b <= 0xEF) n = 3;
  else if (b == 0xF0) n = 4, low = 0x90;
  else if (b >= 0xF1 && b <= 0xF3) n = 4;
  else if (b == 0xF4) n = 4, high = 0x8F;
  else return 0;
  if (i + n > text.size()) return 0;
  if (byte(i + 1) < low || byte(i + 1) > high) return 0;
  for (std::size_t k = 2; k < n; ++k)
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  return n;
}

std::string printable(std::string_view text, std::size_t limit) {
  std::string out;
  std::size_t shown = 0;  // characters shown so far (an escape counts its own length)
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = utf8_length(text, i);
    std::string piece;
    const auto b = static_cast<std::uint8_t>(text[i]);
    // C1 controls (U+0080–U+009F) are C2 80 … C2 9F in UTF-8: shown escaped, both bytes.
    const bool c1 = n == 2 && b == 0xC2 && static_cast<std::uint8_t>(text[i + 1]) <= 0x9F;
    if (n == 0 || b < 0x20 || b == 0x7F) {
      piece = escaped(b);
      i += 1;
    } else if (c1) {
      piece = escaped(b) + escaped(static_cast<std::uint8_t>(text[i + 1]));
      i += 2;
    } else {
      piece = std::string(text.substr(i, n));
      i += n;
    }
    const std::size_t width = n > 1 && !c1 ? 1 : piece.size();
    if (shown + width > limit || (shown + width == limit && i < text.size())) return out + "…";
    out += piece;
    shown += width;
  }
  return out;
}

std::string console_text(std::string_view text) {
  std::string out;
  for (std::size_t start = 0; start <= text.size();) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    out += printable(text.substr(start, end - start), std::string_view::npos);
    if (end == text.size()) break;
    out += '\n';
    start = end + 1;
  }
  return out;
}

}  // namespace dlpverify
