#include "render/progressive/cmlt/cmlt_chain.h"

#include "render/trace/render_scene.h"

#include <algorithm>

namespace lucerna {

CmltChain::CmltChain(const RenderScene& scene, const CmltSettings& settings, uint64_t bootstrapSeed)
    : MltChain(scene, settings.mlt, bootstrapSeed, settings.pathLensSteps > 0), scene_(scene), settings_(settings),
      densities_(scene), lensPath_(scene, densities_), causticPath_(scene, densities_) {}

int CmltChain::run(int steps, double scale, std::vector<FilmSplat>& out) {
    int made = 0;
    while (made < steps) {
        const long long acceptedBefore = counters_.accepted;
        mutate(scale, out);  // step 1: a new seed
        ++made;
        // The tracer holds the current state's light subpath if the seed's proposal was
        // accepted, and after any lens step (the light stream does not move).
        bool lightSubpathCurrent = counters_.accepted > acceptedBefore;
        for (int i = 0; i < settings_.lensSteps && current().f > 0; ++i) {
            made += lensStep(scale, lightSubpathCurrent, out);
            lightSubpathCurrent = true;
        }
        for (int i = 0; i < settings_.causticSteps && current().f > 0; ++i) made += causticStep(scale, out);
        if (settings_.pathLensSteps > 0 && current().f > 0) made += pathLensSubChain(scale, out);
    }
    return made;
}

void CmltChain::prepareCandidates(int p) {
    candidates_.resize(size_t(p));
    for (PathContribution& c : candidates_) c.recordPaths = current().recordPaths;  // any may become the state
}

void CmltChain::proposeRasters(const V2f& x, int p) {
    prepareCandidates(p);
    rasters_.resize(size_t(p));
    rays_.resize(size_t(p));
    hits_.resize(size_t(p));
    const float w = float(camera_.width()), h = float(camera_.height());
    for (int i = 0; i < p; ++i) {
        rasters_[size_t(i)] = perturbRaster(x, settings_.sigmaPixels, w, h, sampler().rng());
        rays_[size_t(i)] = camera_.ray(rasters_[size_t(i)].x, rasters_[size_t(i)].y);
    }
    scene_.intersectCoherent(rays_, hits_);  // the candidates' camera rays as one packet
}

LensMove CmltChain::depositAndChoose(const PathContribution& cur, double scale, std::vector<FilmSplat>& out) {
    double keep = 0;  // the competitor's total weight
    candidateF_.resize(candidates_.size());
    for (size_t i = 0; i < candidates_.size(); ++i) {
        const PathContribution& c = candidates_[i];
        const double a = std::min(1.0, c.f / cur.f);
        if (c.f > 0) depositContribution(c, scale * a / c.f, out);
        keep += 1.0 - a;
        candidateF_[i] = c.f;
    }
    depositContribution(cur, scale * keep / cur.f, out);
    return chooseLensMove(candidateF_, cur.f, sampler().rng());
}

int CmltChain::lensStep(double scale, bool lightSubpathCurrent, std::vector<FilmSplat>& out) {
    PssSampler& sampler = this->sampler();
    const float w = float(camera_.width()), h = float(camera_.height());
    // The current raster point, from the state's first two numbers.
    sampler.startReplay();
    const V2f x = rasterPoint(camera_, sampler.next2D());

    const int p = std::max(1, settings_.tries);
    proposeRasters(x, p);
    for (int i = 0; i < p; ++i) {
        sampler.startReplay();
        // Only the camera side moves: the current state's light subpath serves every candidate
        // (traced by the first unless the tracer holds it already).
        evaluatePathAt(tracer(), rasters_[size_t(i)].x, rasters_[size_t(i)].y, hits_[size_t(i)],
                       i > 0 || lightSubpathCurrent, sampler, candidates_[size_t(i)]);
    }

    const LensMove move = depositAndChoose(current(), scale, out);  // step 3
    countSteps(cmltCounters_.lensSteps, p);
    if (move.accepted) {
        const V2f& r = rasters_[size_t(move.candidate)];
        sampler.setCoordinate(SampleStream::Camera, 0, r.x / w);
        sampler.setCoordinate(SampleStream::Camera, 1, r.y / h);
        current() = candidates_[size_t(move.candidate)];
        countAccepted(cmltCounters_.lensAccepted, p);
    }
    return p;
}

int CmltChain::causticStep(double scale, std::vector<FilmSplat>& out) {
    PssSampler& sampler = this->sampler();
    // The current state's camera subpath, traced once for every candidate.
    sampler.startReplay();
    const V2f r = rasterPoint(camera_, sampler.next2D());
    tracer().traceCameraSubpathOnly(r.x, r.y, sampler);

    const int p = std::max(1, settings_.tries);
    causticTries_.start(sampler, p, sampler.rng());
    prepareCandidates(p);
    for (int i = 0; i < p; ++i)
        evaluateLightSideAt(tracer(), r.x, r.y, causticTries_.candidate(i), candidates_[size_t(i)]);

    const LensMove move = depositAndChoose(current(), scale, out);
    counters_.steps += p;
    counters_.causticSteps += p;
    if (move.accepted) {
        sampler = causticTries_.candidate(move.candidate);
        sampler.accept();
        current() = candidates_[size_t(move.candidate)];
        counters_.accepted += p;
        counters_.causticAccepted += p;
    }
    return p;
}

namespace {
// The least luminance a path-space contribution F may have. F's scale is free (only ratios and
// the colour matter) and far from the image's: a path through many glass faces carries their
// Fresnel factors, down to 1e-45 on the caustic scene, where a float keeps one bit of a colour and
// 1 / F overflows. Below this the path counts as outside its perturbation's class (F = 0): its
// candidates are rejected, and a seed there keeps its steps in place, which keeps the density.
constexpr float kMinPathContribution = 1e-30f;

// One path of the sample, chosen in proportion to its contribution; nullptr when none has
// kMinPathContribution (or none is recorded: light tracing alone).
const StrategyRecord* choosePath(const SampledPaths& paths, Rng& rng) {
    const auto weight = [](const StrategyRecord& r) {
        const float l = luminance(r.weighted);
        return l >= kMinPathContribution ? double(l) : 0.0;
    };
    double total = 0;
    for (const StrategyRecord& r : paths.strategies) total += weight(r);
    if (!(total > 0)) return nullptr;
    double pick = rng.nextDouble() * total;
    const StrategyRecord* chosen = nullptr;
    for (const StrategyRecord& r : paths.strategies) {
        const double w = weight(r);
        if (!(w > 0)) continue;
        chosen = &r;  // the last with weight, should rounding leave pick >= 0
        if ((pick -= w) < 0) break;
    }
    return chosen;
}

// A path's contribution as a deposit at its raster point (x, y).
void asDeposit(const Sensor& camera, float x, float y, const Rgb& c, PathContribution& out) {
    out.deposits.clear();
    const float f = luminance(c);
    out.f = f >= kMinPathContribution && isFinite(c) ? f : 0.0f;
    if (out.f > 0)
        out.deposits.push_back({std::clamp(int(x), 0, camera.width() - 1), std::clamp(int(y), 0, camera.height() - 1), c});
}
}  // namespace

int CmltChain::pathLensSubChain(double scale, std::vector<FilmSplat>& out) {
    const int p = std::max(1, settings_.tries), made = settings_.pathLensSteps * p;
    const StrategyRecord* seed = choosePath(current().paths, sampler().rng());
    if (seed && !seed->sensorNextEvent) {
        current().paths.path(*seed, pathVertices_);
        if (lensSubChain(*seed, p, scale, out)) {
            countSteps(cmltCounters_.pathLensSteps, made);
            return made;
        }
        if (causticSubChain(p, scale, out)) {
            countSteps(cmltCounters_.pathCausticSteps, made);
            return made;
        }
    }
    // No perturbation moves this path: every step stays on it (on the whole sample where no
    // path of it can be chosen), so that every seed weighs the same.
    countSteps(cmltCounters_.pathStillSteps, made);
    if (seed) {
        asDeposit(camera_, seed->rasterX, seed->rasterY, seed->weighted, lensState_);
        depositContribution(lensState_, scale * made / lensState_.f, out);
    } else {
        depositContribution(current(), scale * made / current().f, out);
    }
    return made;
}

void CmltChain::countSteps(long long& kernelSteps, long long steps) {
    counters_.steps += steps;
    counters_.variantSteps += steps;
    kernelSteps += steps;
}

void CmltChain::countAccepted(long long& kernelAccepted, long long accepted) {
    counters_.accepted += accepted;
    counters_.variantAccepted += accepted;
    kernelAccepted += accepted;
}

std::map<std::string, long long> CmltChain::variantCounts() const {
    const Counters& c = cmltCounters_;
    return {{"lens_steps", c.lensSteps},
            {"lens_accepted", c.lensAccepted},
            {"path_lens_steps", c.pathLensSteps},
            {"path_lens_accepted", c.pathLensAccepted},
            {"path_caustic_steps", c.pathCausticSteps},
            {"path_caustic_accepted", c.pathCausticAccepted},
            {"path_still_steps", c.pathStillSteps}};
}

bool CmltChain::takeSubChainMove(const LensMove& move, int p, long long& acceptedOfKind) {
    if (!move.accepted) return false;
    std::swap(lensState_, candidates_[size_t(move.candidate)]);
    countAccepted(acceptedOfKind, p);
    return true;
}

bool CmltChain::lensSubChain(const StrategyRecord& seed, int p, double scale, std::vector<FilmSplat>& out) {
    if (!lensPath_.build(pathVertices_)) return false;
    V2f x(seed.rasterX, seed.rasterY);
    const Rgb c = lensPath_.contribution(x.x, x.y, scene_.intersect(camera_.ray(x.x, x.y)));
    asDeposit(camera_, x.x, x.y, c, lensState_);
    if (!(lensState_.f > 0)) return false;
    for (int step = 0; step < settings_.pathLensSteps; ++step) {
        proposeRasters(x, p);
        for (int i = 0; i < p; ++i) {
            const V2f& r = rasters_[size_t(i)];
            asDeposit(camera_, r.x, r.y, lensPath_.contribution(r.x, r.y, hits_[size_t(i)]), candidates_[size_t(i)]);
        }
        const LensMove move = depositAndChoose(lensState_, scale, out);
        if (takeSubChainMove(move, p, cmltCounters_.pathLensAccepted)) x = rasters_[size_t(move.candidate)];
    }
    return true;
}

bool CmltChain::causticSubChain(int p, double scale, std::vector<FilmSplat>& out) {
    if (!causticPath_.build(pathVertices_)) return false;
    V3f w = causticPath_.direction();
    float x = 0, y = 0;
    const Rgb c = causticPath_.contribution(w, x, y);
    asDeposit(camera_, x, y, c, lensState_);
    if (!(lensState_.f > 0)) return false;
    prepareCandidates(p);
    directions_.resize(size_t(p));
    for (int step = 0; step < settings_.pathLensSteps; ++step) {
        for (int i = 0; i < p; ++i) {
            directions_[size_t(i)] = perturbDirection(w, settings_.causticSigma, sampler().rng());
            const Rgb ci = causticPath_.contribution(directions_[size_t(i)], x, y);
            asDeposit(camera_, x, y, ci, candidates_[size_t(i)]);
        }
        const LensMove move = depositAndChoose(lensState_, scale, out);
        if (takeSubChainMove(move, p, cmltCounters_.pathCausticAccepted)) w = directions_[size_t(move.candidate)];
    }
    return true;
}

}  // namespace lucerna
