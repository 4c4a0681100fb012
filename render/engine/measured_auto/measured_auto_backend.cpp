#include "render/engine/measured_auto/measured_auto_backend.h"

#include "core/number_format.h"
#include "render/engine/backend_table.h"
#include "render/engine/measured_auto/film_measures.h"
#include "render/engine/measured_auto/measured_auto_settings.h"
#include "render/engine/measured_auto/trial.h"
#include "render/trace/embree_scene.h"
#include "render/trace/render_scene_cache.h"
#include "render/trace/rng.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <optional>
#include <ranges>
#include <thread>

#include <tbb/parallel_for.h>

namespace lucerna {

namespace {

// A method whose weight in a tile would be under this takes none there (film_measures.h).
constexpr double kMinimumWeight = 0.1;
// A method whose cost is under this share of the costliest's that may be in the image
// (costliestInImage) is left out of it.
constexpr double kMinimumShare = 0.35;

struct Method {
    std::string name;
    std::array<std::unique_ptr<Backend>, 2> replicas;
    // After its pilot a method's passes go to replica 0, replica 1 stopping at two passes (its
    // halves, for the measures): two runs of half the length are worse than one. A Markov
    // chain's error falls faster than 1 / time while it settles (mir on a closed sphere of
    // albedo 0.9: 5 times from 15 to 30 s), and so does a Sobol sequence's on smooth integrands
    // (path on the Cornell box and the office floor was 1.1 to 1.26 times its error alone with
    // two replicas at 92% of the time).
    std::array<int, 2> passes{0, 0};
    double cost = 0;  // seconds or rays of its passes, both replicas
    std::array<double, 2> costSincePilots{0, 0};  // of each replica's passes once every pilot was done
    std::array<bool, 2> prepared{false, false};
    int piloted() const { return std::min(passes[0], passes[1]); }
};

// What the last measure found, per method (0 for a method not yet measured).
struct Measures {
    std::vector<double> gain;         // relmse taken off per unit of cost (film_measures.h)
    std::vector<double> efficiency;   // 1 / (relmse x cost), relative to the best
    std::vector<double> imageWeight;  // mean weight over the tiles
    std::vector<bool> farBehind;      // gain under dropBelow of the best's: its pilot ends
    double cost = 0;                  // the render's cost when measured
    bool taken = false;
};

class MeasuredAutoBackend : public Backend {
public:
    MeasuredAutoBackend(SceneSnapshot scene, const RenderSettings& settings)
        : auto_(MeasuredAutoSettings::forScene(*scene, settings)), firstFrameSoon_(settings.firstFrameSoon),
          start_(std::chrono::steady_clock::now()) {
        RenderSettings each = settings;
        if (!each.sharedScenes) each.sharedScenes = std::make_shared<RenderSceneCache>();
        // A method far behind stops after its pilot: what only a longer run needs waits for its
        // second pass (renderPass).
        each.deferPreparation = true;
        if (auto_.cost == AutoCost::Rays && !each.rayRecorder) {
            rays_ = std::make_unique<RayRecorder>(int(std::thread::hardware_concurrency()) + 1, /*countOnly=*/true);
            each.rayRecorder = rays_.get();
        }
        recorder_ = each.rayRecorder;
        for (size_t k = 0; k < auto_.candidates.size(); ++k) {
            Method m;
            m.name = auto_.candidates[k];
            for (int r = 0; r < 2; ++r) {
                each.seed = hashSeed(settings.seed, 0x6175746f + k, uint64_t(r));
                m.replicas[size_t(r)] = findBackend(m.name)->make(scene, each);
            }
            methods_.push_back(std::move(m));
        }
        closeTrials_.assign(methods_.size(), 0);
    }

    // In the window (firstFrameSoon) only the first method is prepared here, each other one before
    // its first pass, so that the first frame comes after one method's preparation, not six (the
    // office floor's first frame in the window: 20 s, most of it MLT's and CMLT's bootstrap and
    // the VPL sets; issue 40); elsewhere all are, so that a time budget counts passes only, as
    // for a single method. Preparing is counted in no method's cost.
    void prepare(TaskContext& ctx) override {
        if (methods_.empty()) return;  // the film stays empty (0 x 0)
        for (size_t k = 0; k < (firstFrameSoon_ ? 1 : methods_.size()); ++k)
            if (!prepareMethod(methods_[k], ctx)) return;
        const Film& f = methods_[0].replicas[0]->film();
        film_ = std::make_unique<Film>(f.width(), f.height());
    }

