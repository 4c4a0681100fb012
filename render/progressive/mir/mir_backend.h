#pragma once
// `--backend mir`: Metropolis instant radiosity (Segovia, Iehl & Peroche 2007).
//
// Per film half, a MirChain (render/vpl/mir_chain.h) with its own importance points, chain and
// Pc, so that the two halves are independent and their difference is an honest error estimate.
// Each pass, for the half h = pass % 2:
//   1. sample VPLs:  n steps of half h's chain, merged into weighted geometric VPLs;
//   2. gather:  one camera sample per pixel, as `ir` (vpl_gatherer.h): emitters, direct light,
//      the VPLs with the clamped geometric term, and the clamped-away residual by short
//      path-traced paths.
// The importance is measured on fixed camera points rather than on a camera point drawn with each
// state, as it was until issue 21: then the target was an unbiased but noisy estimate of a VPL's
// image contribution, a chain that drew a lucky point (a VPL right beside it) stayed there for
// many steps, and each VPL's image contribution had to be measured and divided by, a ratio
// estimate with heavy tails (Cornell box, 30 s: relmse 5e-3 to 3e-2 with the seed; now 1.0e-3 to
// 2.0e-3 over 8 seeds, BENCHMARKS.md, "Held-out scene families (issue 21)").
// The VPLs only stand for the CLAMPED indirect term; the residual is estimated independently of
// them, so nothing is counted twice.

#include "render/backend/backend.h"

namespace lucerna {

std::unique_ptr<Backend> makeMirBackend(SceneSnapshot scene, const RenderSettings& settings);

}  // namespace lucerna
