// `--backend auto` as a measurement (render/engine/measured_auto/): the measures of constructed
// films (weights that follow each method's noise tile by tile, a chain's understated halves, a
// method that has not seen a rare event, tiles weighed as SPEC's relmse weighs them, the
// allocation's relmse of each method as SPEC weighs it and the level of the weights' errors, both
// read from the replica that runs on), when a method out of the image takes a trial, where the
// time goes on a scene one method wins by far, what it says it decided, and that a render with a
// seed is reproducible. Its consistency on the closed forms is in test_closed_form (its "auto"
// rows).

#include "closed_form_scenes.h"
#include "render/engine/measured_auto/film_measures.h"
#include "render/engine/measured_auto/measured_auto_settings.h"
#include "render/engine/measured_auto/trial.h"
#include "render_helpers.h"

#include <QtTest>

#include <numeric>
#include <random>
#include <sstream>

using namespace lucerna;
using namespace lucerna::test;

namespace {

constexpr int kSize = 64, kTile = 16;

// A replica of a method whose values are 1 + noise: per pixel, its two halves with independent
// noise of standard deviation sdHalf(x) each, plus `shared` noise common to both halves (what a
// Markov chain's halves share); the image is the halves' mean.
ReplicaImages replica(std::mt19937& rng, const std::function<double(int x)>& sdHalf, double shared = 0) {
    std::normal_distribution<double> n(0.0, 1.0);
    ReplicaImages r{Image(kSize, kSize), {Image(kSize, kSize), Image(kSize, kSize)}};
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const double common = shared * n(rng);
            Rgb h[2];
            for (Rgb& c : h) c = Rgb(float(1 + common + sdHalf(x) * n(rng)), float(1 + common + sdHalf(x) * n(rng)),
                                     float(1 + common + sdHalf(x) * n(rng)));
            r.half[0].at(x, y) = h[0], r.half[1].at(x, y) = h[1];
            r.image.at(x, y) = (h[0] + h[1]) * 0.5f;
        }
    return r;
}

std::array<ReplicaImages, 2> pair(std::mt19937& rng, const std::function<double(int x)>& sdHalf, double shared = 0) {
    return {replica(rng, sdHalf, shared), replica(rng, sdHalf, shared)};
}

// A method's numbers from the EXR header's `lucerna:auto_shares` ("path=0.9 mir=0.05 ...").
double share(const Image& img, const std::string& key, const std::string& method) {
    const std::string& s = img.attributes.at("lucerna:" + key);
    const size_t at = s.find(method + "=");
    return at == std::string::npos ? -1.0 : std::stod(s.substr(at + method.size() + 1));
}

}  // namespace

class TestMeasuredAuto : public QObject {
    Q_OBJECT
private slots:
    void weightsFollowEachMethodsNoise();
    void chainHalvesAreInflated();
    void rareEventTakesNoWeight();
    void weightsWeighTilesAsTheRelmseDoes();
    void allocationKeepsEachRelmse();
    void relmseIsPerPixel();
    void allocationReadsTheLongReplica();
    void trialsForWhatAShortRunUnderstates();
    void candidatesAreConsistent();
    void bestByFarTakesTheTime();
    void saysWhatItDecided();
    void reproducibleWithSeed();
};