    void renderPass(TaskContext& ctx, int) override {
        const size_t k = nextMethod();
        Method& m = methods_[k];
        if (!prepareMethod(m, ctx)) return;
        // Past its first pass a method completes what its pilot went without (once; after that
        // a call returns at once), outside its cost as its preparation is: else the door's cmlt,
        // with its bootstrap's rest (1 s) in its third pass, measured 0.75 of mir's efficiency
        // and lost the render (relmse 1.7 times).
        if (m.passes[0] >= 1) {
            for (auto& r : m.replicas) r->completePreparation(ctx);
            if (ctx.isCancelled()) return;
        }
        const double before = costNow();
        const bool eligibleBefore = m.piloted() >= 2;
        for (int r = 0; r < 2; ++r) {
            if (r == 1 && pilotDone(k) && m.passes[1] >= 2) continue;
            const double passStart = costNow();
            m.replicas[size_t(r)]->renderPass(ctx, m.passes[size_t(r)]);
            if (ctx.isCancelled()) return;
            ++m.passes[size_t(r)];
            if (pilotsDone_) m.costSincePilots[size_t(r)] += costNow() - passStart;
        }
        m.cost += costNow() - before;
        dirty_ = true;
        // A trial is measured again once the method's cost has doubled: a pilot's estimate that
        // was too good costs about what the method had, not a quarter of the render.
        // So is a method that has just its second pass in each replica, which may now be in
        // the image: with `--spp 16` on a small room the image stayed the pilots' equal mix while
        // path took every pass after them.
        const bool trialDue = trial_ && methods_[trial_->method].cost >= 2 * trial_->startCost;
        const bool eligible = !eligibleBefore && m.piloted() >= 2;
        if (allPiloted() &&
            (!measures_.taken || trialDue || eligible || totalCost() >= (1 + auto_.remeasureGrowth) * measures_.cost))
            measure();
        if (!pilotsDone_ &&
            std::ranges::all_of(std::views::iota(size_t(0), methods_.size()), [&](size_t j) { return pilotDone(j); }))
            pilotsDone_ = totalCost();
    }

    double deferredPreparationSeconds() const override {
        double s = 0;
        for (const Method& m : methods_)
            for (const auto& r : m.replicas) s += r->deferredPreparationSeconds();
        return s;
    }

    // Frames may come after every pass (lucerna bench): between measures the film is composed
    // again with the last measure's weights, which costs a frame of the methods in the image.
    const Film& film() const override {
        if (dirty_) combination_.methods.empty() ? measure() : compose();
        return *film_;
    }

    // The film's halves are not two equal estimates (half 1 is the short replicas'), so the
    // estimate is the methods' in the image: each one's long replica's own estimate (from its
    // halves), by its weight in the image squared. One method carrying the image reads as that
    // method alone would.
    double estimatedRelmse() const override {
        const Film& f = film();
        if (!measures_.taken) return f.estimatedRelmse();
        double e = 0;
        for (size_t k : combination_.methods) {
            const double w = measures_.imageWeight[k];
            if (w > 0) e += w * w * methods_[k].replicas[0]->film().estimatedRelmse();
        }
        return e;
    }

    std::map<std::string, std::string> diagnostics() const override {
        film();
        std::map<std::string, std::string> d{
            {"auto", summary()}, {"auto_methods", carrying()}, {"auto_time", shares(false)}, {"auto_weight", shares(true)}};
        if (const auto p = decided())
            d["auto_decided"] = fixedNumber(p->pilotsDone, 1) + " " + methods_[p->carrying].name + " " + fixedNumber(p->share, 3);
        return d;
    }

