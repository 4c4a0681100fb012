// CIE 97:2005's maintenance factor from a designer's choices (core/photometry/maintenance_assistant.h):
// the room index K = L W / (h (L + W)); an LED's LLMF on the straight line through its rating; LSF 1
// with spot replacement; and the lookups of the tables (a lamp family by hours, LMF and RSMF by
// cleaning interval, RSMF's room column by K), exact at a tabulated column and linear between.
// The tables here are made up for the test (round figures, so the expected values can be worked
// by hand): they check the lookups, not CIE 97's figures, which Lucerna does not bundle yet.

#include "core/photometry/maintenance_assistant.h"

#include <QtTest>

#include <cmath>
#include <stdexcept>

using namespace lucerna;

namespace {

bool near(double a, double b) { return std::abs(a - b) < 1e-12; }

// A made-up table in CIE 97's layout: cleaning intervals 0.5 to 3 years, two lamp columns.
Cie97Tables testTables() {
    Cie97Tables t;
    t.source = "test table";
    t.lampHours = {4000, 8000, 12000};
    t.lamps = {{"test family", {0.96, 0.92, 0.90}, {1.00, 0.98, 0.90}}};
    t.cleaningYears = {0.5, 1, 1.5, 2, 2.5, 3};
    t.lmf[{LuminaireClass::D, Cleanliness::Clean}] = {0.95, 0.90, 0.86, 0.82, 0.80, 0.78};
    t.roomIndexOfSize = {0.7, 2.5, 5.0};
    t.rsmf[{RoomSize::Small, LightDistribution::Direct, Cleanliness::Clean}] = {0.97, 0.96, 0.95, 0.94, 0.93, 0.92};
    t.rsmf[{RoomSize::Medium, LightDistribution::Direct, Cleanliness::Clean}] = {0.98, 0.97, 0.96, 0.95, 0.94, 0.93};
    t.rsmf[{RoomSize::Large, LightDistribution::Direct, Cleanliness::Clean}] = {0.99, 0.98, 0.97, 0.96, 0.95, 0.94};
    return t;
}

}  // namespace

