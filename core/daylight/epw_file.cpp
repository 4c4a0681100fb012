#include "core/daylight/epw_file.h"

#include "core/message_text.h"
#include "core/number_format.h"
#include "core/regular_file.h"

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <fstream>
#include <istream>
#include <optional>
#include <string_view>
#include <system_error>

namespace lucerna {

namespace {

constexpr size_t kHeaderLines = 8;  // LOCATION, then 7 others that annual daylight has no use for
constexpr int kCommonYearRows = 8760, kLeapYearRows = 8784;
constexpr double kMissingIrradiance = 9999, kMissingDewPoint = 99.9, kDewPointInstead = 11;

constexpr const char* kMonthNames[12] = {"January", "February", "March",     "April",   "May",      "June",
                                         "July",    "August",   "September", "October", "November", "December"};

std::string_view trimmed(std::string_view s) {
    const size_t a = s.find_first_not_of(" \t");
    if (a == std::string_view::npos) return {};
    return s.substr(a, s.find_last_not_of(" \t") - a + 1);
}

std::vector<std::string_view> splitFields(std::string_view line) {
    std::vector<std::string_view> fields;
    for (size_t start = 0;;) {
        const size_t comma = line.find(',', start);
        fields.push_back(trimmed(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
        if (comma == std::string_view::npos) return fields;
        start = comma + 1;
    }
}

std::optional<double> numberIn(std::string_view field) {
    // strtod takes a leading '+', from_chars not; "+-1" must stay a non-number.
    if (field.size() > 1 && field[0] == '+' && field[1] != '+' && field[1] != '-') field.remove_prefix(1);
    double x = 0;
    const char* end = field.data() + field.size();
    const auto r = std::from_chars(field.data(), end, x);
    // from_chars reads "nan" and "inf", which no hour of weather can be.
    if (field.empty() || r.ec != std::errc() || r.ptr != end || !std::isfinite(x)) return std::nullopt;
    return x;
}

int daysInMonth(int month, bool withLeapDay) {
    static constexpr int kDays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    return kDays[month - 1] + (month == 2 && withLeapDay ? 1 : 0);
}

struct RowDate {
    int month = 1, day = 1, hour = 1;
    bool operator==(const RowDate&) const = default;
};

std::string dateText(const RowDate& d) {
    return std::to_string(d.day) + " " + kMonthNames[d.month - 1] + " hour " + std::to_string(d.hour);
}

// The row that must come next: 1 January hour 1 to 31 December hour 24, with 29 February either
// wholly there or wholly absent, which the first row after 28 February hour 24 decides.
class Calendar {
public:
    bool finished() const { return finished_; }
    int rowsInYear() const { return leapDay_ == LeapDay::Present ? kLeapYearRows : kCommonYearRows; }
    std::string nextText() const {
        return atUndecidedLeapDay() ? dateText(next_) + " or 1 March hour 1" : dateText(next_);
    }

    // Moves past `d` when it is the row that comes next; false when it is out of order.
    bool accept(const RowDate& d) {
        if (finished_) return false;
        if (atUndecidedLeapDay()) {
            if (d == next_) {
                leapDay_ = LeapDay::Present;
            } else if (d == RowDate{3, 1, 1}) {
                leapDay_ = LeapDay::Absent;
                next_ = d;
            }
        }
        if (d != next_) return false;
        if (++next_.hour > 24) {
            next_.hour = 1;
            if (++next_.day > daysInMonth(next_.month, leapDay_ != LeapDay::Absent)) {
                next_.day = 1;
                if (++next_.month > 12) finished_ = true;
            }
        }
        return true;
    }

private:
    enum class LeapDay { Undecided, Present, Absent };
    bool atUndecidedLeapDay() const { return leapDay_ == LeapDay::Undecided && next_ == RowDate{2, 29, 1}; }

    RowDate next_;
    LeapDay leapDay_ = LeapDay::Undecided;
    bool finished_ = false;
};

class EpwReader {
public:
    EpwReader(std::istream& in, const std::string& name) : in_(in), name_(name) {}

    WeatherFile read() {
        WeatherFile file;
        std::string line;
        if (!nextLine(line)) fail("the file is empty");
        readLocation(line, file);
        while (lineNumber_ < kHeaderLines)
            if (!nextLine(line)) fail(lineNumber_, "the file ends within its " + std::to_string(kHeaderLines) + " header lines");

        Calendar calendar;
        size_t lastRowLine = lineNumber_, firstBlankLine = 0;
        while (nextLine(line)) {
            // Blank lines are let through only at the end, where editors and tools leave them.
            if (trimmed(line).empty()) {
                if (firstBlankLine == 0) firstBlankLine = lineNumber_;
                continue;
            }
            if (firstBlankLine != 0) fail(firstBlankLine, "an empty line among the rows of hours");
            if (calendar.finished())
                fail(lineNumber_, "a row after 31 December hour 24: the file has more than " +
                                      std::to_string(calendar.rowsInYear()) + " rows of hours");
            file.hours.push_back(readRow(line, calendar));
            if (file.hours.back().missing) ++file.hoursWithMissingValues;
            lastRowLine = lineNumber_;
        }
        if (in_.bad()) fail("cannot read the file");
        if (!calendar.finished())
            fail(lastRowLine, "the file ends after " + std::to_string(file.hours.size()) + " rows of hours, before " +
                                  calendar.nextText() + ": a year is " + std::to_string(kCommonYearRows) + " rows (" +
                                  std::to_string(kLeapYearRows) + " with 29 February) to 31 December hour 24");
        return file;
    }

private:
    [[noreturn]] void fail(const std::string& problem) const { throw WeatherFileError(name_ + ": " + problem); }
    [[noreturn]] void fail(size_t line, const std::string& problem) const {
        throw WeatherFileError(name_ + ":" + std::to_string(line) + ": " + problem);
    }

    bool nextLine(std::string& line) {
        if (!std::getline(in_, line)) return false;
        ++lineNumber_;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        // A byte-order mark is invisible in an editor, so "LOCATION" must still read as the first word.
        if (lineNumber_ == 1 && line.starts_with("\xEF\xBB\xBF")) line.erase(0, 3);
        return true;
    }

    [[noreturn]] void failField(int field, const char* what, const std::string& problem) const {
        fail(lineNumber_, "field " + std::to_string(field) + " (" + what + ") " + problem);
    }

    double numberField(const std::vector<std::string_view>& fields, int field, const char* what) const {
        const std::string_view text = fields[size_t(field) - 1];
        const std::optional<double> x = numberIn(text);
        if (!x) failField(field, what, "is not a number: \"" + printableWord(text) + "\"");
        return *x;
    }

    double numberFieldIn(const std::vector<std::string_view>& fields, int field, const char* what, double lo, double hi) const {
        const double x = numberField(fields, field, what);
        if (x < lo || x > hi)
            failField(field, what, "is not from " + shortestNumber(lo) + " to " + shortestNumber(hi) + ": " + shortestNumber(x));
        return x;
    }

    int wholeField(const std::vector<std::string_view>& fields, int field, const char* what, int lo, int hi) const {
        const double x = numberField(fields, field, what);
        if (x != std::floor(x)) failField(field, what, "is not a whole number: " + shortestNumber(x));
        if (x < lo || x > hi)
            failField(field, what, "is not from " + std::to_string(lo) + " to " + std::to_string(hi) + ": " + shortestNumber(x));
        return int(x);
    }

    void readLocation(const std::string& line, WeatherFile& file) const {
        const std::vector<std::string_view> fields = splitFields(line);
        if (fields[0] != "LOCATION")
            fail(lineNumber_, "the first line is not the LOCATION line: it starts \"" + printableWord(fields[0]) + "\"");
        if (fields.size() < 10)
            fail(lineNumber_, "the LOCATION line has " + std::to_string(fields.size()) + " fields; it needs 10");
        file.city = fields[1];
        file.region = fields[2];
        file.country = fields[3];
        file.source = fields[4];
        file.wmo = fields[5];
        file.latitudeDeg = numberFieldIn(fields, 7, "latitude", -90, 90);
        file.longitudeDeg = numberFieldIn(fields, 8, "longitude", -180, 180);
        file.timeZoneHours = numberFieldIn(fields, 9, "time zone", -14, 14);
        file.elevationM = numberField(fields, 10, "elevation");
    }

    WeatherHour readRow(const std::string& line, Calendar& calendar) const {
        const std::vector<std::string_view> fields = splitFields(line);
        if (fields.size() < 16)
            fail(lineNumber_, "the row has " + std::to_string(fields.size()) + " fields; it needs at least 16");
        WeatherHour h;
        h.month = wholeField(fields, 2, "month", 1, 12);
        h.day = wholeField(fields, 3, "day", 1, 31);
        // 29 February is a day of February here; whether this file may have it is the calendar's call.
        if (h.day > daysInMonth(h.month, true))
            failField(3, "day", "is not a day of " + std::string(kMonthNames[h.month - 1]) + ": " + std::to_string(h.day));
        h.hour = wholeField(fields, 4, "hour", 1, 24);
        const RowDate date{h.month, h.day, h.hour};
        const std::string expected = calendar.nextText();
        if (!calendar.accept(date))
            fail(lineNumber_, "row out of order: " + dateText(date) + " where " + expected + " should come");

        h.dewPointC = numberField(fields, 8, "dew point");
        h.directNormalIrradiance = irradianceField(fields, 15, "direct normal irradiance");
        h.diffuseHorizontalIrradiance = irradianceField(fields, 16, "diffuse horizontal irradiance");
        if (h.dewPointC == kMissingDewPoint) {
            h.dewPointC = kDewPointInstead;
            h.missing = true;
        }
        for (double* e : {&h.directNormalIrradiance, &h.diffuseHorizontalIrradiance}) {
            if (*e == kMissingIrradiance) {
                *e = 0;
                h.missing = true;
            }
        }
        return h;
    }

    double irradianceField(const std::vector<std::string_view>& fields, int field, const char* what) const {
        const double x = numberField(fields, field, what);
        if (x < 0) failField(field, what, "is negative: " + shortestNumber(x));
        return x;
    }

    std::istream& in_;
    const std::string& name_;
    size_t lineNumber_ = 0;
};

std::string lowerFirst(std::string s) {
    if (!s.empty()) s[0] = char(std::tolower(static_cast<unsigned char>(s[0])));
    return s;
}

}  // namespace

std::string WeatherFile::describe() const {
    std::string place;
    for (const std::string* part : {&city, &region, &country}) {
        if (part->empty()) continue;
        if (!place.empty()) place += ", ";
        place += printableWord(*part, 80);
    }
    if (!source.empty() || !wmo.empty()) {
        std::string origin = printableWord(source, 80);
        if (!wmo.empty()) origin += (origin.empty() ? "WMO " : ", WMO ") + printableWord(wmo, 80);
        place += (place.empty() ? "(" : " (") + origin + ")";
    }
    if (!place.empty()) place += ", ";
    return place + shortestNumber(std::abs(latitudeDeg)) + (latitudeDeg < 0 ? " S, " : " N, ") +
           shortestNumber(std::abs(longitudeDeg)) + (longitudeDeg < 0 ? " W, " : " E, ") + "UTC" +
           (timeZoneHours < 0 ? "-" : "+") + shortestNumber(std::abs(timeZoneHours));
}

WeatherFile readWeatherFile(const std::string& path) {
    if (const std::string kind = nonRegularFileKind(path); !kind.empty())
        throw WeatherFileError(path + ": cannot read the file: not a regular file (" + kind + ")");
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        const std::string reason = errno != 0 ? lowerFirst(std::generic_category().message(errno)) : "cannot open it";
        throw WeatherFileError(path + ": cannot read the file: " + reason);
    }
    return parseWeatherFile(in, path);
}

WeatherFile parseWeatherFile(std::istream& in, const std::string& name) {
    return EpwReader(in, name).read();
}

}  // namespace lucerna
