#include "render/photometry/grid_auto.h"

#include "core/number_format.h"
#include "core/sub_task.h"
#include "render/photometry/grid_combination.h"

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
// times the running one's) goes on to the full share; one further behind is beaten
// (revisitBeaten).
constexpr double kFirstPointPilotShare = 0.01;
constexpr double kCloseRatio = 3;
// Between path and ir that short first pilot may take up to this share of the running method's
// rest, not kPilotShare (pilotLengthSeconds, grid_auto.h): on the closed room of albedo 0.5 ir
// runs 0.1 s, and path, held to a twentieth, was piloted on 1 of 4 seeds, then took over and
// finished in 0.05 s.
constexpr double kCombinedPilotRestShare = 0.5;
// A pilot at its full share that does not take over goes on, twice as long each time, while all
// pilots together take at most kLongerPilotsShare of the running method's projected total
// (pilotRunsOn, grid_auto.h):
// - where it is ahead of the running method but within the take-over margin: a short pilot's
//   projection is one noisy reading, and a longer one gives a later reading (the room lit from
//   the next one: bdpt's pilots projected 1.4 to 3.6 s against its 1.9 s alone, and one at 2.4 s
//   against path's 3.2 s lost);
// - where its rest is under kCloserRatio times the running method's and its projection is still
//   falling fast (under kFallingRatio times its projection at half the pilot's length: a heavy
//   tail met early, being diluted). Such a method shows its pace only after a while: bdpt in a
//   room lit from the next one projected 3.4 to 6.6 s in its first 0.1 s (one sample's spike),
//   against path's 2.5 to 3, and reaches the target in 1.7 s alone, path in 3.1 s.
constexpr double kCloserRatio = 2;
constexpr double kFallingRatio = 0.75;
constexpr double kLongerPilotsShare = 0.2;
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
// The margin by which a challenger must beat the running method (challengerTakesOver): where
// the running method's passes are dropped, and where both are path or ir, whose runs are
// combined (the corridor of the many-luminaire family: path projected 17 to 22 s against ir's
// 15 to 26 s and never took over; ir ran to the 30 s limit, path alone takes 16 to 19 s).
constexpr double kTakeOverRatio = 0.7;
constexpr double kCombinedTakeOverRatio = 0.85;

double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
std::string secondsText(double s) { return std::isfinite(s) ? formatNumber(s, 2) : "-"; }

// The methods auto may run, the cheapest to start first (the first runs from the start).
std::vector<GridMethod> candidates(bool litThroughGlass) {
    if (litThroughGlass) return {GridMethod::Bdpt, GridMethod::Mlt, GridMethod::Cmlt};
    return {GridMethod::Vpl, GridMethod::Path, GridMethod::Bdpt, GridMethod::Mir, GridMethod::Mlt, GridMethod::Cmlt};
}

// Path and ir estimate each point pass by pass; the other methods render replicas.
bool estimatesPoints(GridMethod m) { return m == GridMethod::Path || m == GridMethod::Vpl; }

double takeOverMargin(GridMethod challenger, GridMethod running) {
    return estimatesPoints(challenger) && estimatesPoints(running) ? kCombinedTakeOverRatio : kTakeOverRatio;
}

double shortestPilot(GridMethod m) { return estimatesPoints(m) ? kShortestPointPilotSeconds : kShortestPilotSeconds; }


// The running method's projections as it ran: (its own seconds, projected seconds).
using History = std::vector<std::pair<double, double>>;

