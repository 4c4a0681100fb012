#include "core/scene/json_string.h"

#include <cstdio>

namespace lucerna {

std::string jsonQuoted(std::string_view s, JsonEscapes escapes) {
    const bool shortForms = escapes == JsonEscapes::Short;
    std::string out = "\"";
    for (unsigned char c : s) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += char(c);
        } else if (shortForms && c == '\n') {
            out += "\\n";
        } else if (shortForms && c == '\t') {
            out += "\\t";
        } else if (shortForms && c == '\r') {
            out += "\\r";
        } else if (c < 0x20 || (!shortForms && c == 0x7f)) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04X", c);
            out += buf;
        } else {
            out += char(c);
        }
    }
    return out + "\"";
}

}  // namespace lucerna
