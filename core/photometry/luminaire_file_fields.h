#pragma once
// The fields of a luminaire file (IES LM-63, EULUMDAT) read one at a time, each with the number
// of its line, so that every problem is reported as "<label>: line N: <problem>".

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace lucerna {

// s without the blanks (spaces, tabs, line ends) at either end.
std::string trimmed(const std::string& s);

// The field with its decimal commas as points (some EULUMDAT writers use commas).
std::string decimalPoints(std::string field);
// The number a field holds, or nothing for a field that is not exactly one finite number.
std::optional<double> fieldNumber(const std::string& field);

class LuminaireFileFields {
public:
    struct Field {
        std::string text;
        size_t line = 0;  // from 1
    };
    // EULUMDAT: every line of `text` one field, blanks trimmed.
    static LuminaireFileFields lines(const std::string& text, std::string label);
    // IES: the words of lines[first] on, separated by blanks or commas; lines.size() is the last line.
    static LuminaireFileFields words(const std::vector<std::string>& lines, size_t first, std::string label);

    // Throws LuminaireFileError "<label>: line <line>: <problem>".
    [[noreturn]] void fail(size_t line, const std::string& problem) const;
    // The line of the next field; the last line past the end.
    size_t line() const { return next_ < fields_.size() ? fields_[next_].line : lastLine_; }
    // How many fields are left, empty lines not counted.
    size_t remaining() const;

    // Each reads the next field or fields, `what` naming them in the message where the file ends
    // or a field is not what it should be.
    std::string text(const std::string& what);
    // A number, decimal commas read as points.
    double number(const std::string& what);
    // A whole number in [lo, hi].
    int integer(const std::string& what, int lo, int hi);
    // `count` numbers; a short table is reported with how many there were.
    std::vector<double> numbers(size_t count, const std::string& what);

private:
    LuminaireFileFields(std::vector<Field> fields, size_t lastLine, std::string label)
        : fields_(std::move(fields)), lastLine_(lastLine), label_(std::move(label)) {}

    std::vector<Field> fields_;
    size_t next_ = 0;
    size_t lastLine_ = 0;
    std::string label_;
};

}  // namespace lucerna