// What a pilot is weighed against: the running method's history and where it stands now.
struct Opponent {
    GridMethod method;
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
        GridResult latest;  // path's and ir's: in the combination of the runs nested in this one
        const LiveRun live(*this, estimatesPoints(method) ? &latest : nullptr);
        GridResult last = computeGridIlluminance(scene_, points_, normal_, own, task.context(), [&](const GridResult& r) {
            if (ctx_.isCancelled() || overtaken || lost) return;
            const double ran = r.seconds - pilotsWithin;
            const double needs = projectedGridSeconds(r, ran, method, settings_);
            GridResult shown = combined(r, method);
            // Reached by the combination, not by r alone: r's method stops here.
            const bool done = shown.converged && !r.converged;
            if (done) task.cancel();
            if (piloting) {
                if (std::isfinite(needs)) history.emplace_back(ran, needs);
                if (ran < opponent->budgetSeconds && !shown.converged) return;
                const Verdict v = weigh(method, r, shown.converged, needs, history, *opponent);
                if (v == Verdict::Longer) {
                    opponent->budgetSeconds = longerPilot(ran, *opponent);
                    opponent->shortPilot = false;
                    task.setDeadline(kPilotOverrun * (opponent->budgetSeconds - ran) + kPilotGraceSeconds);
                    return;
                }
                piloting = false;
                pilotSeconds_ += ran;
                if (v == Verdict::Lost) {
                    if (estimatesPoints(method)) banked_.push_back(r);
                    lost = true;
                    task.cancel();
                    return;
                }
                task.setDeadline(kInfinity);
            }
            ctx_.setProgress(task.context().progress());
            if (onPass_) {
                shown.autoMeasured = line(method);
                onPass_(shown);
            }
            latest = r;
            if (!std::isfinite(needs) || shown.converged) return;
            if (history.empty() || history.back().first < ran) history.emplace_back(ran, needs);
            revisitBeaten(method, ran, needs);
            const auto pilotStart = Clock::now();
            const std::optional<Pending> challenger = nextPilot(method, ran, needs);
            if (!challenger) return;
            std::optional<GridResult> won = run(challenger->method, Opponent{method, budget(method, ran, needs, *challenger),
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
        GridResult result = combined(last, method);
        result.method = method;
        return result;
    }

    // A run of path or ir in progress: its latest result is in the combination of the runs
    // nested in it (pilots between its passes, and the one that takes over from it).
    class LiveRun {
    public:
        LiveRun(AutoGrid& grid, const GridResult* latest) : grid_(grid), latest_(latest) {
            if (latest_) grid_.live_.push_back(latest_);
        }
        ~LiveRun() {
            if (latest_) grid_.live_.pop_back();
        }
        LiveRun(const LiveRun&) = delete;
        LiveRun& operator=(const LiveRun&) = delete;

    private:
        AutoGrid& grid_;
        const GridResult* latest_;
    };

    // r, of `method`, combined with every other run of path and ir so far (grid_combination.h):
    // the pilots that lost, and the runs this one is nested in. r alone for the other methods,
    // whose error bars come from a few replicas.
    GridResult combined(const GridResult& r, GridMethod method) {
        if (!estimatesPoints(method) || r.passes < kCombinedMinPasses) {
            combinedParts_ = 0;
            return r;
        }
        std::vector<const GridResult*> parts{&r};
        for (const GridResult& b : banked_)
            if (b.passes >= kCombinedMinPasses) parts.push_back(&b);
        for (size_t k = 0; k + 1 < live_.size(); ++k)  // the last is r's run's
            if (live_[k]->passes >= kCombinedMinPasses) parts.push_back(live_[k]);
        combinedParts_ = int(parts.size());
        return parts.size() == 1 ? r : combineGridResults(parts, settings_);
    }

    // The length of p's pilot now (pilotLengthSeconds); it waits until the running method has
    // run as long, so that the two are weighed at equal times (weigh).
    double budget(GridMethod running, double ran, double needs, const Pending& p) const {
        const double rest = std::min(needs - ran, limit_ - secondsSince(begin_));
        return pilotLengthSeconds(p.shortPilot, estimatesPoints(running), rest, needs, pilotSeconds_);
    }

    // The next method to pilot between the running method's passes, taken off the pending list;
    // nothing when no pilot is worth its cost now.
    std::optional<Pending> nextPilot(GridMethod running, double ran, double needs) {
        const auto next = std::ranges::find_if(pending_, [&](const Pending& p) {
            const double b = budget(running, ran, needs, p);
            return ran >= b &&
                   b >= std::max(shortestPilot(p.method), kRetryFactor * p.triedSeconds);
        });
        if (next == pending_.end()) return std::nullopt;
        const Pending p = *next;
        pending_.erase(next);
        return p;
    }

    // A pilot's verdict: it takes over, it runs on (longerPilot), or it lost.
    enum class Verdict { TakesOver, Longer, Lost };

    // A short run's projection is biased (an error bar from few batches, heavy tails not yet
    // sampled or just met; on the caustic grid path's projection from 0.1 s is 3.3 times its
    // projection from 3 s, ir's 1.1 times), so a pilot is weighed against the running method's
    // projection when that one had run as long, and the ratio scales the running method's
    // projection now.
    Verdict weigh(GridMethod method, const GridResult& pilot, bool converged, double pilotNeeds, const History& own,
                  const Opponent& o) {
        const std::string name = gridMethodName(method);
        if (converged) {
            pilots_.push_back(name + " reached the target in its pilot");
            return Verdict::TakesOver;
        }
        if (!std::isfinite(pilotNeeds)) {
            noMeasure(method, o.budgetSeconds, pilot.seconds);
            return Verdict::Lost;
        }
        const History& h = *o.history;
        const auto then = std::ranges::find_if(h, [&](const auto& e) { return e.first >= pilot.seconds; });
        const double needs = pilotNeeds * o.needsSeconds / (then != h.end() ? then->second : h.back().second);
        pilots_.push_back(name + " " + secondsText(needs) + " (" + secondsText(o.needsSeconds) + ")");
        if (challengerTakesOver({needs, pilot.seconds}, {o.needsSeconds, o.ranSeconds}, limit_ - secondsSince(begin_),
                                takeOverMargin(method, o.method))) {
            pilots_.back() += ", took over";
            return Verdict::TakesOver;
        }
        const double rest = needs - pilot.seconds, runningRest = o.needsSeconds - o.ranSeconds;
        // Its projection at half its time so far: one falling fast (a heavy tail met early being
        // diluted) is not to be trusted yet.
        const auto half = std::ranges::find_if(own, [&](const auto& e) { return e.first >= 0.5 * pilot.seconds; });
        const bool falling = half != own.end() && pilotNeeds < kFallingRatio * half->second;
        if (pilotRunsOn(o.shortPilot, falling, rest, runningRest) && longerPilot(pilot.seconds, o) > pilot.seconds) {
            pilots_.back() += ", longer";
            return Verdict::Longer;
        }
        const auto first = std::ranges::find(measured_, method, &Measure::first);  // its first measure, if any
        const bool second = first != measured_.end() && std::ranges::count(measured_, method, &Measure::first) == 1;
        const double firstNeeds = second ? first->second : needs;  // read before measured_ grows
        measured_.emplace_back(method, needs);
        if (second && std::max(needs, firstNeeds) > kDisagreementRatio * std::min(needs, firstNeeds)) {
            pilots_.back() += ", again later";
            pilotAgainNext(method);
        } else {
            beaten_.push_back({method, {needs, pilot.seconds}});
        }
        return Verdict::Lost;
    }

    // The length a close pilot that has run `ran` seconds goes on to: twice as long, at least the
    // full share of the running method's rest (path's and ir's first pilot), while all pilots
    // stay within kLongerPilotsShare of its projected total and the time limit; `ran` where
    // that allows no more.
    double longerPilot(double ran, const Opponent& o) const {
        const double longer = std::max(2 * ran, kPilotShare * (o.needsSeconds - o.ranSeconds));
        const double allowed = std::min(kLongerPilotsShare * o.needsSeconds - pilotSeconds_, limit_ - secondsSince(begin_) + ran);
        return longer <= allowed ? longer : ran;
    }

    // A beaten method goes back to the front of the pending list, to be piloted again, once what
    // its pilot showed would take over from where the running method, `ran` seconds in, stands
    // now: the projection that beat it was too low (heavy tails met late: on the glass cube ir's
    // went from 0.4 s to 14 s after beating path's short pilot, which projected 4.8 s).
    void revisitBeaten(GridMethod running, double ran, double needs) {
        for (auto b = beaten_.begin(); b != beaten_.end();) {
            if (!challengerTakesOver(b->stand, {needs, ran}, limit_ - secondsSince(begin_), takeOverMargin(b->method, running))) {
                ++b;
                continue;
            }
            pilotAgainNext(b->method);
            b = beaten_.erase(b);
        }
    }

    // A measured method to the front of the pending list, for a pilot at the full share.
    void pilotAgainNext(GridMethod method) { pending_.insert(pending_.begin(), {method, 0.0, false}); }

    // A pilot that measured nothing is tried again, four times as long (kRetryFactor): path's or
    // ir's next, since they start at once and theirs was only shorter than their first passes
    // (the glass partition office: path's 0.01 s, under its 8 passes, went to the back, bdpt's
    // and mir's pilots took the pilots' share, and ir ran where path is the faster); the others'
    // after the rest, their preparation being what outlasted the pilot.
    void noMeasure(GridMethod method, double budgetSeconds, double spent) {
        pilots_.push_back(std::string(gridMethodName(method)) + " none within " + formatDuration(spent));
        pending_.insert(estimatesPoints(method) ? pending_.begin() : pending_.end(), {method, budgetSeconds, false});
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
        s += "; ran " + std::string(gridMethodName(running));
        if (combinedParts_ > 1)
            s += ", its values combined with " + std::to_string(combinedParts_ - 1) + (combinedParts_ == 2 ? " other run" : " other runs") +
                 " of path and ir";
        return s + "; pilots took " + formatDuration(pilotSeconds_);
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
    // Path's and ir's results: of the pilots that lost, and of the runs in progress (LiveRun).
    std::vector<GridResult> banked_;
    std::vector<const GridResult*> live_;
    int combinedParts_ = 0;  // the runs in the last combination
    double pilotSeconds_ = 0;          // the pilots' own time, up to their decisions
    int pilotCount_ = 0;
};

}  // namespace

bool pilotRunsOn(bool shortPilot, bool falling, double restSeconds, double runningRestSeconds) {
    if (shortPilot) return restSeconds < kCloseRatio * runningRestSeconds;
    return restSeconds < runningRestSeconds || (falling && restSeconds < kCloserRatio * runningRestSeconds);
}

bool challengerTakesOver(const MethodStand& challenger, const MethodStand& running, double secondsLeft, double margin) {
    if (!std::isfinite(challenger.needsSeconds)) return false;
    const double challengerRest = std::max(0.0, challenger.needsSeconds - challenger.ranSeconds);
    const double runningRest = std::max(0.0, running.needsSeconds - running.ranSeconds);
    if (std::min(challengerRest, runningRest) <= secondsLeft) return challengerRest < margin * runningRest;
    // Neither reaches the target within the limit: the variance at the limit, as 1 / time.
    return challenger.needsSeconds / (challenger.ranSeconds + secondsLeft) <
           margin * running.needsSeconds / (running.ranSeconds + secondsLeft);
}

double pilotLengthSeconds(bool shortPilot, bool againstPathOrIr, double restSeconds, double needsSeconds,
                          double pilotsSeconds) {
    const double share =
        shortPilot ? std::min(std::max(kFirstPointPilotShare * restSeconds, kShortestPointPilotSeconds),
                              (againstPathOrIr ? kCombinedPilotRestShare : kPilotShare) * restSeconds)
                   : kPilotShare * restSeconds;
    return std::min(share, kPilotsShare * needsSeconds - pilotsSeconds);
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