void TestMeasuredAuto::weightsFollowEachMethodsNoise() {
    // Method a: the same noise everywhere; b: a quarter of a's standard deviation on the left
    // half of the image, twice it on the right. The weights follow, tile by tile.
    std::mt19937 rng(7);
    const TileGrid tiles(kSize, kSize, kTile);
    const MethodMeasure a = measureMethod(pair(rng, [](int) { return 0.1; }), tiles, true);
    const MethodMeasure b = measureMethod(pair(rng, [](int x) { return x < kSize / 2 ? 0.025 : 0.2; }), tiles, true);
    QVERIFY(a.inflation < 1.5 && b.inflation < 1.5);  // independent halves: nothing to inflate
    const std::vector<const TileStats*> stats{&a.replica[0], &b.replica[0]};
    const auto w = inverseErrorWeights(expectedSquaredErrors(stats));
    for (int t = 0; t < tiles.count(); ++t) {
        const bool left = (t % tiles.nx) < tiles.nx / 2;
        QCOMPARE_LE(std::abs(w[0][size_t(t)] + w[1][size_t(t)] - 1.0), 1e-12);
        // Optimal: b 0.94 on the left, a 0.8 on the right; drawn halfway to each method's mean
        // error over the image (film_measures.h), b about 0.8 and a about 0.67.
        if (left) QVERIFY2(w[1][size_t(t)] > 0.7, qPrintable(QString::number(w[1][size_t(t)])));
        else QVERIFY2(w[0][size_t(t)] > 0.6, qPrintable(QString::number(w[0][size_t(t)])));
    }
    // The combination of images of 1 is 1 wherever the weights change.
    const std::array<ReplicaImages, 2> ra = pair(rng, [](int) { return 0.0; }), rb = pair(rng, [](int) { return 0.0; });
    const std::vector<const Image*> flat{&ra[0].image, &rb[0].image};
    const Image c = combineImages(flat, w, tiles);
    for (const Rgb& p : c.pixels) QCOMPARE_LE(std::abs(p.y - 1.0f), 1e-5f);
}

void TestMeasuredAuto::chainHalvesAreInflated() {
    // Halves that share most of their noise understate a replica's variance; the difference of
    // the replicas does not, and their ratio scales the halves' estimate up.
    std::mt19937 rng(11);
    const TileGrid tiles(kSize, kSize, kTile);
    const MethodMeasure m = measureMethod(pair(rng, [](int) { return 0.01; }, 0.1), tiles, true);
    qInfo("inflation %.1f", m.inflation);
    QVERIFY(m.inflation > 50);  // (0.1^2 + 0.01^2 / 2) / (0.01^2 / 2) = 201 in expectation
    double within = 0, across = 0;
    for (int t = 0; t < tiles.count(); ++t) within += m.replica[0].variance[size_t(t)], across += m.pair.variance[size_t(t)];
    QVERIFY(within > 0.5 * 2 * across && within < 2 * 2 * across);  // a replica's variance, twice the pair's
}

void TestMeasuredAuto::rareEventTakesNoWeight() {
    // Two methods see the light (1, with noise); a third has not yet (0, no noise at all): its
    // zero variance must not take the weight, its distance from the others counts.
    std::mt19937 rng(13);
    const TileGrid tiles(kSize, kSize, kTile);
    const MethodMeasure a = measureMethod(pair(rng, [](int) { return 0.2; }), tiles, true);
    const MethodMeasure b = measureMethod(pair(rng, [](int) { return 0.3; }), tiles, true);
    std::array<ReplicaImages, 2> blind = pair(rng, [](int) { return 0.0; });
    for (ReplicaImages& r : blind)
        for (Image* i : {&r.image, &r.half[0], &r.half[1]})
            for (Rgb& p : i->pixels) p = Rgb(0, 0, 0);
    const MethodMeasure c = measureMethod(blind, tiles, true);
    const std::vector<const TileStats*> stats{&a.replica[1], &b.replica[1], &c.replica[1]};
    const auto w = inverseErrorWeights(expectedSquaredErrors(stats), 0.1);
    for (int t = 0; t < tiles.count(); ++t) {
        QCOMPARE(w[2][size_t(t)], 0.0);
        QVERIFY(w[0][size_t(t)] > w[1][size_t(t)]);  // a is the less noisy
    }
}

