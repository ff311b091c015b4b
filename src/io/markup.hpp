// Text in XML or HTML (the JUnit report, the HTML report): what a user or a study wrote, safe to
// put between tags and in an attribute's quotes.
#pragma once

#include <string>

namespace dlpverify {

// `text` as character data or an attribute value (XML 1.0 §2.2, §2.4; HTML reads it the same): the
// five special characters & < > " ' as entities, every character XML cannot carry (C0 controls
// but tab, newline and carriage return; U+FFFE, U+FFFF) and every byte outside well-formed UTF-8
// as U+FFFD.
std::string markup_text(const std::string& text);

}  // namespace dlpverify