    void rewriteFilms(const std::function<void(Film&)>& rewrite) override {
        for (Method& m : methods_)
            for (auto& r : m.replicas) r->rewriteFilms(rewrite);
        dirty_ = true;
    }

private:
    // False when cancelled before both replicas were prepared.
    static bool prepareMethod(Method& m, TaskContext& ctx) {
        for (size_t r = 0; r < m.replicas.size(); ++r) {
            if (m.prepared[r]) continue;
            if (ctx.isCancelled()) return false;
            m.replicas[r]->prepare(ctx);
            m.prepared[r] = !ctx.isCancelled();
        }
        return m.prepared[0] && m.prepared[1];
    }

    double costNow() const {
        if (auto_.cost == AutoCost::Rays) return double(recorder_->total());
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }
    double totalCost() const {
        return std::accumulate(methods_.begin(), methods_.end(), 0.0, [](double s, const Method& m) { return s + m.cost; });
    }
    // The cost of the costliest method that may be in the image (two passes in each replica): a
    // method under kMinimumShare of it is out. A pilot's single passes do not set the bar: with
    // `--spp 16` on a small room mir's one pass cost 39%, and path, with every other pass, stayed
    // out, leaving no method in the image.
    double costliestInImage() const {
        double c = 0;
        for (const Method& m : methods_)
            if (m.piloted() >= 2) c = std::max(c, m.cost);
        return c;
    }
    bool allPiloted() const {
        return std::ranges::all_of(methods_, [&](const Method& m) { return m.piloted() >= auto_.pilotPasses; });
    }
    double samples(size_t k, int replica) const { return methods_[k].replicas[size_t(replica)]->film().samplesPerPixel(); }
    bool farBehind(size_t k) const { return measures_.taken && measures_.farBehind[k]; }
    bool pilotDone(size_t k) const {
        const Method& m = methods_[k];
        return m.piloted() >= auto_.pilotPasses &&
               (auto_.cost == AutoCost::Rays || m.cost >= auto_.pilotSeconds || farBehind(k));
    }

    // Pilots first, interleaved (the fewest passes, then the least cost), then the largest gain.
    size_t nextMethod() const {
        size_t best = methods_.size();
        for (size_t k = 0; k < methods_.size(); ++k)
            if (methods_[k].piloted() < auto_.pilotPasses &&
                (best == methods_.size() || methods_[k].piloted() < methods_[best].piloted()))
                best = k;
        if (best < methods_.size()) return best;
        for (size_t k = 0; k < methods_.size(); ++k)
            if (!pilotDone(k) && (best == methods_.size() || methods_[k].cost < methods_[best].cost)) best = k;
        if (best < methods_.size()) return best;
        if (!measures_.taken || measures_.gain.size() != methods_.size()) return 0;  // not measured (not prepared)
        // A trial runs until its method's cost has doubled: a measure taken before, as the render
        // grows, does not end it. Else a first trial, taken at kFirstTrialMargin, ended at the
        // next such measure, which asks kTrialMargin (the daylit office, seed 4: one pass of mir).
        if (trial_) {
            if (methods_[trial_->method].cost < 2 * trial_->startCost) return trial_->method;
            trial_.reset();
        }
        // A method out of the image (under kMinimumShare of costliestInImage) adds nothing
        // until it is in: its gain counts by how far along it is, so that a pilot's optimistic
        // estimate does not draw time that the image then leaves out (the office floor: cmlt took
        // 14% of the time, path kept the image).
        const double costliest = costliestInImage();
        std::vector<double> gains(methods_.size());
        for (size_t k = 0; k < methods_.size(); ++k) {
            const double share = costliest > 0 ? std::min(1.0, methods_[k].cost / (kMinimumShare * costliest)) : 1.0;
            gains[k] = std::isfinite(measures_.gain[k]) ? measures_.gain[k] * share : -1.0;
        }
        const size_t leader = size_t(std::ranges::max_element(gains) - gains.begin());
        const double leading = gains[leader];
        // A method on trial takes the pass, the one with the largest gain if several are.
        // Open-ended (the window, or counted in passes), the budget left is as long again as so far.
        const double total = totalCost();
        const double costLeft = auto_.budgetSeconds > 0 ? auto_.budgetSeconds - total : total;
        std::optional<size_t> onTrial;
        for (size_t k = 0; k < methods_.size(); ++k) {
            const TrialQuestion q{methods_[k].name, measures_.gain[k], leading, methods_[k].cost,
                                  kMinimumShare * costliest, methods_[leader].cost, costLeft, closeTrials_[k],
                                  auto_.caustics};
            if (k != leader && takesTrial(q) && (!onTrial || measures_.gain[k] > measures_.gain[*onTrial])) onTrial = k;
        }
        if (!onTrial) return leading >= 0 ? leader : 0;
        trial_ = Trial{*onTrial, methods_[*onTrial].cost};
        if (!leadsByMargin(measures_.gain[*onTrial], leading)) ++closeTrials_[*onTrial];
        return *onTrial;
    }