void TestMeasuredAuto::weightsWeighTilesAsTheRelmseDoes() {
    // A dim image, as most members are: tiles of 0.1 and 0.01 in turn, where SPEC's denominators
    // (0.02 and 0.0101) are mostly its 0.01. Method a has the same variance everywhere (1e-5), b
    // twice a's on the bright tiles and a fifth of it on the dark. On the bright tiles a is the
    // better, and keeps the larger weight there once each tile's error is drawn halfway to the
    // method's mean over the image (film_measures.h): relative to SPEC's denominators, a's and b's
    // means are alike; relative to the squared brightness, a's would be 4.6 times the larger,
    // dominated by the dark tiles, and a would lose the bright ones too (b 0.6).
    const size_t n = 16;
    TileStats a, b;
    for (size_t t = 0; t < n; ++t) {
        const bool bright = t % 2 == 0;
        for (TileStats* m : {&a, &b}) {
            m->mean.push_back(bright ? 0.1 : 0.01);
            m->meanVariance.push_back(0.0);
        }
        a.variance.push_back(1e-5);
        b.variance.push_back(bright ? 2e-5 : 2e-6);
    }
    const std::vector<const TileStats*> stats{&a, &b};
    const auto w = inverseErrorWeights(expectedSquaredErrors(stats));
    for (size_t t = 0; t < n; ++t) {
        if (t % 2 == 0) QVERIFY2(w[0][t] > 0.5, qPrintable(QString::number(w[0][t])));
        else QVERIFY2(w[1][t] > 0.5, qPrintable(QString::number(w[1][t])));
    }
}

void TestMeasuredAuto::allocationKeepsEachRelmse() {
    // Half the tiles bright (1), half dark (0.01). Two methods of equal relmse by SPEC's weighting
    // 1 / (m^2 + 0.01): one with its error in the dark tiles, one in the bright. The allocation
    // must see them as equal (the weights' spreading made the first look 1.7 times worse on the
    // deep-plan daylit room), and pool each one's tiles halfway to its mean.
    const size_t n = 8;
    std::vector<double> means(n);
    for (size_t t = 0; t < n; ++t) means[t] = t < n / 2 ? 1.0 : 0.01;
    TileStats dark{means, std::vector(n, 0.0), std::vector(n, 0.0), {}}, bright = dark;
    for (size_t t = 0; t < n; ++t) (t < n / 2 ? bright : dark).variance[t] = 0.02 * relmseDenominator(means[t]);
    const std::vector<const TileStats*> stats{&dark, &bright};
    const auto relative = relativeSquaredErrors(stats);
    const auto relmse = [&](const std::vector<double>& e) { return std::accumulate(e.begin(), e.end(), 0.0) / double(n); };
    for (size_t k = 0; k < 2; ++k)
        for (size_t t = 0; t < n; ++t)  // the means agree: no distance
            QCOMPARE_LE(std::abs(relative[k][t] - stats[k]->variance[t] / relmseDenominator(means[t])), 1e-12);
    const auto pooled = pooledTowardMean(relative);
    for (size_t k = 0; k < 2; ++k) {
        QCOMPARE_LE(std::abs(relmse(pooled[k]) - 0.01), 1e-12);
        for (size_t t = 0; t < n; ++t)  // halfway between 0 or 0.02 and the mean 0.01
            QCOMPARE_LE(std::abs(pooled[k][t] - (stats[k]->variance[t] > 0 ? 0.015 : 0.005)), 1e-12);
    }
    const auto gains = marginalGains(pooled, std::vector{1.0, 1.0});
    QCOMPARE_LE(std::abs(gains[0] / gains[1] - 1.0), 1e-9);
}

