// The EPW weather file reader of SPEC.md section 6: a year of rows read field by field, 29
// February deciding the year, missing values replaced and counted, CRLF and a trailing empty
// line let through, and every damaged file a one-line error naming the line that is wrong.

#include "core/daylight/epw_file.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cctype>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace lucerna;

namespace {

const std::string kLocation = "LOCATION,Luzern,LU,CHE,IWEC Data,066500,47.03,8.3,1.0,456.0";
constexpr size_t kFirstRowLine = 9;  // lines 1 to 8 are headers

// What the generated file holds for the row of hour-of-year `i` (0-based) at `hour`: values that
// differ from row to row, so that a row read into the wrong slot shows.
double dewPointOf(size_t i) { return double(i % 50) * 0.5 - 10; }
double directOf(size_t i, int hour) { return hour >= 8 && hour <= 17 ? double(i % 900) : 0; }
double diffuseOf(size_t i, int hour) { return hour >= 7 && hour <= 18 ? double(i % 300) + 0.5 : 0; }

std::string numberText(double x) {
    std::ostringstream s;
    s << x;
    return s.str();
}

// A valid EPW file as lines (index 0 is line 1): the LOCATION line, the 7 other headers as
// EnergyPlus writes them, and one row of 35 fields per hour, field 1 mixing years as typical-year
// files do.
std::vector<std::string> epwLines(bool leapYear = false) {
    static constexpr int kDays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    std::vector<std::string> lines = {
        kLocation,
        "DESIGN CONDITIONS,0",
        "TYPICAL/EXTREME PERIODS,0",
        "GROUND TEMPERATURES,0",
        "HOLIDAYS/DAYLIGHT SAVINGS,No,0,0,0",
        "COMMENTS 1,generated for test_epw_file",
        "COMMENTS 2,",
        "DATA PERIODS,1,1,Data,Sunday, 1/ 1,12/31"};
    size_t i = 0;
    for (int month = 1; month <= 12; ++month) {
        const int days = kDays[month - 1] + (month == 2 && leapYear ? 1 : 0);
        for (int day = 1; day <= days; ++day) {
            for (int hour = 1; hour <= 24; ++hour, ++i) {
                std::string row = std::to_string(1995 + month % 4) + "," + std::to_string(month) + "," + std::to_string(day) +
                                  "," + std::to_string(hour) + ",60,?9?9?9?9E0?9?9?9?9?9?9?9?9?9?9?9?9?9?9?9*9*9?9?9?9,12.5," +
                                  numberText(dewPointOf(i)) + ",80,96500,0,1415,320,250," + numberText(directOf(i, hour)) +
                                  "," + numberText(diffuseOf(i, hour));
                // Fields 17 to 35: illuminances, wind, cloud, visibility, snow, rain.
                for (int field = 17; field <= 35; ++field) row.append(",").append(std::to_string(field % 7));
                lines.push_back(std::move(row));
            }
        }
    }
    return lines;
}

std::string joined(const std::vector<std::string>& lines, const std::string& eol = "\n") {
    std::string text;
    for (const std::string& l : lines) text += l + eol;
    return text;
}

// The line of the row of hour-of-year `i` (0-based).
size_t rowLine(size_t i) { return kFirstRowLine + i; }

std::vector<std::string> splitRow(const std::string& row) {
    std::vector<std::string> fields;
    std::istringstream in(row);
    std::string f;
    while (std::getline(in, f, ',')) fields.push_back(f);
    if (!row.empty() && row.back() == ',') fields.emplace_back();
    return fields;
}

std::string joinedRow(const std::vector<std::string>& fields) {
    std::string row;
    for (size_t k = 0; k < fields.size(); ++k) row += (k ? "," : "") + fields[k];
    return row;
}

// Sets field `field` (from 1) of line `line` (from 1).
void setField(std::vector<std::string>& lines, size_t line, size_t field, const std::string& value) {
    std::vector<std::string> fields = splitRow(lines[line - 1]);
    fields[field - 1] = value;
    lines[line - 1] = joinedRow(fields);
}

std::vector<std::string> withField(size_t line, size_t field, const std::string& value, bool leapYear = false) {
    std::vector<std::string> lines = epwLines(leapYear);
    setField(lines, line, field, value);
    return lines;
}

WeatherFile parsed(const std::string& text) {
    std::istringstream in(text);
    return parseWeatherFile(in, "weather.epw");
}

// The message of the error reading `text`; empty when it reads.
std::string rejection(const std::string& text) {
    try {
        parsed(text);
    } catch (const WeatherFileError& e) {
        return e.what();
    }
    return {};
}

}  // namespace

