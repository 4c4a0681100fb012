// parseScene on hostile bytes: truncated and mutated versions of the bundled scenes, deep nesting,
// huge numbers, unicode escapes, NUL bytes. Every input either parses or throws SceneError:
// nothing else escapes, nothing crashes. What parses must also survive a save and reload.

#include "core/scene/scene_io.h"

#include <QFile>
#include <QtTest>

#include <cstdint>

using namespace lucerna;

namespace {

const std::string kData = LUCERNA_TEST_DATA_DIR;
const std::string kPath = kData + "/fuzz.json";  // mesh files resolve against tests/data

std::string readText(const std::string& path) {
    QFile f(QString::fromStdString(path));
    return f.open(QIODevice::ReadOnly) ? f.readAll().toStdString() : std::string();
}

// SplitMix64: tiny, and the same sequence on every platform (std distributions are not).
class Rng {
public:
    explicit Rng(uint64_t seed) : state_(seed) {}
    uint64_t next() {
        uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }
    size_t below(size_t n) { return n == 0 ? 0 : size_t(next() % n); }

private:
    uint64_t state_;
};

struct Outcome {
    int parsed = 0, rejected = 0;
};

// Runs one input; a failure names the input's tag so that it can be replayed.
bool survive(const std::string& bytes, const QString& tag, Outcome& outcome) {
    try {
        const Scene s = parseScene(bytes, kPath);
        ++outcome.parsed;
        // Whatever was accepted must write out and read back as the same scene.
        const Scene back = parseScene(saveSceneToString(s), kPath);
        if (!(back == s)) {
            qWarning("%s: accepted, but did not survive a save and reload", qPrintable(tag));
            return false;
        }
        return true;
    } catch (const SceneError& e) {
        ++outcome.rejected;
        if (std::string(e.what()).find('\n') != std::string::npos) {
            qWarning("%s: message spans lines: %s", qPrintable(tag), e.what());
            return false;
        }
        return true;
    } catch (const std::exception& e) {
        qWarning("%s: threw something other than SceneError: %s", qPrintable(tag), e.what());
    } catch (...) {
        qWarning("%s: threw something that is not a std::exception", qPrintable(tag));
    }
    return false;
}

using namespace std::string_view_literals;

constexpr std::string_view kTokens[] = {
    "\"", "[", "]", "{", "}", ",", ":", "-", "0", "1", "-1", "0.5", "1e999", "-1e999", "1e-999", "16384", "16385",
    "1e308", "-0", "2147483648", "4294967296", "99999999999999999999", "NaN", "Infinity", "null", "true", "false",
    "\"\"", "\\u0000", "\\ud800", "\\ud83d\\ude00", "\\", "\xC3", "\xFF", "\0"sv,
    "\"lucerna\": 1", "\"quad\"", "\"file\"", "\"meshes/cube.off\"", "\"emitter\"", "\"spot\"", "[0, 0, 0]",
    "[[0, 0, 0], [0, 0, 0], [0, 0, 0], [0, 0, 0]]", "\"matrix\": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]",
};

std::string token(Rng& rng) { return std::string(kTokens[rng.below(std::size(kTokens))]); }

std::string mutate(std::string s, Rng& rng) {
    const int edits = 1 + int(rng.below(4));
    for (int e = 0; e < edits && !s.empty(); ++e) {
        const size_t at = rng.below(s.size());
        switch (rng.below(7)) {
        case 0: s[at] = char(rng.next() & 0xff); break;                            // any byte
        case 1: s.erase(at, 1 + rng.below(8)); break;                              // delete a few
        case 2: s.insert(at, 1, char(rng.next() & 0xff)); break;                   // insert a byte
        case 3: s.insert(at, token(rng)); break;                                   // insert a token
        case 4: s.replace(at, std::min<size_t>(s.size() - at, 1 + rng.below(6)), token(rng)); break;
        case 5: {                                                                  // duplicate a span
            const size_t len = std::min<size_t>(s.size() - at, 1 + rng.below(64));
            s.insert(rng.below(s.size()), s.substr(at, len));
            break;
        }
        case 6:                                                                    // change a digit
            for (size_t k = at; k < s.size(); ++k)
                if (s[k] >= '0' && s[k] <= '9') {
                    s[k] = char('0' + rng.below(10));
                    break;
                }
            break;
        }
    }
    return s;
}

}  // namespace

class TestSceneFuzz : public QObject {
    Q_OBJECT

private slots:
    void truncatedAndMutatedScenes_data();
    void truncatedAndMutatedScenes();
    void hostileInputs();
};

void TestSceneFuzz::truncatedAndMutatedScenes_data() {
    QTest::addColumn<QString>("path");
    QTest::addColumn<int>("mutations");
    QTest::newRow("cornell-box") << QString(LUCERNA_RESOURCE_DIR "/scenes/cornell-box.json") << 20000;
    QTest::newRow("interior") << QString(LUCERNA_RESOURCE_DIR "/scenes/interior.json") << 4000;
    QTest::newRow("every-key") << QString::fromStdString(kData + "/every-key.json") << 15000;
}

