#pragma once
// Words quoted from a file into a one-line message: a binary file's bytes (NUL, control
// characters, line breaks, bytes beyond ASCII) would break the line or the terminal, so they
// are written as \xNN, and a long word is cut to its first 40 characters and "...".

#include <cstdio>
#include <string>
#include <string_view>

namespace lucerna {

inline std::string printableWord(std::string_view word, size_t limit = 40) {
    std::string out;
    for (size_t i = 0; i < word.size(); ++i) {
        if (i == limit) return out + "...";
        const auto c = static_cast<unsigned char>(word[i]);
        if (c >= 0x20 && c < 0x7f) {
            out += char(c);
        } else {
            char hex[8];
            std::snprintf(hex, sizeof hex, "\\x%02x", c);
            out += hex;
        }
    }
    return out;
}

}  // namespace lucerna