void TestMeasuredAuto::relmseIsPerPixel() {
    // Inside every tile, bright (1) and dark (0.01) columns alternate. Method a is noisy on the
    // bright pixels, b on the dark, with the same relmse by SPEC (b's standard deviation 10 times
    // smaller, as the denominators are 1.01 and 0.0101). Against the tile mean's denominator b's
    // error would read 100 times smaller; against the median of the methods' images, per pixel,
    // the two read alike, and their mean over the tiles is the relmse.
    std::mt19937 rng(17);
    const TileGrid tiles(kSize, kSize, kTile);
    const auto truth = [](int x) { return x % 2 ? 1.0 : 0.01; };
    const double sdBright = 0.2, sdDark = 0.2 * std::sqrt(relmseDenominator(0.01) / relmseDenominator(1.0));
    const auto scene = [&](double sdOnBright, double sdOnDark) {
        std::array<ReplicaImages, 2> p = pair(rng, [&](int x) { return x % 2 ? sdOnBright : sdOnDark; });
        for (ReplicaImages& r : p)
            for (Image* i : {&r.image, &r.half[0], &r.half[1]})
                for (int y = 0; y < kSize; ++y)
                    for (int x = 0; x < kSize; ++x) i->at(x, y) = i->at(x, y) + Rgb(1, 1, 1) * float(truth(x) - 1);
        return p;
    };
    const std::array<ReplicaImages, 2> a = scene(sdBright, 0), b = scene(0, sdDark);
    const Image meanA = a[0].image, meanB = b[0].image;
    const std::vector<const Image*> both{&meanA, &meanB};
    const Image reference = medianImage(both);
    const MethodMeasure ma = measureMethod(a, tiles, true, 1, 1, &reference);
    const MethodMeasure mb = measureMethod(b, tiles, true, 1, 1, &reference);
    const std::vector<const TileStats*> stats{&ma.pair, &mb.pair};
    const auto e = relativeSquaredErrors(stats);
    double relmse[2] = {0, 0};
    for (size_t k = 0; k < 2; ++k)
        for (double x : e[k]) relmse[k] += x / tiles.count();
    // A half's variance sd^2, a replica's sd^2 / 2, the pair's mean's sd^2 / 4, on half of the
    // pixels.
    const double expected = sdBright * sdBright / 8 / relmseDenominator(1.0);
    qInfo("relmse a %.3g, b %.3g, expected %.3g", relmse[0], relmse[1], expected);
    QCOMPARE_LE(std::abs(relmse[1] / relmse[0] - 1.0), 0.25);
    QCOMPARE_LE(std::abs(relmse[0] / expected - 1.0), 0.25);
}

void TestMeasuredAuto::allocationReadsTheLongReplica() {
    // Replica 0 has run 100 passes and replica 1 stopped at 2, whose halves were 10 times less
    // noisy per pass (a chain before it met its rare paths). The allocation reads the error that
    // replica 0's own halves show, as the pair's mean by samples; the pair's spread, dominated by
    // replica 1, would read it about 50 times smaller.
    std::mt19937 rng(23);
    const TileGrid tiles(kSize, kSize, kTile);
    const double sdLong = 0.2, sdShort = 0.02, n0 = 100, n1 = 2;
    const std::array<ReplicaImages, 2> p{replica(rng, [&](int) { return sdLong; }),
                                         replica(rng, [&](int) { return sdShort; })};
    Image reference(kSize, kSize);
    for (Rgb& c : reference.pixels) c = Rgb(1, 1, 1);
    const MethodMeasure m = measureMethod(p, tiles, true, n0, n1, &reference);
    const auto relmse = [&](const TileStats& s) {
        const std::vector<const TileStats*> one{&s};
        const auto e = relativeSquaredErrors(one);
        return std::accumulate(e[0].begin(), e[0].end(), 0.0) / tiles.count();
    };
    // Replica 0's image: sd^2 / 2; as the pair's mean: n0 / (n0 + n1) of that.
    const double expected = n0 / (n0 + n1) * sdLong * sdLong / 2 / relmseDenominator(1.0);
    qInfo("allocation %.3g, pair %.3g, expected %.3g", relmse(m.allocation), relmse(m.pair), expected);
    QCOMPARE_LE(std::abs(relmse(m.allocation) / expected - 1.0), 0.1);
    QCOMPARE_LE(relmse(m.pair), 0.1 * expected);
    // Without a second half in replica 0 (its first pass), the pair's.
    std::array<ReplicaImages, 2> early = p;
    early[0].bothHalves = false;
    QCOMPARE(relmse(measureMethod(early, tiles, false, n0, n1, &reference).allocation), relmse(m.pair));
    // The weights read replica 0's level too (measured_auto_backend.cpp, weigh): its errors over
    // replica 1's, (0.2 / 0.02)^2 = 100, where error as 1 / samples would scale them by 0.02.
    const double level = errorLevelRatio(m.replica[0], m.replica[1]);
    qInfo("level %.1f", level);
    QCOMPARE_LE(std::abs(level / (sdLong * sdLong / (sdShort * sdShort)) - 1.0), 0.1);
}