void TestSceneFuzz::truncatedAndMutatedScenes() {
    QFETCH(QString, path);
    QFETCH(int, mutations);
    const std::string original = readText(path.toStdString());
    QVERIFY(!original.empty());
    Outcome outcome;
    QVERIFY(survive(original, "original", outcome));
    QCOMPARE(outcome.parsed, 1);

    int failures = 0;
    // Every prefix: a scene cut off anywhere (a partial download, a crash while saving). Only
    // the trailing newline may go.
    const size_t end = original.find_last_not_of(" \n\r\t");
    const size_t step = original.size() > 4000 ? 3 : 1;
    for (size_t n = 0; n <= end; n += step)
        failures += !survive(original.substr(0, n), QString("prefix %1").arg(n), outcome);
    QCOMPARE(outcome.parsed, 1);  // no proper prefix of a scene is a scene

    Rng rng(0x5eed0000 + uint64_t(original.size()));
    for (int i = 0; i < mutations; ++i)
        failures += !survive(mutate(original, rng), QString("mutation %1").arg(i), outcome);
    QCOMPARE(failures, 0);
    // The mutations must reach past the syntax: some mutated scenes stay valid.
    QVERIFY2(outcome.parsed > mutations / 100, qPrintable(QString("only %1 of %2 parsed").arg(outcome.parsed).arg(mutations)));
    QVERIFY(outcome.rejected > mutations / 2);
}

void TestSceneFuzz::hostileInputs() {
    const std::string scene = readText(kData + "/every-key.json");
    const std::string camera = R"("camera": {"position": [0, 1, 5], "target": [0, 1, 0], "fov_y": 40, "resolution": [8, 8]})";
    const auto withName = [&](const std::string& name) {
        return "{\"lucerna\": 1, " + camera + R"(, "materials": {"m": {"type": "diffuse", "albedo": [1, 1, 1]}},)"
               R"( "objects": [{"name": ")" + name + R"(", "material": "m", "mesh": {"quad": [[0, 0, 0], [1, 0, 0], [1, 0, 1], [0, 0, 1]]}}]})";
    };
    const auto withNumber = [&](const std::string& number) {
        return "{\"lucerna\": 1, " + camera + R"(, "materials": {}, "objects": [], "meters_per_unit": )" + number + "}";
    };

    struct Case {
        const char* tag;
        std::string bytes;
        bool parses;
    };
    std::string deepObject;
    for (int i = 0; i < 100000; ++i) deepObject += "{\"a\":";
    const std::vector<Case> cases = {
        {"empty", "", false},
        {"whitespace", " \n\t\r ", false},
        {"byte-order mark only", "\xEF\xBB\xBF", false},
        {"100000 [", std::string(100000, '['), false},
        {"100000 [ then ]", std::string(100000, '[') + std::string(100000, ']'), false},
        {"100000 nested objects", deepObject, false},
        {"257 nested arrays in a scene", withNumber(std::string(257, '[') + "1" + std::string(257, ']')), false},
        {"400-digit number", withNumber("1" + std::string(400, '0')), false},
        {"huge exponent", withNumber("1e99999999999999999999"), false},
        {"tiny exponent underflows to 0", withNumber("1e-99999999999999999999"), false},  // 0 is not positive
        {"largest double", withNumber("1.7976931348623157e308"), true},
        {"smallest denormal", withNumber("4.9406564584124654e-324"), true},
        {"leading zeros", withNumber("007"), false},
        {"plus sign", withNumber("+1"), false},
        {"hex", withNumber("0x10"), false},
        {"bare dot", withNumber(".5"), false},
        {"escaped NUL in a name", withName("a\\u0000b"), true},
        {"raw NUL in a name", withName(std::string("a\0b", 3)), false},
        {"NUL after the document", scene + std::string(1, '\0'), false},
        {"NUL in the middle", scene.substr(0, 100) + std::string(1, '\0') + scene.substr(100), false},
        {"surrogate pair", withName("\\ud83d\\ude00"), true},
        {"lone low surrogate", withName("\\udc00"), false},
        {"high surrogate then text", withName("\\ud83dx"), false},
        {"bad escape", withName("\\x41"), false},
        {"short \\u", withName("\\u12"), false},
        {"overlong UTF-8", withName("\xC0\xAF"), false},
        {"UTF-8 surrogate", withName("\xED\xA0\x80"), false},
        {"4-byte UTF-8", withName("\xF0\x9F\x98\x80"), true},
        {"beyond U+10FFFF", withName("\xF4\x90\x80\x80"), false},
        {"megabyte name", withName(std::string(1 << 20, 'x')), true},
        {"two documents", scene + scene, false},
        {"comment", "// scene\n" + scene, false},
    };
    Outcome outcome;
    for (const Case& c : cases) {
        const int parsedBefore = outcome.parsed;
        QVERIFY2(survive(c.bytes, c.tag, outcome), c.tag);
        QVERIFY2((outcome.parsed > parsedBefore) == c.parses, c.tag);
    }
}

QTEST_GUILESS_MAIN(TestSceneFuzz)
#include "test_scene_fuzz.moc"