    // Measures every method with a pass in each replica (the allocation), and makes the film the
    // combination of those with two (film_measures.h).
    void measure() const {
        dirty_ = false;
        if (film_->width() == 0) return;  // not prepared
        const TileGrid tiles(film_->width(), film_->height(), auto_.tileSize);
        std::vector<size_t> measured;
        for (size_t k = 0; k < methods_.size(); ++k)
            if (methods_[k].piloted() >= 1) measured.push_back(k);
        if (measured.empty()) return;
        // A task per replica's film, then one per method: one core's measures took 2.5% of a 30 s
        // render of the Cornell box (0.75 s for 14) while the others waited; 0.4 s on two cores.
        std::vector<std::array<ReplicaImages, 2>> images(measured.size());
        tbb::parallel_for(size_t(0), 2 * measured.size(), [&](size_t j) {
            const Method& method = methods_[measured[j / 2]];
            const int r = int(j % 2);
            const Film& f = method.replicas[size_t(r)]->film();
            // Pass p goes to half p % 2: two passes fill both halves.
            images[j / 2][size_t(r)] = {f.image(), {f.halfImage(0), f.halfImage(1)}, method.passes[size_t(r)] >= 2};
        });
        // Only the allocation reads the per-pixel errors, and it waits for every pilot: the frames
        // shown before then do without the median image.
        const bool allocating = allPiloted();
        const Image reference = allocating ? consensus(measured, images) : Image();
        std::vector<MethodMeasure> m(measured.size());
        tbb::parallel_for(size_t(0), measured.size(), [&](size_t i) {
            const size_t k = measured[i];
            m[i] = measureMethod(images[i], tiles, methods_[k].piloted() >= 2, samples(k, 0), samples(k, 1),
                                 allocating ? &reference : nullptr);
        });
        std::vector<const TileStats*> pair, allocation;
        for (const MethodMeasure& x : m) pair.push_back(&x.pair), allocation.push_back(&x.allocation);
        // The allocation weighs each method's relmse as measured at its length, per pixel (not
        // spread over the tiles as the weights' errors are: film_measures.h).
        if (allocating) allocate(measured, relativeSquaredErrors(allocation));
        // Each method's image-wide error from the spread of its replicas, relative.
        weigh(measured, m, relativeErrors(pair, measuredSquaredErrors(pair)), tiles);
        compose();
    }

    // What stands for the truth in SPEC's denominators: per pixel, the median of the methods'
    // images (each the mean of its replicas by their samples).
    Image consensus(const std::vector<size_t>& measured, const std::vector<std::array<ReplicaImages, 2>>& images) const {
        std::vector<Image> means;
        for (size_t i = 0; i < measured.size(); ++i) {
            const double n0 = samples(measured[i], 0), n1 = samples(measured[i], 1);
            Image mean = images[i][0].image;
            for (size_t p = 0; p < mean.pixels.size(); ++p)
                mean.pixels[p] = (images[i][0].image.pixels[p] * float(n0) + images[i][1].image.pixels[p] * float(n1)) *
                                 float(1.0 / (n0 + n1));
            means.push_back(std::move(mean));
        }
        std::vector<const Image*> all;
        for (const Image& i : means) all.push_back(&i);
        return medianImage(all);
    }

