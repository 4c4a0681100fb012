#include "render/photometry/grid_auto.h"

#include "core/number_format.h"
#include "core/sub_task.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

namespace lucerna {

namespace {

using Clock = std::chrono::steady_clock;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// A pilot lasts this share of the running method's projected rest, and all pilots together take
// at most the larger share of its projected total; shorter than the shortest, a pilot is not
// worth running (its method would barely start: path and ir start at once, the replicas' methods
// prepare each replica first). A method that gave no measure in its pilot
// (still preparing at the deadline) is tried again with a pilot four times as long, when the
// running method's rest allows one. A pilot's deadline (preparation included) is its length
// times the overrun, plus the grace.
constexpr double kPilotShare = 0.05;
// Path and ir, which start at once, have a short first pilot, a hundredth of the running one's
// rest (at least kShortestPointPilotSeconds): one clearly ahead shows it that soon (the caustic
// floor: path's projection from 0.3 s is 0.55 times ir's, ir waiting 0.3 s for path's first
// pilot instead of 1.4 s). One that does not take over but is close (its rest under kCloseRatio
// times the running one's) is piloted again at the full share, before the others; one further
// behind is beaten (revisitBeaten). The short pilot's passes are lost.
constexpr double kFirstPointPilotShare = 0.01;
constexpr double kCloseRatio = 3;
// A method whose second pilot's projection differs from its first by more than this factor met a
// heavy tail in one of them (the satin ball, seed 4: path 21 s, then 77 s; path alone takes 7 s),
// so it is piloted a third time, again at the full share, before it can be beaten.
constexpr double kDisagreementRatio = 2;
constexpr double kPilotsShare = 0.1;
constexpr double kShortestPilotSeconds = 0.05;
constexpr double kShortestPointPilotSeconds = 0.01;  // path, ir
constexpr double kRetryFactor = 4;
constexpr double kPilotOverrun = 1.5;
constexpr double kPilotGraceSeconds = 0.02;
// The margin by which a challenger must beat the running method (challengerTakesOver).
constexpr double kTakeOverRatio = 0.7;

double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
std::string secondsText(double s) { return std::isfinite(s) ? formatNumber(s, 2) : "-"; }

// The methods auto may run, the cheapest to start first (the first runs from the start).
std::vector<GridMethod> candidates(bool litThroughGlass) {
    if (litThroughGlass) return {GridMethod::Bdpt, GridMethod::Mlt, GridMethod::Cmlt};
    return {GridMethod::Vpl, GridMethod::Path, GridMethod::Bdpt, GridMethod::Mir, GridMethod::Mlt, GridMethod::Cmlt};
}

// Path and ir estimate each point pass by pass; the other methods render replicas.
bool estimatesPoints(GridMethod m) { return m == GridMethod::Path || m == GridMethod::Vpl; }

double shortestPilot(GridMethod m) { return estimatesPoints(m) ? kShortestPointPilotSeconds : kShortestPilotSeconds; }


// The running method's projections as it ran: (its own seconds, projected seconds).
using History = std::vector<std::pair<double, double>>;

// What a pilot is weighed against: the running method's history and where it stands now.
struct Opponent {
    double budgetSeconds;
    bool shortPilot;  // path's or ir's first pilot (kFirstPointPilotShare)
    const History* history;
    double needsSeconds, ranSeconds;
};

class AutoGrid {
public:
    AutoGrid(const RenderScene& scene, const std::vector<V3d>& points, const V3d& normal, const GridSettings& settings,
             TaskContext& ctx, const std::function<void(const GridResult&)>& onPass, bool litThroughGlass)
        : scene_(scene), points_(points), normal_(normal), settings_(settings), ctx_(ctx), onPass_(onPass),
          limit_(settings.timeLimitSeconds > 0 ? settings.timeLimitSeconds : kInfinity) {
        for (GridMethod m : candidates(litThroughGlass)) pending_.push_back({m, 0.0, estimatesPoints(m)});
        first_ = pending_.front().method;
        pending_.erase(pending_.begin());
    }

    GridResult compute() {
        GridResult result = *run(first_, std::nullopt);
        result.seconds = secondsSince(begin_);
        result.autoMeasured = line(result.method);
        if (onPass_) onPass_(result);
        return result;
    }

private:
    struct Pending {
        GridMethod method;
        double triedSeconds;  // its last pilot's length, which gave no measure (0: none yet)
        bool shortPilot;      // its next pilot is path's or ir's first (kFirstPointPilotShare)
    };

