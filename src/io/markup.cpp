#include "io/markup.hpp"

#include <cstdint>
#include <string_view>

#include "io/printable.hpp"

namespace dlpverify {

std::string markup_text(const std::string& text) {
  static const std::string replacement = "\xEF\xBF\xBD";
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = utf8_length(text, i);
    const auto b = static_cast<std::uint8_t>(text[i]);
    const std::string_view piece(text.data() + i, n == 0 ? 1 : n);
    i += piece.size();
    if (n == 0 || (b < 0x20 && b != '\t' && b != '\n' && b != '\r') || piece == "\xEF\xBF\xBE" || piece == "\xEF\xBF\xBF")
      out += replacement;
    else if (b == '&') out += "&amp;";
    else if (b == '<') out += "&lt;";
    else if (b == '>') out += "&gt;";
    else if (b == '"') out += "&quot;";
    else if (b == '\'') out += "&apos;";
    else out += piece;
  }
  return out;
}

}  // namespace dlpverify