    // The gains, from each method's relative errors at its length (MethodMeasure::allocation),
    // once every method has its pilot passes; they decide.
    void allocate(const std::vector<size_t>& measured, const std::vector<std::vector<double>>& errors) const {
        std::vector<double> costs;
        for (size_t k : measured) costs.push_back(methods_[k].cost);
        const auto pooled = pooledTowardMean(errors);
        const std::vector<double> gains = marginalGains(pooled, costs);
        measures_ = Measures{};
        measures_.gain.assign(methods_.size(), 0.0);
        measures_.efficiency.assign(methods_.size(), 0.0);
        measures_.imageWeight.assign(methods_.size(), 0.0);
        measures_.farBehind.assign(methods_.size(), false);
        measures_.cost = totalCost();
        measures_.taken = true;
        for (size_t i = 0; i < measured.size(); ++i) {
            const double relmse = std::accumulate(pooled[i].begin(), pooled[i].end(), 0.0);
            measures_.gain[measured[i]] = gains[i];
            measures_.efficiency[measured[i]] = relmse > 0 && costs[i] > 0 ? 1.0 / (relmse * costs[i]) : 0.0;
        }
        const double bestGain = *std::ranges::max_element(measures_.gain);
        const double bestEfficiency = *std::ranges::max_element(measures_.efficiency);
        for (size_t k = 0; k < methods_.size(); ++k) {
            measures_.farBehind[k] = measures_.gain[k] < auto_.dropBelow * bestGain;
            if (bestEfficiency > 0) measures_.efficiency[k] /= bestEfficiency;
        }
    }

    // The weights of replica r's images from what replica 1 - r shows (cross-fitting).
    // pairRelative: each method's image-wide relative error from its replicas' spread, which
    // floors what a replica's halves show (halves of a chain, or of one VPL set a pass, share
    // errors across the whole image that no tile sees); one number from the whole image, so it
    // hardly depends on any value it weighs.
    void weigh(const std::vector<size_t>& measured, const std::vector<MethodMeasure>& m,
               const std::vector<double>& pairRelative, const TileGrid& tiles) const {
        Combination c;
        // The methods with two passes in each replica whose cost is at least kMinimumShare of the
        // costliest's. Under the allocation a method that stays near its pilot's cost adds
        // little, and its error estimate is the least sure of all: a short replica 1 makes a
        // chain's long replica 0 look worse than it is (its error falls faster than 1 /
        // samples), so a partner with a pilot's few passes of one VPL set would take a weight
        // its noise does not earn (the door: mir with 5% of the time took 17% of the image next
        // to cmlt, 1.8 times cmlt's error alone).
        const double costliest = costliestInImage();
        std::vector<size_t> in;
        for (size_t i = 0; i < m.size(); ++i)
            if (m[i].hasReplicaStats() && methods_[measured[i]].cost >= kMinimumShare * costliest) in.push_back(i);
        // Before any method has two passes (the first frames): every method with one, equally.
        const bool equal = in.empty();
        if (equal)
            for (size_t i = 0; i < m.size(); ++i) in.push_back(i);
        for (size_t i : in) c.methods.push_back(measured[i]);
        for (int r = 0; r < 2; ++r) {
            auto& w = c.weights[size_t(r)];
            if (equal) {
                w.assign(in.size(), std::vector(size_t(tiles.count()), 1.0 / double(in.size())));
                continue;
            }
            // Replica 1 - r's errors (its means tested against each other on its own scale),
            // then as replica r's would be with its own samples: error as 1 / samples, replica 0
            // running longer than replica 1. The pair's error is that of the mean by samples,
            // n / n_s times replica s's: half of it floors replica s's.
            // The long replica's errors are at least at the level its own halves show against
            // the short one's (errorLevelRatio: one number a method, so the tiles' pattern stays
            // the short replica's): a chain's error need not fall as 1 / samples (cmlt on the
            // satin-ball caustic: relmse x seconds 3.3 times from 0.3 s to 30 s), and where it
            // fell slower, or a chain of the long one stuck on a rare bright path, the long
            // replica took a weight its noise did not earn (seed 11: cmlt with 22% of the time took
            // 0.45 of the image beside bdpt, 5.4 times bdpt's error alone). Only up: a short
            // replica of one or two VPL sets a half shows its image-wide level with few degrees
            // of freedom, and where that read high the long replica would take weight unearned.
            const int s = 1 - r;
            std::vector<const TileStats*> other;
            std::vector<double> floors;
            for (size_t i : in) {
                const size_t k = measured[i];
                other.push_back(&m[i].replica[size_t(s)]);
                floors.push_back(0.5 * pairRelative[i] * (samples(k, 0) + samples(k, 1)) / samples(k, s));
            }
            auto errors = expectedSquaredErrors(other, floors);
            for (size_t j = 0; j < in.size(); ++j) {
                const size_t k = measured[in[j]];
                double scale = samples(k, s) / samples(k, r);
                if (r == 0) scale = std::max(scale, errorLevelRatio(m[in[j]].replica[0], m[in[j]].replica[1]));
                for (double& e : errors[j]) e *= scale;
            }
            w = inverseErrorWeights(errors, kMinimumWeight);
        }
        const std::array<double, 2> sums{halfSamples(c.methods, 0), halfSamples(c.methods, 1)};
        // A method's weight in the image: over the tiles, and over the halves by their samples.
        if (measures_.taken)
            for (size_t j = 0; j < in.size(); ++j) {
                double w = 0;
                for (int r = 0; r < 2; ++r)
                    for (double x : c.weights[size_t(r)][j]) w += sums[size_t(r)] / (sums[0] + sums[1]) * x / tiles.count();
                measures_.imageWeight[c.methods[j]] = w;
            }
        combination_ = std::move(c);
    }

