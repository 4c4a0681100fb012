#pragma once
// When `auto` gives passes to a method that its gains would not give them to
// (measured_auto_backend.cpp): a trial. A method whose cost is under a share of the
// costliest's in the image is left out of it, and its gain is discounted by how far along it
// is, so that a pilot's optimistic estimate draws no time that the image then leaves out; in
// the image, the leading gain takes every pass. Both starve a method whose short run
// understates it; a trial gives it passes until a measure has seen it at a greater length.

#include <string_view>

namespace lucerna {

// How close to the leading method's gain a method must come to take a trial, kCloseTrials
// times; after those, by how much it must lead. Each trial doubles the method's cost, so where
// it is truly behind the close ones take it to about 2^kCloseTrials times its cost when the
// first began.
inline constexpr double kTrialMargin = 1.3;
inline constexpr int kCloseTrials = 3;
// The first trial's margin: a pilot of one or two passes a replica reads a method whose passes
// are heavy-tailed by one draw. On the daylit office one pass of mir's read a relmse of 0.25 to
// 1.51 over seeds 1 to 11, and auto's seed 2 met one of 3.36 in its pilot: mir's gain read 0.55
// of ir's, ir carried, and mir alone is 1.4 times better there.
inline constexpr double kFirstTrialMargin = 2;

// Whether a gain leads the leading one by kTrialMargin; a trial taken without that is a close one.
inline bool leadsByMargin(double gain, double leadingGain) { return gain > kTrialMargin * leadingGain; }

// The methods whose error per unit of cost a short run does not flatter: path, whose passes are
// independent and whose Sobol sequence's error falls faster than 1 / time at first, but not
// where mirrors or glass make caustics (`caustics`), which it finds only by hitting an emitter
// and a short run does not show; and mir, whose chain and normalisation (Pc, its samples
// balanced as the passes go) settle, so that its error too falls faster than 1 / time at first.
// Not the chains of mlt and cmlt, whose error per unit of cost grows as they meet their rare
// paths, nor bdpt, whose light paths meet their heavy tails late on caustics, nor ir, whose
// passes are independent VPL sets.
bool shortRunIsFair(std::string_view method, bool caustics);

// What the trial rule reads of one method and of the render.
struct TrialQuestion {
    std::string_view method;
    double gain = 0;          // its relmse taken off per unit of cost, undiscounted
    double leadingGain = 0;   // the largest gain after the discount (the leading method's)
    double cost = 0;          // its cost so far (seconds or rays)
    double inImageCost = 0;   // the cost at which it would be in the image
    double leadingCost = 0;   // the leading method's cost
    double costLeft = 0;      // the budget left (open-ended: as long again as so far)
    int closeTrials = 0;      // the trials it has taken without leading by kTrialMargin
    bool caustics = false;    // the scene has mirrors or glass (shortRunIsFair)
};

// True when the method takes the passes: its short run does not flatter it; it is out of the
// image, or in it with less cost than the leading method; its gain is within kTrialMargin of the
// leading gain (kFirstTrialMargin for its first trial; it must lead by kTrialMargin once it has
// taken kCloseTrials such trials, so that a method close to the leader but behind does not go in
// and out for ever, its passes left out when the render ends); and the budget left can bring it
// into the image.
bool takesTrial(const TrialQuestion& q);

}  // namespace lucerna