class TestEpwFile : public QObject {
    Q_OBJECT
private slots:
    void goodFileReads();
    void leapYearFileFallsIn2020();
    void missingValuesAreReplacedAndCounted();
    void lineEndingsAndSpacesAreAccepted();
    void describeNamesThePlace();
    void badFileNamesTheLine_data();
    void badFileNamesTheLine();
    void emptyFileIsOneLine();
    void readsFromDiskAndRefusesWhatIsNoFile();
};

void TestEpwFile::goodFileReads() {
    const WeatherFile w = parsed(joined(epwLines()));
    QCOMPARE(w.city, std::string("Luzern"));
    QCOMPARE(w.region, std::string("LU"));
    QCOMPARE(w.country, std::string("CHE"));
    QCOMPARE(w.source, std::string("IWEC Data"));
    QCOMPARE(w.wmo, std::string("066500"));
    QCOMPARE(w.latitudeDeg, 47.03);
    QCOMPARE(w.longitudeDeg, 8.3);
    QCOMPARE(w.timeZoneHours, 1.0);
    QCOMPARE(w.elevationM, 456.0);
    QCOMPARE(w.hours.size(), size_t(8760));
    QCOMPARE(w.year(), 2021);
    QCOMPARE(w.hoursWithMissingValues, 0);

    // 1 January hour 1, a summer noon (2 July hour 12: day 182 of the year) and the last row.
    for (const size_t i : {size_t(0), size_t(182 * 24 + 11), size_t(8759)}) {
        const WeatherHour& h = w.hours[i];
        QCOMPARE(h.hour, int(i % 24) + 1);
        QCOMPARE(h.dewPointC, dewPointOf(i));
        QCOMPARE(h.directNormalIrradiance, directOf(i, h.hour));
        QCOMPARE(h.diffuseHorizontalIrradiance, diffuseOf(i, h.hour));
        QVERIFY(!h.missing);
    }
    QCOMPARE(w.hours[182 * 24 + 11].month, 7);
    QCOMPARE(w.hours[182 * 24 + 11].day, 2);
    QVERIFY(w.hours[182 * 24 + 11].directNormalIrradiance > 0);
    QCOMPARE(w.hours.back().month, 12);
    QCOMPARE(w.hours.back().day, 31);
    QCOMPARE(w.hours.back().hour, 24);
    // The 1440th row follows 28 February hour 24 in a year without 29 February.
    QCOMPARE(w.hours[59 * 24].month, 3);
    QCOMPARE(w.hours[59 * 24].day, 1);
}

void TestEpwFile::leapYearFileFallsIn2020() {
    const WeatherFile w = parsed(joined(epwLines(true)));
    QCOMPARE(w.hours.size(), size_t(8784));
    QCOMPARE(w.year(), 2020);
    QCOMPARE(w.hours[59 * 24].month, 2);
    QCOMPARE(w.hours[59 * 24].day, 29);
    QCOMPARE(w.hours[59 * 24 + 23].hour, 24);
    QCOMPARE(w.hours[60 * 24].month, 3);
    QCOMPARE(w.hours.back().day, 31);
    QCOMPARE(w.hours.back().hour, 24);
}

void TestEpwFile::missingValuesAreReplacedAndCounted() {
    std::vector<std::string> lines = epwLines();
    const size_t noonDirect = 10 * 24 + 11, noonDiffuse = 20 * 24 + 11, dew = 30 * 24 + 3, all = 40 * 24 + 12;
    setField(lines, rowLine(noonDirect), 15, "9999");
    setField(lines, rowLine(noonDiffuse), 16, "9999.0");
    setField(lines, rowLine(dew), 8, "99.9");
    for (const auto& [field, value] : {std::pair<size_t, std::string>{8, "99.9"}, {15, "9999"}, {16, "9999"}})
        setField(lines, rowLine(all), field, value);

    const WeatherFile w = parsed(joined(lines));
    QCOMPARE(w.hoursWithMissingValues, 4);  // the row with three missing values counts once
    QCOMPARE(w.hours[noonDirect].directNormalIrradiance, 0.0);
    QCOMPARE(w.hours[noonDirect].diffuseHorizontalIrradiance, diffuseOf(noonDirect, 12));
    QCOMPARE(w.hours[noonDiffuse].diffuseHorizontalIrradiance, 0.0);
    QCOMPARE(w.hours[noonDiffuse].directNormalIrradiance, directOf(noonDiffuse, 12));
    QCOMPARE(w.hours[dew].dewPointC, 11.0);
    QCOMPARE(w.hours[all].dewPointC, 11.0);
    QCOMPARE(w.hours[all].directNormalIrradiance, 0.0);
    QCOMPARE(w.hours[all].diffuseHorizontalIrradiance, 0.0);
    for (const size_t i : {noonDirect, noonDiffuse, dew, all}) QVERIFY(w.hours[i].missing);
    QVERIFY(!w.hours[noonDirect + 1].missing);
}

