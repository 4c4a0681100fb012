#include "core/photometry/luminaire_file_fields.h"

#include "core/message_text.h"
#include "core/number_format.h"
#include "core/photometry/goniometric_distribution.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>

namespace lucerna {

std::string trimmed(const std::string& s) {
    const size_t a = s.find_first_not_of(" \t\r\n");
    if (a == std::string::npos) return {};
    return s.substr(a, s.find_last_not_of(" \t\r\n") - a + 1);
}

std::string decimalPoints(std::string field) {
    std::replace(field.begin(), field.end(), ',', '.');
    return field;
}

std::optional<double> fieldNumber(const std::string& field) {
    double x = 0;
    const char* end = field.data() + field.size();
    const auto r = std::from_chars(field.data(), end, x);
    if (field.empty() || r.ec != std::errc() || r.ptr != end || !std::isfinite(x)) return std::nullopt;
    return x;
}

LuminaireFileFields LuminaireFileFields::lines(const std::string& text, std::string label) {
    std::vector<Field> fields;
    std::istringstream in(text);
    std::string l;
    while (std::getline(in, l)) fields.push_back({trimmed(l), fields.size() + 1});
    const size_t last = fields.size();
    return LuminaireFileFields(std::move(fields), last, std::move(label));
}

LuminaireFileFields LuminaireFileFields::words(const std::vector<std::string>& lines, size_t first, std::string label) {
    std::vector<Field> fields;
    for (size_t i = first; i < lines.size(); ++i) {
        std::string l = lines[i];
        std::replace(l.begin(), l.end(), ',', ' ');
        std::istringstream in(l);
        std::string word;
        while (in >> word) fields.push_back({word, i + 1});
    }
    return LuminaireFileFields(std::move(fields), lines.size(), std::move(label));
}

void LuminaireFileFields::fail(size_t line, const std::string& problem) const {
    throw LuminaireFileError(label_ + ": line " + std::to_string(line) + ": " + problem);
}

size_t LuminaireFileFields::remaining() const {
    size_t n = 0;
    for (size_t i = next_; i < fields_.size(); ++i) n += fields_[i].text.empty() ? 0 : 1;
    return n;
}

std::string LuminaireFileFields::text(const std::string& what) {
    if (next_ >= fields_.size()) fail(lastLine_, "the file ends before " + what);
    return fields_[next_++].text;
}

double LuminaireFileFields::number(const std::string& what) {
    const size_t here = line();
    const std::string field = decimalPoints(text(what));
    const std::optional<double> x = fieldNumber(field);
    if (!x) fail(here, "expected a number for " + what + ", found \"" + printableWord(field) + "\"");
    return *x;
}

int LuminaireFileFields::integer(const std::string& what, int lo, int hi) {
    const size_t here = line();
    const double x = number(what);
    if (x != std::floor(x) || x < lo || x > hi)
        fail(here, what + " must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) +
                       ", got " + shortestNumber(x));
    return int(x);
}

std::vector<double> LuminaireFileFields::numbers(size_t count, const std::string& what) {
    if (remaining() < count)
        fail(lastLine_, "expected " + std::to_string(count) + " " + what + ", found " + std::to_string(remaining()));
    std::vector<double> out;
    out.reserve(count);
    for (size_t i = 0; i < count; ++i) out.push_back(number(what));
    return out;
}

}  // namespace lucerna