    // The film's half r is replica r's images combined by the weights of the last measure, with
    // the replicas' samples now.
    void compose() const {
        dirty_ = false;
        const TileGrid tiles(film_->width(), film_->height(), auto_.tileSize);
        Film out(tiles.width, tiles.height);
        for (int r = 0; r < 2; ++r) {
            std::vector<Image> images;
            for (size_t k : combination_.methods) images.push_back(methods_[k].replicas[size_t(r)]->film().image());
            std::vector<const Image*> values;
            for (const Image& i : images) values.push_back(&i);
            const double sum = halfSamples(combination_.methods, r);
            const Image half = combineImages(values, combination_.weights[size_t(r)], tiles);
            for (int y = 0; y < half.height; ++y)
                for (int x = 0; x < half.width; ++x) out.addSample(r, x, y, half.at(x, y) * float(sum));
            out.finishPass(r, sum);
        }
        *film_ = std::move(out);
    }

    // The samples half r of the film counts: each method's replica r's. A short replica is worth
    // less than its samples (its error has not fallen as a long run's does), so it counts by the
    // share it has of the long one's: fixed by the sample counts, not by the values, so the
    // image stays consistent.
    double halfSamples(const std::vector<size_t>& methods, int r) const {
        double sum = 0;
        for (size_t k : methods) sum += samples(k, r) * std::min(1.0, samples(k, r) / samples(k, 1 - r));
        return sum;
    }

    // "time: mir 81%, path 9%, ...; image: mir 0.86, ...; efficiency (best 1): ..."
    std::string summary() const {
        const double total = totalCost();
        std::vector<size_t> order(methods_.size());
        std::iota(order.begin(), order.end(), size_t(0));
        std::ranges::stable_sort(order, [&](size_t a, size_t b) { return methods_[a].cost > methods_[b].cost; });
        std::string s = "measured";
        for (const Method& m : methods_) s += " " + m.name;
        s += " (two replicas each); time:";
        for (size_t k : order)
            s += " " + methods_[k].name + " " + fixedNumber(total > 0 ? 100.0 * methods_[k].cost / total : 0.0, 0) + "% (" +
                 std::to_string(methods_[k].passes[0]) + " passes)";
        if (!measures_.taken) return s + "; still in the pilots";
        s += "; image weight:";
        for (size_t k : order) s += " " + methods_[k].name + " " + formatNumber(measures_.imageWeight[k], 2);
        s += "; efficiency (best 1):";
        for (size_t k : order) s += " " + methods_[k].name + " " + formatNumber(measures_.efficiency[k], 2);
        return s + decision();
    }