void TestEpwFile::lineEndingsAndSpacesAreAccepted() {
    const WeatherFile plain = parsed(joined(epwLines()));
    std::vector<std::string> lines = epwLines();
    setField(lines, rowLine(100), 15, "  +12.5 ");
    setField(lines, rowLine(100), 4, " 5");
    lines.emplace_back();  // a trailing empty line
    std::string crlf = joined(lines, "\r\n");

    for (const std::string& text : {crlf, "\xEF\xBB\xBF" + crlf, joined(epwLines()).substr(0, joined(epwLines()).size() - 1)}) {
        const std::string message = rejection(text);
        QVERIFY2(message.empty(), message.c_str());
        const WeatherFile w = parsed(text);
        QCOMPARE(w.hours.size(), size_t(8760));
        QCOMPARE(w.hours[200].diffuseHorizontalIrradiance, plain.hours[200].diffuseHorizontalIrradiance);
        QCOMPARE(w.hours.back().dewPointC, plain.hours.back().dewPointC);
        QCOMPARE(w.city, std::string("Luzern"));
        QCOMPARE(w.elevationM, 456.0);
    }
    QCOMPARE(parsed(crlf).hours[100].directNormalIrradiance, 12.5);
}

void TestEpwFile::describeNamesThePlace() {
    QCOMPARE(parsed(joined(epwLines())).describe(), std::string("Luzern, LU, CHE (IWEC Data, WMO 066500), 47.03 N, 8.3 E, UTC+1"));
    std::vector<std::string> lines = epwLines();
    lines[0] = "LOCATION,Santiago,-,CHL,TMY3,855740,-33.38,-70.78,-4.5,474";
    QCOMPARE(parsed(joined(lines)).describe(), std::string("Santiago, -, CHL (TMY3, WMO 855740), 33.38 S, 70.78 W, UTC-4.5"));
}