void TestMeasuredAuto::trialsForWhatAShortRunUnderstates() {
    // Path out of the image (cost 1 of the 3.5 that would bring it in; the leader's 10), 20 left
    // in the budget.
    TrialQuestion q{"path", 0.85, 1.0, 1.0, 3.5, 10.0, 20.0, 0};
    // Close to the leader (the office floor's pilot: 0.83 to 1 of cmlt's), path takes a trial;
    // a chain, whose short run flatters it, does not.
    QVERIFY(takesTrial(q));
    QVERIFY(!takesTrial({"cmlt", 0.85, 1.0, 1.0, 3.5, 10.0, 20.0, 0}));
    QVERIFY(!takesTrial({"bdpt", 2.0, 1.0, 1.0, 3.5, 10.0, 20.0, 0}));
    QVERIFY(!takesTrial({"ir", 0.85, 1.0, 1.0, 3.5, 10.0, 20.0, 0}));
    // mir, whose chain and Pc settle (the daylit office's pilot: 0.74 to 1 of ir's), takes one.
    QVERIFY(takesTrial({"mir", 0.85, 1.0, 1.0, 3.5, 10.0, 20.0, 0}));
    // path where mirrors or glass make caustics, which its short run does not show: none.
    QVERIFY(!takesTrial({"path", 0.85, 1.0, 1.0, 3.5, 10.0, 20.0, 0, /*caustics=*/true}));
    // A first trial within kFirstTrialMargin (a pilot reads a heavy-tailed method by one draw:
    // mir on the daylit office, seed 2, 0.55 of ir's gain after one pass of relmse 3.36); further
    // behind: none.
    q.gain = 0.6;
    QVERIFY(takesTrial(q));
    q.gain = 0.45;
    QVERIFY(!takesTrial(q));
    // Later ones within kTrialMargin; after kCloseTrials such trials it must lead by it.
    q.closeTrials = 1;
    q.gain = 0.7;
    QVERIFY(!takesTrial(q));
    q.closeTrials = kCloseTrials - 1;
    q.gain = 0.85;
    QVERIFY(takesTrial(q));
    q.closeTrials = kCloseTrials;
    QVERIFY(!takesTrial(q));
    q.gain = 1.1;
    QVERIFY(!takesTrial(q));
    q.gain = 1.4;
    QVERIFY(takesTrial(q));
    // In the image with less cost than the leader: a trial (the leader would take every pass);
    // with as much: none.
    q.cost = 3.5;
    QVERIFY(takesTrial(q));
    q.cost = 10.0;
    QVERIFY(!takesTrial(q));
    // Out of the image with too little budget left to bring it in: none.
    q.cost = 1.0;
    q.costLeft = 2.0;
    QVERIFY(!takesTrial(q));
}

void TestMeasuredAuto::candidatesAreConsistent() {
    const std::string glass = R"({"lucerna": 1, "camera": {"position": [0, 1, -3], "target": [0, 0, 0], "fov_y": 50,
      "resolution": [16, 16]}, "materials": {"g": {"type": "dielectric", "ior": 1.5}},
      "objects": [{"name": "pane", "material": "g", "mesh": {"quad": [[-1,0,-1],[-1,0,1],[1,0,1],[1,0,-1]]}}],
      "lights": [{"name": "bulb", "type": "point", "position": [0, 2, 0], "intensity": [1, 1, 1]}]})";
    QCOMPARE(autoCandidates(parseScene(glass, "glass.json")), (std::vector<std::string>{"bdpt", "cmlt"}));
    // The same pane under an emitter: a path tracer reaches the lamp through it.
    const std::string panel = R"({"lucerna": 1, "camera": {"position": [0, 1, -3], "target": [0, 0, 0], "fov_y": 50,
      "resolution": [16, 16]}, "materials": {"g": {"type": "dielectric", "ior": 1.5},
      "lamp": {"type": "emitter", "radiance": [5, 5, 5]}},
      "objects": [{"name": "pane", "material": "g", "mesh": {"quad": [[-1,0,-1],[-1,0,1],[1,0,1],[1,0,-1]]}},
                  {"name": "lamp", "material": "lamp", "mesh": {"quad": [[-1,2,-1],[1,2,-1],[1,2,1],[-1,2,1]]}}]})";
    QCOMPARE(autoCandidates(parseScene(panel, "panel.json")), (std::vector<std::string>{"bdpt", "cmlt", "path"}));
    RectangleOverPlane s;
    QCOMPARE(autoCandidates(parseScene(s.json(), "plane.json")).size(), size_t(5));
}

