#pragma once
// `--backend mir`: Metropolis instant radiosity (Segovia, Iehl & Peroche 2007).
//
// Each pass, for the film half h = pass % 2 (each half has its own chain and its own Pc, so the
// two halves are independent and their difference is an honest error estimate):
//   1. sample paths:  n steps of half h's multiple-try Metropolis chain over complete
//      camera-to-light paths in primary sample space (metropolis.h, mir_path.h), density
//      proportional to their clamped image contribution; the light-side half of the current path
//      after each step is a path VPL;
//   2. merge:  consecutive path VPLs at the same place (a rejected step repeats the path) form one
//      geometric VPL i with count k_i; its share of the power reaching the camera is
//      P_i = k_i Pc / n;
//   3. refine Pc:  Pc = the mean of f over every path the chain evaluated at an independent
//      uniform point (start candidates, large-step trials and references, and pcSamplesPerPass
//      extra samples a pass), accumulated over all of half h's passes so far: an unbiased,
//      ever-refined estimate of the integral of f;
//   4. normalise:  each geometric VPL rendered with its own (unnormalised) power has the image
//      contribution P'_i (mean over the image of the luminance it brings, measured on the
//      gather's own camera samples); it is scaled by P_i / P'_i, so that it brings exactly P_i;
//   5. gather:  one camera sample per pixel, as `ir` (vpl_gatherer.h): emitters, direct light,
//      the scaled VPLs with the clamped geometric term, and the clamped-away residual by short
//      path-traced paths.
// The VPLs only stand for the CLAMPED indirect term; the residual is estimated independently of
// them, so nothing is counted twice: P_i and P'_i are both measured on the clamped term.

#include "render/backend/backend.h"

namespace lucerna {

std::unique_ptr<ProgressiveBackend> makeMirBackend(SceneSnapshot scene, const RenderSettings& settings);

}  // namespace lucerna