void TestEpwFile::badFileNamesTheLine_data() {
    QTest::addColumn<std::string>("text");
    QTest::addColumn<int>("line");
    QTest::addColumn<std::string>("words");  // a part of the message

    const auto row = [](size_t i) { return int(rowLine(i)); };
    {
        std::vector<std::string> lines = epwLines();
        std::vector<std::string> fields = splitRow(lines[rowLine(100) - 1]);
        fields.resize(15);
        lines[rowLine(100) - 1] = joinedRow(fields);
        QTest::newRow("row of 15 fields") << joined(lines) << row(100) << std::string("the row has 15 fields; it needs at least 16");
    }
    QTest::newRow("month not a number") << joined(withField(rowLine(200), 2, "Jan")) << row(200)
                                        << std::string("field 2 (month) is not a number: \"Jan\"");
    QTest::newRow("day not a number") << joined(withField(rowLine(300), 3, "x")) << row(300)
                                      << std::string("field 3 (day) is not a number: \"x\"");
    QTest::newRow("hour empty") << joined(withField(rowLine(400), 4, "")) << row(400)
                                << std::string("field 4 (hour) is not a number: \"\"");
    QTest::newRow("dew point not a number") << joined(withField(rowLine(500), 8, "abc")) << row(500)
                                            << std::string("field 8 (dew point) is not a number: \"abc\"");
    QTest::newRow("direct not a number") << joined(withField(27, 15, "abc")) << 27
                                         << std::string("field 15 (direct normal irradiance) is not a number: \"abc\"");
    QTest::newRow("diffuse nan") << joined(withField(rowLine(600), 16, "nan")) << row(600)
                                 << std::string("field 16 (diffuse horizontal irradiance) is not a number: \"nan\"");
    QTest::newRow("diffuse with a tail") << joined(withField(rowLine(601), 16, "12abc")) << row(601)
                                         << std::string("field 16 (diffuse horizontal irradiance) is not a number");
    QTest::newRow("hour not whole") << joined(withField(rowLine(700), 4, "1.5")) << row(700)
                                    << std::string("field 4 (hour) is not a whole number: 1.5");
    QTest::newRow("month 13") << joined(withField(rowLine(800), 2, "13")) << row(800)
                              << std::string("field 2 (month) is not from 1 to 12: 13");
    QTest::newRow("day 32") << joined(withField(rowLine(900), 3, "32")) << row(900)
                            << std::string("field 3 (day) is not from 1 to 31: 32");
    QTest::newRow("30 February") << joined(withField(rowLine(40 * 24), 3, "30")) << row(40 * 24)
                                 << std::string("field 3 (day) is not a day of February: 30");
    QTest::newRow("hour 0") << joined(withField(rowLine(1000), 4, "0")) << row(1000)
                            << std::string("field 4 (hour) is not from 1 to 24: 0");
    QTest::newRow("hour 25") << joined(withField(rowLine(1001), 4, "25")) << row(1001)
                             << std::string("field 4 (hour) is not from 1 to 24: 25");
    QTest::newRow("negative direct") << joined(withField(rowLine(1100), 15, "-1")) << row(1100)
                                     << std::string("field 15 (direct normal irradiance) is negative: -1");
    QTest::newRow("negative diffuse") << joined(withField(rowLine(1101), 16, "-0.5")) << row(1101)
                                      << std::string("field 16 (diffuse horizontal irradiance) is negative: -0.5");
    QTest::newRow("plus minus") << joined(withField(rowLine(1102), 16, "+-5")) << row(1102)
                                << std::string("field 16 (diffuse horizontal irradiance) is not a number");
    {
        std::vector<std::string> lines = epwLines();
        std::swap(lines[rowLine(1200) - 1], lines[rowLine(1201) - 1]);
        QTest::newRow("two rows swapped") << joined(lines) << row(1200)
                                          << std::string("row out of order: 20 February hour 2 where 20 February hour 1 should come");
    }
    {
        std::vector<std::string> lines = epwLines();
        lines[rowLine(1301) - 1] = lines[rowLine(1300) - 1];
        QTest::newRow("a row repeated") << joined(lines) << row(1301) << std::string("row out of order");
    }
    {
        std::vector<std::string> lines = epwLines();
        lines.erase(lines.begin() + long(rowLine(2000) - 1));
        QTest::newRow("a row left out") << joined(lines) << row(2000) << std::string("row out of order");
    }
    QTest::newRow("first row hour 2") << joined(withField(kFirstRowLine, 4, "2")) << int(kFirstRowLine)
                                      << std::string("where 1 January hour 1 should come");
    {
        // 29 February hour 1 alone: the file has 29 February, so hour 2 must follow.
        std::vector<std::string> lines = epwLines();
        std::vector<std::string> fields = splitRow(lines[rowLine(59 * 24 - 1) - 1]);
        fields[2] = "29";
        fields[3] = "1";
        lines.insert(lines.begin() + long(rowLine(59 * 24) - 1), joinedRow(fields));
        QTest::newRow("29 February hour 1 alone") << joined(lines) << row(59 * 24 + 1)
                                                  << std::string("where 29 February hour 2 should come");
    }
    QTest::newRow("wrong date after 28 February") << joined(withField(rowLine(59 * 24), 3, "2")) << row(59 * 24)
                                                  << std::string("where 29 February hour 1 or 1 March hour 1 should come");
    {
        std::vector<std::string> lines = epwLines();
        lines.push_back(lines.back());
        QTest::newRow("8761 rows") << joined(lines) << row(8760) << std::string("more than 8760 rows");
    }
    {
        std::vector<std::string> lines = epwLines(true);
        lines.push_back(lines.back());
        QTest::newRow("8785 rows") << joined(lines) << row(8784) << std::string("more than 8784 rows");
    }
    {
        std::vector<std::string> lines = epwLines();
        lines.pop_back();
        QTest::newRow("8759 rows") << joined(lines) << row(8758)
                                   << std::string("ends after 8759 rows of hours, before 31 December hour 24");
        lines.insert(lines.end(), {"", "  ", ""});
        QTest::newRow("8759 rows and empty lines") << joined(lines) << row(8758) << std::string("ends after 8759 rows");
    }
    {
        std::vector<std::string> lines = epwLines(true);
        lines.erase(lines.begin() + long(rowLine(59 * 24) - 1), lines.begin() + long(rowLine(60 * 24) - 1));
        lines.pop_back();
        QTest::newRow("8784 rows less 29 February and one") << joined(lines) << row(8758) << std::string("ends after 8759 rows");
    }
    {
        std::vector<std::string> lines = epwLines();
        lines.resize(kFirstRowLine - 1);
        QTest::newRow("no rows") << joined(lines) << 8 << std::string("ends after 0 rows");
        lines.resize(5);
        QTest::newRow("5 header lines") << joined(lines) << 5 << std::string("the file ends within its 8 header lines");
        lines.resize(1);
        QTest::newRow("LOCATION alone") << joined(lines) << 1 << std::string("the file ends within its 8 header lines");
    }
    {
        std::vector<std::string> lines = epwLines();
        lines[rowLine(300) - 1].clear();
        QTest::newRow("empty line among rows") << joined(lines) << row(300) << std::string("an empty line among the rows of hours");
    }
    const auto withLocation = [](const std::string& location) {
        std::vector<std::string> lines = epwLines();
        lines[0] = location;
        return joined(lines);
    };
    QTest::newRow("no LOCATION") << withLocation("DESIGN CONDITIONS,0") << 1
                                 << std::string("the first line is not the LOCATION line: it starts \"DESIGN CONDITIONS\"");
    QTest::newRow("LOCATION of 9 fields") << withLocation("LOCATION,Luzern,LU,CHE,IWEC Data,066500,47.03,8.3,1.0") << 1
                                          << std::string("the LOCATION line has 9 fields; it needs 10");
    QTest::newRow("latitude not a number") << withLocation("LOCATION,Luzern,LU,CHE,IWEC Data,066500,N47,8.3,1.0,456") << 1
                                           << std::string("field 7 (latitude) is not a number: \"N47\"");
    QTest::newRow("latitude 91") << withLocation("LOCATION,Luzern,LU,CHE,IWEC Data,066500,91,8.3,1.0,456") << 1
                                 << std::string("field 7 (latitude) is not from -90 to 90: 91");
    QTest::newRow("longitude -181") << withLocation("LOCATION,Luzern,LU,CHE,IWEC Data,066500,47,-181,1.0,456") << 1
                                    << std::string("field 8 (longitude) is not from -180 to 180: -181");
    QTest::newRow("time zone 15") << withLocation("LOCATION,Luzern,LU,CHE,IWEC Data,066500,47,8.3,15,456") << 1
                                  << std::string("field 9 (time zone) is not from -14 to 14: 15");
    QTest::newRow("elevation not a number") << withLocation("LOCATION,Luzern,LU,CHE,IWEC Data,066500,47,8.3,1,high") << 1
                                            << std::string("field 10 (elevation) is not a number: \"high\"");
}