void TestMeasuredAuto::bestByFarTakesTheTime() {
    // A closed sphere of albedo 0.95 lit by a small cap: nearly all of its light has bounced many
    // times. Gathering VPLs (ir, mir) carries that light at every pixel at once, where paths and
    // chains must find it one long path at a time: at equal rays ir and mir reach errors many
    // times below the others'. Counted in passes (--spp), auto's cost is rays.
    SphereWithEmittingCap s;
    s.rho = 0.95, s.rings = 16, s.segments = 32, s.resolution = 32, s.capAngleDeg = 20;
    RenderSettings settings;
    settings.spp = 40;
    settings.seed = 3;
    const RenderFrame f = renderFrame("auto", sceneFromJson(s.json()), settings);
    qInfo("%s", f.image.attributes.at("lucerna:auto").c_str());
    const double vpl = share(f.image, "auto_time", "ir") + share(f.image, "auto_time", "mir");
    QVERIFY2(vpl > 0.85, qPrintable(QString::number(vpl)));
    QVERIFY(share(f.image, "auto_weight", "ir") + share(f.image, "auto_weight", "mir") > 0.95);
    QCOMPARE_LE(std::abs(f.image.mean() / s.expectedRadiance() - 1.0), 0.02);
    // Once the pilots are done the carrying method takes nearly everything: "mir 0.97" in
    // lucerna:auto_decided (the cost when they were done, the method, its share since).
    std::istringstream decided(f.image.attributes.at("lucerna:auto_decided"));
    double pilotsDone = 0, since = 0;
    std::string carrying;
    QVERIFY(decided >> pilotsDone >> carrying >> since);
    QVERIFY(carrying == "ir" || carrying == "mir");
    QCOMPARE_GE(since, 0.95);
}

void TestMeasuredAuto::saysWhatItDecided() {
    RectangleOverPlane s;
    RenderSettings settings;
    settings.spp = 16;
    const RenderFrame f = renderFrame("auto", sceneFromJson(s.json()), settings);
    const auto& a = f.image.attributes;
    QCOMPARE(a.at("lucerna:backend"), std::string("auto"));
    QVERIFY(a.at("lucerna:auto").starts_with("measured path bdpt ir mir cmlt"));
    QVERIFY(a.at("lucerna:auto").find('\n') == std::string::npos);
    QVERIFY(a.at("lucerna:auto").find("; pilots done after ") != std::string::npos);
    QVERIFY(!a.at("lucerna:auto_methods").empty());
    double time = 0;
    for (const char* m : {"path", "bdpt", "ir", "mir", "cmlt"}) time += share(f.image, "auto_time", m);
    QCOMPARE_LE(std::abs(time - 1.0), 0.01);
    QVERIFY(std::isfinite(f.estimatedRelmse));
}

void TestMeasuredAuto::reproducibleWithSeed() {
    RectangleOverPlane s;
    RenderSettings settings;
    settings.spp = 12;
    settings.seed = 9;
    const SceneSnapshot scene = sceneFromJson(s.json());
    const RenderFrame a = renderFrame("auto", scene, settings, 1), b = renderFrame("auto", scene, settings, 1);
    QCOMPARE(a.image.attributes.at("lucerna:auto_time"), b.image.attributes.at("lucerna:auto_time"));
    QVERIFY(a.image.pixels == b.image.pixels);
    settings.seed = 10;
    QVERIFY(renderFrame("auto", scene, settings, 1).image.pixels != a.image.pixels);
}

QTEST_GUILESS_MAIN(TestMeasuredAuto)
#include "test_measured_auto.moc"