    // Runs `method` to the grid's end (its target or time limit, or cancelled), or, as a pilot
    // against an opponent, until it has run the pilot's length: then it goes on to the end only
    // if it takes over. Nothing for a pilot that did not (nor where the job was cancelled in it).
    // A method piloted between this one's passes that takes over ends this one with its result.
    std::optional<GridResult> run(GridMethod method, std::optional<Opponent> opponent) {
        SubTask task(ctx_, opponent ? kPilotOverrun * opponent->budgetSeconds + kPilotGraceSeconds : kInfinity);
        bool piloting = opponent.has_value(), lost = false;
        const auto start = Clock::now();
        std::optional<GridResult> overtaken;
        History history;
        double pilotsWithin = 0;  // seconds of pilots within this run (its clock counts them)
        GridSettings own = settings_;
        own.autoMethod = false;
        own.method = method;
        own.timeLimitSeconds = std::isfinite(limit_) ? std::max(0.01, limit_ - secondsSince(begin_)) : 0;
        if (piloting) own.seed = settings_.seed + 0x70696c6f + uint64_t(pilotCount_++);
        GridResult last = computeGridIlluminance(scene_, points_, normal_, own, task.context(), [&](const GridResult& r) {
            if (ctx_.isCancelled() || overtaken || lost) return;
            const double ran = r.seconds - pilotsWithin;
            const double needs = projectedGridSeconds(r, ran, method, settings_);
            if (piloting) {
                if (ran < opponent->budgetSeconds && !r.converged) return;
                piloting = false;
                pilotSeconds_ += ran;
                if (!takesOver(method, r, needs, *opponent)) {
                    lost = true;
                    task.cancel();
                    return;
                }
                task.setDeadline(kInfinity);
            }
            ctx_.setProgress(task.context().progress());
            if (onPass_) {
                GridResult shown = r;
                shown.autoMeasured = line(method);
                onPass_(shown);
            }
            if (!std::isfinite(needs) || r.converged) return;
            history.emplace_back(ran, needs);
            revisitBeaten(ran, needs);
            const auto pilotStart = Clock::now();
            const std::optional<Pending> challenger = nextPilot(ran, needs);
            if (!challenger) return;
            std::optional<GridResult> won = run(challenger->method, Opponent{budget(ran, needs, *challenger),
                                                                             challenger->shortPilot, &history, needs, ran});
            if (won) {
                overtaken = std::move(won);
                task.cancel();
                return;
            }
            pilotsWithin += secondsSince(pilotStart);
        });
        if (overtaken) return overtaken;
        if (piloting && !ctx_.isCancelled()) {  // cut at its deadline, still preparing
            const double spent = secondsSince(start);
            pilotSeconds_ += spent;
            noMeasure(method, opponent->budgetSeconds, spent);
        }
        if (piloting || lost) return std::nullopt;
        last.method = method;
        return last;
    }

    // The length of p's pilot now: a share of the running method's rest, within the pilots'
    // share of its total; it waits until that method has run as long (so that the two are
    // weighed at equal times, takesOver).
    double budget(double ran, double needs, const Pending& p) const {
        const double rest = std::min(needs - ran, limit_ - secondsSince(begin_));
        const double share = p.shortPilot ? std::max(kFirstPointPilotShare * rest, kShortestPointPilotSeconds) : kPilotShare * rest;
        return std::min({share, kPilotShare * rest, kPilotsShare * needs - pilotSeconds_});
    }

    // The next method to pilot between the running method's passes, taken off the pending list;
    // nothing when no pilot is worth its cost now.
    std::optional<Pending> nextPilot(double ran, double needs) {
        const auto next = std::ranges::find_if(pending_, [&](const Pending& p) {
            const double b = budget(ran, needs, p);
            return ran >= b &&
                   b >= std::max(shortestPilot(p.method), kRetryFactor * p.triedSeconds);
        });
        if (next == pending_.end()) return std::nullopt;
        const Pending p = *next;
        pending_.erase(next);
        return p;
    }

    // A short run's projection is biased (an error bar from few batches, heavy tails not yet
    // sampled or just met; on the caustic grid path's projection from 0.1 s is 3.3 times its
    // projection from 3 s, ir's 1.1 times), so a pilot is weighed against the running method's
    // projection when that one had run as long, and the ratio scales the running method's
    // projection now.
    bool takesOver(GridMethod method, const GridResult& pilot, double pilotNeeds, const Opponent& o) {
        const std::string name = gridMethodName(method);
        if (pilot.converged) {
            pilots_.push_back(name + " reached the target in its pilot");
            return true;
        }
        if (!std::isfinite(pilotNeeds)) {
            noMeasure(method, o.budgetSeconds, pilot.seconds);
            return false;
        }
        const History& h = *o.history;
        const auto then = std::ranges::find_if(h, [&](const auto& e) { return e.first >= pilot.seconds; });
        const double needs = pilotNeeds * o.needsSeconds / (then != h.end() ? then->second : h.back().second);
        pilots_.push_back(name + " " + secondsText(needs) + " (" + secondsText(o.needsSeconds) + ")");
        const auto first = std::ranges::find(measured_, method, &Measure::first);  // its first measure, if any
        const bool second = first != measured_.end() && std::ranges::count(measured_, method, &Measure::first) == 1;
        measured_.emplace_back(method, needs);
        if (!challengerTakesOver({needs, pilot.seconds}, {o.needsSeconds, o.ranSeconds}, limit_ - secondsSince(begin_))) {
            const bool close = o.shortPilot && needs - pilot.seconds < kCloseRatio * (o.needsSeconds - o.ranSeconds);
            const bool disagrees = second && std::max(needs, first->second) > kDisagreementRatio * std::min(needs, first->second);
            if (close || disagrees) {
                pilots_.back() += ", again later";
                pilotAgainNext(method);
            } else {
                beaten_.push_back({method, {needs, pilot.seconds}});
            }
            return false;
        }
        pilots_.back() += ", took over";
        return true;
    }