void TestEpwFile::badFileNamesTheLine() {
    QFETCH(std::string, text);
    QFETCH(int, line);
    QFETCH(std::string, words);
    const std::string message = rejection(text);
    const std::string place = "weather.epw:" + std::to_string(line) + ": ";
    QVERIFY2(message.rfind(place, 0) == 0, ("expected " + place + "...; got: " + message).c_str());
    QVERIFY2(message.find(words) != std::string::npos, message.c_str());
    QVERIFY2(message.find('\n') == std::string::npos && message.find('\r') == std::string::npos, message.c_str());
    QVERIFY2(std::islower(static_cast<unsigned char>(message[place.size()])), message.c_str());
}

void TestEpwFile::emptyFileIsOneLine() {
    QCOMPARE(rejection(""), std::string("weather.epw: the file is empty"));
    QVERIFY(rejection("\n").rfind("weather.epw:1: ", 0) == 0);
}

void TestEpwFile::readsFromDiskAndRefusesWhatIsNoFile() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string folder = dir.path().toStdString();
    const std::string path = folder + "/luzern.epw";
    {
        std::ofstream out(path, std::ios::binary);
        out << joined(epwLines(), "\r\n");
    }
    QCOMPARE(readWeatherFile(path).hours.size(), size_t(8760));

    for (const auto& [file, problem] : {std::pair<std::string, std::string>{folder + "/absent.epw", ": cannot read the file: "},
                                        {folder, ": cannot read the file: not a regular file (a directory)"}}) {
        std::string message;
        try {
            readWeatherFile(file);
        } catch (const WeatherFileError& e) {
            message = e.what();
        }
        QVERIFY2(message.rfind(file + problem, 0) == 0, message.c_str());
        QVERIFY2(message.find('\n') == std::string::npos, message.c_str());
    }
}

QTEST_GUILESS_MAIN(TestEpwFile)
#include "test_epw_file.moc"
