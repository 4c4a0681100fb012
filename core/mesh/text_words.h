#pragma once
// The whitespace-separated words of a text mesh file (ASCII PLY, OFF, STL), each with its line
// number for messages; '#' optionally starts a comment that runs to the end of its line. A view
// of the text: it must outlive the reader.

#include <optional>
#include <string_view>

namespace lucerna {

class TextWords {
public:
    TextWords(std::string_view text, size_t from, bool hashComments) : text_(text), at_(from), comments_(hashComments) {
        for (size_t i = 0; i < from && i < text.size(); ++i) line_ += text[i] == '\n';
    }

    // The next word, or nothing at the end of the text.
    std::optional<std::string_view> next() {
        for (;;) {
            while (at_ < text_.size() && isBlank(text_[at_])) line_ += text_[at_++] == '\n';
            if (comments_ && at_ < text_.size() && text_[at_] == '#') {
                skipLine();
                continue;
            }
            break;
        }
        if (at_ >= text_.size()) return std::nullopt;
        wordLine_ = line_;
        const size_t start = at_;
        while (at_ < text_.size() && !isBlank(text_[at_]) && !(comments_ && text_[at_] == '#')) ++at_;
        return text_.substr(start, at_ - start);
    }
    // Past the end of the current line.
    void skipLine() {
        while (at_ < text_.size() && text_[at_] != '\n') ++at_;
        if (at_ < text_.size()) {
            ++at_;
            ++line_;
        }
    }
    long long line() const { return wordLine_; }  // of the last word returned

private:
    static bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }
    std::string_view text_;
    size_t at_;
    bool comments_;
    long long line_ = 1, wordLine_ = 1;
};

}  // namespace lucerna
