#pragma once
// A string as a JSON string literal, quotes included, in one of two escapings.

#include <string>
#include <string_view>

namespace lucerna {

enum class JsonEscapes {
    // Scene files: \" \\ \n \t \r, other control characters as \u00XX, the rest as it is.
    Short,
    // Error messages: \" \\, every control character and DEL as \u00XX, so that text from a file
    // can never break the message's single line.
    OneLine,
};

std::string jsonQuoted(std::string_view s, JsonEscapes escapes);

}  // namespace lucerna
