#pragma once
// A grid's `--method auto` as a measurement (issue 38). The grid starts with the method that is
// cheapest to start (ir; bdpt where a lamp reaches some point only through glass) and, between its
// passes, short pilots of the other methods that can carry the scene's light to the points (path,
// ir, bdpt, mir, mlt, cmlt; bdpt, mlt and cmlt through glass) measure each one's seconds to the
// grid's error target. A method whose pilot shows it would reach the target clearly sooner than
// the running one takes over: its pilot goes on to the end, the running one's passes dropped
// (kept where both are path or ir, below).
// One that lost is piloted again once the running method's projection has grown past what would
// have let it take over (heavy tails met late).
//
// A pilot costs a share of the running method's projected remaining time (path's and ir's first
// a smaller share, grid_auto.cpp): a grid that the first method finishes in a second is not held
// up by measuring five others, and a slow grid gives long enough pilots for the methods that
// prepare (mlt's and cmlt's bootstrap counts in the pilot) to show their pace. The methods keep
// their samples in different forms (points, replicas); path's and ir's runs, pilots included,
// are combined point by point (grid_combination.h), the others' pilots that do not take over are
// lost.

#include "render/photometry/grid_calculation.h"

namespace lucerna {

// The grid on `points` by auto; `start` is the grid's empty result (points inside geometry and lit
// through glass marked). The result's method is the one that ran to the end, its autoMeasured
// the pilots' line, its seconds the whole time, pilots included. Cancelled: the running method's
// result so far.
GridResult computeGridByAuto(const RenderScene& scene, const std::vector<V3d>& points, const V3d& normal,
                             const GridSettings& settings, TaskContext& ctx,
                             const std::function<void(const GridResult&)>& onPass, GridResult start);

// A method's projected seconds to the grid's target from its start, `ran` seconds of its own so
// far: its preparation (r.prepareSeconds), then its passes' time scaled by (error / target)^2,
// error bars shrinking as 1 / sqrt(time). Preparation does not shrink the error (the corridor of
// the many-luminaire family: bdpt's pilot, its eight replicas' preparation scaled too, projected
// 49 s, without 25 s; bdpt alone reaches the target in 10 s). Infinite while the error bars are
// not to be trusted (path and ir before settings.minPasses passes, at least 2; the replicas'
// methods before their first).
double projectedGridSeconds(const GridResult& r, double ran, GridMethod method, const GridSettings& settings);

// The length of a pilot now, in seconds: a share of the running method's projected rest
// (`restSeconds`), within what all pilots together may still take (a tenth of its projected
// total `needsSeconds`, less the `pilotsSeconds` they took). Path's or ir's first pilot
// (`shortPilot`) is a hundredth of the rest, at least 0.01 s, and may take up to half the rest
// where the running method is path or ir too (`againstPathOrIr`): one that loses costs that
// hundredth, and on a grid done in a tenth of a second a twentieth of the rest would be shorter
// than the shortest pilot. Any other pilot is a twentieth of the rest. A pilot shorter than its
// method's shortest (0.01 s for path and ir, 0.05 s for the others) is not run.
double pilotLengthSeconds(bool shortPilot, bool againstPathOrIr, double restSeconds, double needsSeconds,
                          double pilotsSeconds);

// Where a method stands: the seconds it needs from its start to reach the grid's target
// (projected: seconds x (error / target)^2, error bars shrinking as 1 / sqrt(time)), and the
// seconds it has run.
struct MethodStand {
    double needsSeconds, ranSeconds;
};

// Whether a piloted method, which goes on from its pilot, replaces the running one, with
// `secondsLeft` of the time limit (infinite: none): when the rest it needs is under `margin`
// times the running one's rest, or, where neither finishes within the limit, when it would end
// with under `margin` times the running one's variance. The margin: pilots are short and their
// error bars noisy, and where the running method's passes are lost by the change (0.7) more so
// than where they stay in the result (path and ir, combined: 0.85).
bool challengerTakesOver(const MethodStand& challenger, const MethodStand& running, double secondsLeft, double margin = 0.7);

// Whether a pilot that did not take over runs on, twice as long, with `restSeconds` of its own
// left to the target against the running method's `runningRestSeconds`: path's or ir's first,
// short pilot (`shortPilot`) when its rest is under 3 times the running one's; any other when it
// is ahead (its rest the shorter, though not by the take-over margin: a short run's projection is
// noisy), or when its rest is under twice the running one's and its projection is still falling
// fast (`falling`: a heavy tail met early, being diluted).
bool pilotRunsOn(bool shortPilot, bool falling, double restSeconds, double runningRestSeconds);

}  // namespace lucerna
