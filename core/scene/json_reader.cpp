#include "core/scene/json_reader.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <unordered_set>

namespace lucerna::json {

const Value* Value::find(std::string_view key) const {
    for (const Member& m : object)
        if (m.key == key) return &m.value;
    return nullptr;
}

const char* describe(Type type) {
    switch (type) {
    case Type::Null: return "null";
    case Type::Boolean: return "a boolean";
    case Type::Number: return "a number";
    case Type::String: return "a string";
    case Type::Array: return "an array";
    case Type::Object: return "an object";
    }
    return "a value";
}

namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }

// A number token that from_chars finds out of range is either too large (an error: SPEC.md
// rejects non-finite numbers) or so small that it rounds to zero (harmless, read as 0). The
// decimal magnitude decides which: the position of the first significant digit plus the exponent.
bool underflows(std::string_view token) {
    size_t i = token[0] == '-' ? 1 : 0;
    long long magnitude = 0;
    bool significant = false;
    for (; i < token.size() && isDigit(token[i]); ++i) {
        if (token[i] != '0') significant = true;
        if (significant) ++magnitude;
    }
    if (i < token.size() && token[i] == '.') {
        for (++i; i < token.size() && isDigit(token[i]); ++i) {
            if (significant) continue;
            if (token[i] != '0') significant = true;
            else --magnitude;
        }
    }
    long long exponent = 0;
    if (i < token.size() && (token[i] == 'e' || token[i] == 'E')) {
        ++i;
        const bool negative = token[i] == '-';
        if (token[i] == '-' || token[i] == '+') ++i;
        for (; i < token.size(); ++i) exponent = std::min(exponent * 10 + (token[i] - '0'), 1'000'000'000LL);
        if (negative) exponent = -exponent;
    }
    return magnitude + exponent < 0;
}

class Parser {
public:
    Parser(std::string_view text, int maxDepth) : s_(text), maxDepth_(maxDepth) {}

    Value parseDocument() {
        if (s_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = 3;
        skipWhitespace();
        Value v = parseValue(0);
        skipWhitespace();
        if (pos_ < s_.size()) fail("unexpected " + describeChar() + " after the end of the JSON value");
        return v;
    }

private:
    [[noreturn]] void fail(const std::string& problem) const { throw ParseError(line_, problem); }

    bool atEnd() const { return pos_ >= s_.size(); }
    char peek() const { return atEnd() ? '\0' : s_[pos_]; }

    std::string describeChar() const {
        if (atEnd()) return "end of input";
        const unsigned char c = static_cast<unsigned char>(s_[pos_]);
        char buf[32];
        if (c >= 0x21 && c < 0x7f) std::snprintf(buf, sizeof buf, "character '%c'", c);
        else std::snprintf(buf, sizeof buf, "byte 0x%02X", c);
        return buf;
    }

    void skipWhitespace() {
        for (; !atEnd(); ++pos_) {
            const char c = s_[pos_];
            if (c == '\n') ++line_;
            else if (c != ' ' && c != '\t' && c != '\r') break;
        }
    }

    void expectLiteral(std::string_view word) {
        if (s_.substr(pos_, word.size()) != word) fail("unexpected " + describeChar());
        pos_ += word.size();
    }

    Value parseValue(int depth) {
        Value v;
        v.line = line_;
        switch (peek()) {
        case '{': parseObject(v, depth + 1); break;
        case '[': parseArray(v, depth + 1); break;
        case '"': v.type = Type::String; v.string = parseString(); break;
        case 't': expectLiteral("true"); v.type = Type::Boolean; v.boolean = true; break;
        case 'f': expectLiteral("false"); v.type = Type::Boolean; break;
        case 'n': expectLiteral("null"); break;
        default:
            if (peek() == '-' || isDigit(peek())) {
                v.type = Type::Number;
                v.number = parseNumber();
            } else {
                fail("unexpected " + describeChar() + " where a value should start");
            }
        }
        return v;
    }

    void enter(int depth) const {
        if (depth > maxDepth_) fail("arrays and objects nested deeper than " + std::to_string(maxDepth_) + " levels");
    }

    void parseArray(Value& v, int depth) {
        enter(depth);
        v.type = Type::Array;
        ++pos_;  // '['
        skipWhitespace();
        if (peek() == ']') { ++pos_; return; }
        for (;;) {
            skipWhitespace();
            v.array.push_back(parseValue(depth));
            skipWhitespace();
            if (peek() == ',') { ++pos_; continue; }
            if (peek() == ']') { ++pos_; return; }
            fail("expected ',' or ']' in an array, found " + describeChar());
        }
    }

    void parseObject(Value& v, int depth) {
        enter(depth);
        v.type = Type::Object;
        ++pos_;  // '{'
        skipWhitespace();
        if (peek() == '}') { ++pos_; return; }
        std::unordered_set<std::string> keys;
        for (;;) {
            skipWhitespace();
            if (peek() != '"') fail("expected a key string in an object, found " + describeChar());
            std::string key = parseString();
            if (!keys.insert(key).second) fail("key \"" + printable(key) + "\" given twice in one object");
            skipWhitespace();
            if (peek() != ':') fail("expected ':' after a key, found " + describeChar());
            ++pos_;
            skipWhitespace();
            Value member = parseValue(depth);
            v.object.push_back(Member{std::move(key), std::move(member)});
            skipWhitespace();
            if (peek() == ',') { ++pos_; continue; }
            if (peek() == '}') { ++pos_; return; }
            fail("expected ',' or '}' in an object, found " + describeChar());
        }
    }

    // Keys quoted in messages must keep the message on one line.
    static std::string printable(const std::string& key) {
        std::string out;
        for (unsigned char c : key) {
            if (c < 0x20 || c == '"' || c == '\\') {
                char buf[8];
                std::snprintf(buf, sizeof buf, "\\u%04X", c);
                out += buf;
            } else {
                out += char(c);
            }
        }
        return out;
    }

    double parseNumber() {
        const size_t start = pos_;
        if (peek() == '-') ++pos_;
        if (peek() == '0') {
            ++pos_;
        } else if (isDigit(peek())) {
            while (isDigit(peek())) ++pos_;
        } else {
            fail("a number needs digits after '-'");
        }
        if (peek() == '.') {
            ++pos_;
            if (!isDigit(peek())) fail("a number needs digits after '.'");
            while (isDigit(peek())) ++pos_;
        }
        if (peek() == 'e' || peek() == 'E') {
            ++pos_;
            if (peek() == '+' || peek() == '-') ++pos_;
            if (!isDigit(peek())) fail("a number needs digits in its exponent");
            while (isDigit(peek())) ++pos_;
        }
        const std::string_view token = s_.substr(start, pos_ - start);
        double value = 0;
        const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
        if (ec == std::errc::result_out_of_range) {
            if (!underflows(token)) fail("number " + std::string(token.substr(0, 40)) + " is too large (not finite)");
            return token[0] == '-' ? -0.0 : 0.0;
        }
        if (ec != std::errc() || end != token.data() + token.size() || !std::isfinite(value))
            fail("malformed number");
        return value;
    }

    unsigned parseHex4() {
        unsigned code = 0;
        for (int i = 0; i < 4; ++i, ++pos_) {
            const char c = peek();
            code <<= 4;
            if (c >= '0' && c <= '9') code |= unsigned(c - '0');
            else if (c >= 'a' && c <= 'f') code |= unsigned(c - 'a' + 10);
            else if (c >= 'A' && c <= 'F') code |= unsigned(c - 'A' + 10);
            else fail("\\u must be followed by four hexadecimal digits");
        }
        return code;
    }

    static void appendUtf8(std::string& out, unsigned cp) {
        if (cp < 0x80) {
            out += char(cp);
        } else if (cp < 0x800) {
            out += char(0xC0 | (cp >> 6));
            out += char(0x80 | (cp & 0x3F));
        } else if (cp < 0x10000) {
            out += char(0xE0 | (cp >> 12));
            out += char(0x80 | ((cp >> 6) & 0x3F));
            out += char(0x80 | (cp & 0x3F));
        } else {
            out += char(0xF0 | (cp >> 18));
            out += char(0x80 | ((cp >> 12) & 0x3F));
            out += char(0x80 | ((cp >> 6) & 0x3F));
            out += char(0x80 | (cp & 0x3F));
        }
    }

    unsigned parseEscapedCodePoint() {
        const unsigned cp = parseHex4();
        if (cp >= 0xDC00 && cp <= 0xDFFF) fail("\\u escape is a lone low surrogate");
        if (cp < 0xD800 || cp > 0xDBFF) return cp;
        if (s_.substr(pos_, 2) != "\\u") fail("\\u escape is a high surrogate without its low half");
        pos_ += 2;
        const unsigned low = parseHex4();
        if (low < 0xDC00 || low > 0xDFFF) fail("\\u escape is a high surrogate without its low half");
        return 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
    }

    // Copies one raw UTF-8 sequence, rejecting overlong forms, surrogates and code points above
    // U+10FFFF (RFC 3629).
    void copyUtf8Sequence(std::string& out) {
        const unsigned char lead = static_cast<unsigned char>(s_[pos_]);
        int length = 0;
        unsigned lo = 0x80, hi = 0xBF;  // allowed range of the second byte
        if (lead >= 0xC2 && lead <= 0xDF) length = 2;
        else if (lead >= 0xE0 && lead <= 0xEF) {
            length = 3;
            if (lead == 0xE0) lo = 0xA0;
            if (lead == 0xED) hi = 0x9F;
        } else if (lead >= 0xF0 && lead <= 0xF4) {
            length = 4;
            if (lead == 0xF0) lo = 0x90;
            if (lead == 0xF4) hi = 0x8F;
        } else {
            fail("invalid UTF-8 in a string");
        }
        if (pos_ + length > s_.size()) fail("invalid UTF-8 in a string");
        for (int i = 1; i < length; ++i) {
            const unsigned char c = static_cast<unsigned char>(s_[pos_ + i]);
            if (c < (i == 1 ? lo : 0x80) || c > (i == 1 ? hi : 0xBF)) fail("invalid UTF-8 in a string");
        }
        out.append(s_.substr(pos_, length));
        pos_ += length;
    }

    std::string parseString() {
        ++pos_;  // opening quote
        std::string out;
        for (;;) {
            if (atEnd()) fail("string not terminated before the end of input");
            const unsigned char c = static_cast<unsigned char>(s_[pos_]);
            if (c == '"') { ++pos_; return out; }
            if (c < 0x20) fail("control character (byte 0x" + hex2(c) + ") inside a string; escape it");
            if (c >= 0x80) { copyUtf8Sequence(out); continue; }
            ++pos_;
            if (c != '\\') { out += char(c); continue; }
            const char e = peek();
            ++pos_;
            switch (e) {
            case '"': out += '"'; break;
            case '\\': out += '\\'; break;
            case '/': out += '/'; break;
            case 'b': out += '\b'; break;
            case 'f': out += '\f'; break;
            case 'n': out += '\n'; break;
            case 'r': out += '\r'; break;
            case 't': out += '\t'; break;
            case 'u': appendUtf8(out, parseEscapedCodePoint()); break;
            default: --pos_; fail("invalid escape sequence in a string");
            }
        }
    }

    static std::string hex2(unsigned char c) {
        char buf[4];
        std::snprintf(buf, sizeof buf, "%02X", c);
        return buf;
    }

    std::string_view s_;
    size_t pos_ = 0;
    int line_ = 1;
    int maxDepth_;
};

}  // namespace

Value parse(std::string_view text, int maxDepth) {
    return Parser(text, maxDepth).parseDocument();
}

}  // namespace lucerna::json