class TestMaintenanceAssistant : public QObject {
    Q_OBJECT
private slots:
    void roomIndexByHand() {
        QVERIFY(near(roomIndex(10, 8, 2), 80.0 / 36.0));   // 2.22
        QVERIFY(near(roomIndex(4, 4, 2.5), 0.8));           // a square room: L / (2 h)
        QVERIFY(near(roomIndex(8, 10, 2), roomIndex(10, 8, 2)));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, roomIndex(0, 8, 2));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, roomIndex(10, 8, -1));
        const Cie97Tables t = testTables();
        QCOMPARE(roomSizeFor(0.8, t), RoomSize::Small);
        QCOMPARE(roomSizeFor(2.22, t), RoomSize::Medium);
        QCOMPARE(roomSizeFor(4.0, t), RoomSize::Large);
    }

    void interpolationIsExactAtColumnsAndLinearBetween() {
        const std::vector<double> xs{0.5, 1, 2}, ys{0.9, 0.8, 0.6};
        QCOMPARE(*interpolateLinearly(xs, ys, 1), 0.8);
        QCOMPARE(*interpolateLinearly(xs, ys, 0.5), 0.9);
        QCOMPARE(*interpolateLinearly(xs, ys, 2), 0.6);
        QVERIFY(near(*interpolateLinearly(xs, ys, 1.5), 0.7));
        QVERIFY(near(*interpolateLinearly(xs, ys, 0.75), 0.85));
        QVERIFY(!interpolateLinearly(xs, ys, 0.4));
        QVERIFY(!interpolateLinearly(xs, ys, 2.1));
        QVERIFY(!interpolateLinearly(xs, {0.9, 0.8}, 1));
    }

    // L80 at 50,000 h: 0.8 at the rated life, 0.95 at a quarter of it, nothing past it.
    void ledFromItsRating() {
        MaintenanceChoices c;
        c.ledLumenFraction = 0.8;
        c.ledRatedLifeHours = 50000;
        c.operatingHours = 12500;
        MaintenanceAssessment a = assessMaintenance(c);
        QVERIFY(near(*a.llmf.value, 0.95));
        QVERIFY(a.llmf.explanation.find("L80 at 50000 h") != std::string::npos);
        QCOMPARE(*a.lsf.value, 1.0);
        QVERIFY(a.lsf.explanation.find("spot replacement") != std::string::npos);
        c.operatingHours = 50000;
        QVERIFY(near(*assessMaintenance(c).llmf.value, 0.8));
        c.operatingHours = 60000;
        a = assessMaintenance(c);
        QVERIFY(!a.llmf.value);
        QVERIFY(a.llmf.explanation.find("beyond") != std::string::npos);
        c.spotReplacement = false;
        QVERIFY(!assessMaintenance(c).lsf.value);
    }

    // What Lucerna bundles: no CIE 97 table, so LMF and RSMF are not found and say what to take.
    void bundledTablesSayWhatIsMissing() {
        MaintenanceChoices c;
        c.operatingHours = 25000;
        const MaintenanceAssessment a = assessMaintenance(c);
        QVERIFY(!a.lmf.value && !a.rsmf.value);
        QVERIFY(a.lmf.explanation.find("not bundled") != std::string::npos);
        QVERIFY(a.rsmf.explanation.find("K = 2.22") != std::string::npos);
        const std::optional<MaintenanceFactor> mf = a.factors();
        QVERIFY(mf && mf->lampLumenMaintenance && mf->lampSurvival);
        QVERIFY(!mf->luminaireMaintenance && !mf->roomSurfaceMaintenance);
        QVERIFY(near(mf->factor(), 0.9));  // L80 at 50,000 h, half way: 0.9, x LSF 1
        c.lamp = kMakersDataLamp;
        c.spotReplacement = false;
        QVERIFY(!assessMaintenance(c).factors());  // nothing found: nothing to fill in
    }

    void tableLookups() {
        const Cie97Tables t = testTables();
        MaintenanceChoices c;
        c.luminaire = LuminaireClass::D;
        c.luminaireEnvironment = Cleanliness::Clean;
        c.luminaireCleaningYears = 1.5;  // a column: the table's figure exactly
        c.roomLengthM = 10;
        c.roomWidthM = 8;
        c.mountingHeightM = 2;           // K = 2.22: the medium column
        c.roomEnvironment = Cleanliness::Clean;
        c.roomCleaningYears = 2;
        c.lamp = "test family";
        c.operatingHours = 8000;
        c.spotReplacement = false;
        MaintenanceAssessment a = assessMaintenance(c, t);
        QCOMPARE(*a.lmf.value, 0.86);
        QCOMPARE(*a.rsmf.value, 0.95);
        QCOMPARE(a.roomSize, RoomSize::Medium);
        QCOMPARE(*a.llmf.value, 0.92);
        QCOMPARE(*a.lsf.value, 0.98);
        QVERIFY(a.lmf.explanation.find("test table Table 3") != std::string::npos);
        QVERIFY(a.lmf.explanation.find("between") == std::string::npos);
        // Between the columns: linear in the interval (and in the hours).
        c.luminaireCleaningYears = 1.25;
        c.roomCleaningYears = 2.75;
        c.operatingHours = 10000;
        a = assessMaintenance(c, t);
        QVERIFY(near(*a.lmf.value, 0.88));
        QVERIFY(a.lmf.explanation.find("between the 1 and 1.5 year columns") != std::string::npos);
        QVERIFY(near(*a.rsmf.value, 0.935));
        QVERIFY(near(*a.llmf.value, 0.91));
        QVERIFY(near(*a.lsf.value, 0.94));
        // A small room takes the small column; a case the table lacks is not found.
        c.roomLengthM = c.roomWidthM = 4;
        c.mountingHeightM = 2.5;  // K = 0.8
        QVERIFY(near(*assessMaintenance(c, t).rsmf.value, 0.925));
        c.distribution = LightDistribution::Indirect;
        QVERIFY(!assessMaintenance(c, t).rsmf.value);
        c.luminaire = LuminaireClass::A;
        QVERIFY(!assessMaintenance(c, t).lmf.value);
        // Hours outside the table's.
        c.operatingHours = 20000;
        QVERIFY(!assessMaintenance(c, t).llmf.value);
    }

    void badChoicesAreOneLine() {
        MaintenanceChoices c;
        c.luminaireCleaningYears = 4;
        try {
            assessMaintenance(c);
            QFAIL("a 4-year interval was taken");
        } catch (const std::invalid_argument& e) {
            QVERIFY(std::string(e.what()).find("0.5 to 3 years") != std::string::npos);
        }
        c.luminaireCleaningYears = 1;
        c.lamp = "sodium";
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, assessMaintenance(c));
        c.lamp = kLedLamp;
        c.ledLumenFraction = 1;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, assessMaintenance(c));
        c.ledLumenFraction = 0.7;
        c.operatingHours = 0;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, assessMaintenance(c));
    }
};

QTEST_MAIN(TestMaintenanceAssistant)
#include "test_maintenance_assistant.moc"