    // A beaten method goes back to the front of the pending list, to be piloted again, once what
    // its pilot showed would take over from where the running method, `ran` seconds in, stands
    // now: the projection that beat it was too low (heavy tails met late: on the glass cube ir's
    // went from 0.4 s to 14 s after beating path's short pilot, which projected 4.8 s).
    void revisitBeaten(double ran, double needs) {
        for (auto b = beaten_.begin(); b != beaten_.end();) {
            if (!challengerTakesOver(b->stand, {needs, ran}, limit_ - secondsSince(begin_))) {
                ++b;
                continue;
            }
            pilotAgainNext(b->method);
            b = beaten_.erase(b);
        }
    }

    // A measured method to the front of the pending list, for a pilot at the full share.
    void pilotAgainNext(GridMethod method) { pending_.insert(pending_.begin(), {method, 0.0, false}); }

    void noMeasure(GridMethod method, double budgetSeconds, double spent) {
        pilots_.push_back(std::string(gridMethodName(method)) + " none within " + formatDuration(spent));
        pending_.push_back({method, budgetSeconds, false});
    }

    // "started with ir; pilots (...): path 8 (28), took over, ...; not measured: ...; ran path; ..."
    std::string line(GridMethod running) const {
        std::string s = "started with " + std::string(gridMethodName(first_));
        if (!pilots_.empty()) {
            s += "; pilots (projected seconds to the target, the running method's in brackets):";
            for (size_t i = 0; i < pilots_.size(); ++i) s += (i ? ", " : " ") + pilots_[i];
        }
        std::string unmeasured;
        for (const Pending& p : pending_)
            if (std::ranges::find(measured_, p.method, &Measure::first) == measured_.end())
                unmeasured += (unmeasured.empty() ? " " : ", ") + std::string(gridMethodName(p.method));
        if (!unmeasured.empty()) s += "; not measured:" + unmeasured;
        return s + "; ran " + gridMethodName(running) + "; pilots took " + formatDuration(pilotSeconds_);
    }

    const RenderScene& scene_;
    const std::vector<V3d>& points_;
    const V3d normal_;
    const GridSettings& settings_;
    TaskContext& ctx_;
    const std::function<void(const GridResult&)>& onPass_;
    const Clock::time_point begin_ = Clock::now();
    const double limit_;  // seconds (infinite: none)
    GridMethod first_;
    // The methods to pilot, in order; each is in it at most once (a pilot takes its method off;
    // one that measured nothing, a short pilot, and revisitBeaten put it back).
    std::vector<Pending> pending_;
    // The methods beaten in a pilot, and where each stood at its pilot's end.
    struct Beaten {
        GridMethod method;
        MethodStand stand;
    };
    std::vector<Beaten> beaten_;
    using Measure = std::pair<GridMethod, double>;  // a pilot's method and projection (seconds)
    std::vector<Measure> measured_;                 // every pilot's that measured, in order
    std::vector<std::string> pilots_;  // what each pilot measured, in order
    double pilotSeconds_ = 0;          // the pilots' own time, up to their decisions
    int pilotCount_ = 0;
};

}  // namespace

bool challengerTakesOver(const MethodStand& challenger, const MethodStand& running, double secondsLeft) {
    if (!std::isfinite(challenger.needsSeconds)) return false;
    const double challengerRest = std::max(0.0, challenger.needsSeconds - challenger.ranSeconds);
    const double runningRest = std::max(0.0, running.needsSeconds - running.ranSeconds);
    if (std::min(challengerRest, runningRest) <= secondsLeft) return challengerRest < kTakeOverRatio * runningRest;
    // Neither reaches the target within the limit: the variance at the limit, as 1 / time.
    return challenger.needsSeconds / (challenger.ranSeconds + secondsLeft) <
           kTakeOverRatio * running.needsSeconds / (running.ranSeconds + secondsLeft);
}

double projectedGridSeconds(const GridResult& r, double ran, GridMethod method, const GridSettings& settings) {
    if (r.passes < (estimatesPoints(method) ? std::max(2, settings.minPasses) : 1) || !std::isfinite(r.maxRelativeError) ||
        !(ran > 0) || !(settings.targetRelativeError > 0))
        return kInfinity;
    const double ratio = r.maxRelativeError / settings.targetRelativeError;
    const double prepared = std::clamp(r.prepareSeconds, 0.0, ran);
    return prepared + (ran - prepared) * ratio * ratio;
}

GridResult computeGridByAuto(const RenderScene& scene, const std::vector<V3d>& points, const V3d& normal,
                             const GridSettings& settings, TaskContext& ctx,
                             const std::function<void(const GridResult&)>& onPass, GridResult start) {
    return AutoGrid(scene, points, normal, settings, ctx, onPass, start.litThroughGlass > 0).compute();
}

}  // namespace lucerna
