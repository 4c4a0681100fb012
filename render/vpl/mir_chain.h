#pragma once
// The Metropolis instant radiosity chain (Segovia, Iehl & Peroche 2007) that the mir backend runs
// once per film half and the preview once per VPL set: VPLs drawn in proportion to the light they
// bring to the camera, each weighted so that the set estimates the clamped indirect light.
//
// Once, at construction:
//   S:      importance points, camera rays stratified over the image followed to their first
//           diffuse or glossy vertex (mir_path.h, traceImportancePoints);
//   floor:  `defensive` times the mean importance of a vertex of uniformly drawn pilot light
//           paths (not counted in Pc), or 1 where S sees no light at all.
// Each call of sampleVpls(n):
//   1. n steps of a Metropolis chain over light sub-paths in primary sample space (metropolis.h)
//      with the target f(u) = sum_k c_k(u) (mir_path.h, evaluateMirLightPath); after each step a
//      vertex k of the current path is chosen with probability c_k / f, so (u, k) has the
//      density c_k(u) / Pc;
//   2. consecutive equal path VPLs (a rejected step repeats the path) merge into one geometric VPL
//      of count k_i;
//   3. Pc, the mean of f over every evaluation at an independent uniform point (start candidates,
//      large-step trials and references) and of pcSamples cheaper unbiased estimates of f a call
//      (mir_path.h, estimateMirImportance), accumulated over calls. Pc's error is shared by every
//      VPL: in a closed bright room it was the image mean's error (1% after seconds with 256
//      exact samples a call), so the mir backend applies the newest Pc to every pass's VPLs
//      (sampleUnitVpls) and sets pcSamples by the balance of pc_balance.h;
//      VPL i carries its sub-path's power times k_i Pc / (n c_k(u_i)), the importance weight of
//      n draws from c / Pc, never above Pc / (n floor).

#include "render/vpl/metropolis.h"
#include "render/vpl/mir_path.h"

#include <memory>
#include <string>

namespace lucerna {

struct MirChainSettings {
    int tries = 1;                     // multiple-try Metropolis trials per step (1: plain MH)
    float largeStepProbability = 0.3f;
    int startCandidates = 1024;        // uniform candidates the chain starts from (resampling)
    int pcSamples = 4096;              // cheap uniform estimates of f refining Pc at each call
    int pcPointsPerVertex = 4;         // members of S each of them measures a vertex on
    int importancePoints = 64;         // |S|
    float defensive = 0.2f;            // the floor, as a fraction of a vertex's mean importance
    int pilotPaths = 256;              // uniform light paths that set the floor
    int maxSpecularDepth = 16;         // camera bounces through mirrors and glass to x_s
    VplOptions vpl;
};

class MirChain {
public:
    // The lights and the camera are the caller's (the preview's edited copies, or the scene's);
    // maxG is the gatherers' clamp bound.
    MirChain(const RenderScene& scene, const LightSampler& lights, const Sensor& camera,
             const MirChainSettings& settings, float maxG, uint64_t seed);

    // n chain steps: at most n geometric VPLs, powers weighted as above. Empty while the chain has
    // found no light path that reaches S or the floor (a scene whose lights leave no VPL).
    VplSet sampleVpls(int n);
    // As sampleVpls, each power without the factor Pc: a film that keeps these VPLs' light apart
    // and scales it by pc() when read carries the newest Pc into every pass, not the one each
    // pass had (the mean of running means has twice the variance of the last; on a closed
    // sphere of albedo 0.9 Pc's error was nearly all of mir's).
    VplSet sampleUnitVpls(int n);

    double pc() const;
    // Pc's relative variance, Var(Pc) / Pc^2, from the spread of the cheap samples (0 before two).
    double pcRelativeVariance() const;
    // The cheap samples' relative variance each, Var(f) / Pc^2: Pc's after N more is this / N.
    double pcSampleRelativeVariance() const;
    // Rays a cheap sample traces, on average (its light path's, and perVertex to S from each
    // vertex).
    double pcSampleRays() const;
    // The cheap samples each later call draws (settings' pcSamples until set).
    void setPcSamples(int samples) { settings_.pcSamples = std::max(0, samples); }
    double acceptanceRate() const { return mtm_->acceptanceRate(); }
    long long pcSamples() const { return mtm_->uniformCount() + cheapCount_; }
    size_t importancePoints() const { return points_.size(); }
    double floor() const { return floor_; }

private:
    double target(double floor, const std::vector<float>& u, MirPath& path) const;
    double defensiveFloor();

    const RenderScene& scene_;
    const LightSampler& lights_;
    MirChainSettings settings_;
    float maxG_;
    int dimension_;
    std::vector<CameraVertex> points_;
    double floor_ = 1;
    Rng rng_;
    std::unique_ptr<MultipleTryMetropolis<MirPath>> mtm_;
    int chosen_ = -1;  // which vertex of the current path is its path VPL
    double cheapSum_ = 0;  // estimateMirImportance's samples of f
    double cheapSumSquares_ = 0;
    long long cheapCount_ = 0;
    long long cheapVertices_ = 0;
};

}  // namespace lucerna