    // When every pilot was first done, in the render's cost, the method that carries the image
    // now (the largest weight) and its share of the cost since: what auto spent beyond that
    // method alone is the part before, its short replica and the others' passes after (trials,
    // a far-behind method measured back in).
    struct Decision {
        double pilotsDone;
        size_t carrying;
        double share, longShare;  // of the cost since pilotsDone: both its replicas, its long one
    };
    std::optional<Decision> decided() const {
        if (!pilotsDone_ || !measures_.taken) return std::nullopt;
        Decision d{*pilotsDone_, size_t(std::ranges::max_element(measures_.imageWeight) - measures_.imageWeight.begin()), 0, 0};
        const auto& [longReplica, shortReplica] = methods_[d.carrying].costSincePilots;
        const double both = longReplica + shortReplica, since = totalCost() - d.pilotsDone;
        d.share = since > 0 ? both / since : 1.0;
        d.longShare = since > 0 ? longReplica / since : 1.0;
        return d;
    }

    // "; pilots done after 3.4 s of 30 s, mir 99% of the time since (its long replica 97%)".
    std::string decision() const {
        const auto d = decided();
        if (!d) return "";
        const std::string after = ", " + methods_[d->carrying].name + " " + fixedNumber(100.0 * d->share, 0) +
                                  "% of the time since (its long replica " + fixedNumber(100.0 * d->longShare, 0) + "%)";
        if (auto_.cost == AutoCost::Rays)
            return "; pilots done after " + fixedNumber(100.0 * d->pilotsDone / totalCost(), 0) + "% of the rays" + after;
        return "; pilots done after " + fixedNumber(d->pilotsDone, 1) + " s of " + fixedNumber(totalCost(), 1) + " s" + after;
    }

    // "path=0.81 bdpt=0.03 ...": each method's share of the cost, or its mean weight in the image.
    std::string shares(bool weights) const {
        const double total = totalCost();
        std::string s;
        for (size_t k = 0; k < methods_.size(); ++k) {
            const double x = weights ? (measures_.taken ? measures_.imageWeight[k] : 0.0)
                                     : (total > 0 ? methods_[k].cost / total : 0.0);
            s += (k ? " " : "") + methods_[k].name + "=" + formatNumber(x, 3);
        }
        return s;
    }

    // The methods that carry a twentieth of the image or more, the heaviest first.
    std::string carrying() const {
        if (!measures_.taken) return "";
        std::vector<size_t> order(methods_.size());
        std::iota(order.begin(), order.end(), size_t(0));
        std::ranges::stable_sort(order, [&](size_t a, size_t b) { return measures_.imageWeight[a] > measures_.imageWeight[b]; });
        std::string s;
        for (size_t k : order)
            if (measures_.imageWeight[k] >= 0.05) s += (s.empty() ? "" : " ") + methods_[k].name;
        return s;
    }

    MeasuredAutoSettings auto_;
    bool firstFrameSoon_;
    std::chrono::steady_clock::time_point start_;
    std::unique_ptr<RayRecorder> rays_;
    RayRecorder* recorder_ = nullptr;
    std::vector<Method> methods_;
    mutable Measures measures_;
    // The method on trial (takesTrial), and its cost when the trial began: it runs until that has
    // doubled (nextMethod).
    struct Trial {
        size_t method;
        double startCost;
    };
    mutable std::optional<Trial> trial_;
    // Per method: the trials it has taken without leading by kTrialMargin (trial.h).
    mutable std::vector<int> closeTrials_;
    // The last measure's combination: the methods in the image and their weights per tile for
    // each half (replica).
    struct Combination {
        std::vector<size_t> methods;
        std::array<std::vector<std::vector<double>>, 2> weights;
    };
    mutable Combination combination_;
    mutable bool dirty_ = true;
    std::optional<double> pilotsDone_;  // the render's cost when every pilot was first done
    mutable std::unique_ptr<Film> film_ = std::make_unique<Film>(0, 0);
};

}  // namespace

std::unique_ptr<Backend> makeMeasuredAutoBackend(SceneSnapshot scene, const RenderSettings& settings) {
    return std::make_unique<MeasuredAutoBackend>(std::move(scene), settings);
}

}  // namespace lucerna
