#pragma once
// A small strict JSON reader (RFC 8259). Qt's QJsonDocument cannot be used for scene files: it
// silently keeps the last of two equal keys, and SPEC.md says a key given twice is an error.
//
// Strict means: exactly one value with only whitespace around it (a leading UTF-8 byte-order
// mark is skipped), no comments, no trailing commas, no NaN or Infinity, no number that
// overflows a double, valid UTF-8 (escapes included: no lone surrogates), no control
// characters inside strings, no key twice in one object, and at most `maxDepth` nested arrays
// and objects, so that hostile input cannot overflow the stack.

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace lucerna::json {

enum class Type { Null, Boolean, Number, String, Array, Object };

struct Member;

struct Value {
    Type type = Type::Null;
    int line = 0;                 // 1-based line of the value's first character
    bool boolean = false;         // Boolean
    double number = 0;            // Number: finite; a tiny number that underflows reads as 0
    std::string string;           // String: UTF-8, escapes resolved (may hold NUL bytes)
    std::vector<Value> array;     // Array
    std::vector<Member> object;   // Object: in file order, keys unique

    // The member named `key` of an object, or nullptr (also when this is not an object).
    const Value* find(std::string_view key) const;
};

struct Member {
    std::string key;
    Value value;
};

// "a number", "an object", ...: for messages such as "expected a number, got a string".
const char* describe(Type type);

class ParseError : public std::runtime_error {
public:
    ParseError(int line, const std::string& problem) : std::runtime_error(problem), line_(line) {}
    int line() const { return line_; }  // where the text stops being JSON

private:
    int line_;
};

inline constexpr int kDefaultMaxDepth = 256;

// Parses `text` as one JSON document. Throws ParseError (with the line and a one-line problem)
// on anything that is not strict JSON; never anything else but std::bad_alloc.
Value parse(std::string_view text, int maxDepth = kDefaultMaxDepth);

}  // namespace lucerna::json
