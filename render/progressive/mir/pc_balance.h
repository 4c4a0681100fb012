#pragma once
// How many cheap samples of the normalisation Pc a mir pass draws (MirChain::setPcSamples), so
// that the render's error at a given cost is least.
//
// After P passes with m samples per chain (two chains, one per film half), the image's relmse is
//   E = s rho / (m P) + B / P:
// Pc's part (s: the image's relmse per squared relative error of Pc; rho: one sample's relative
// variance; the image carries the mean of the halves' Pc, of variance rho / (m P)) and the
// gather's (B: its relmse after one pass). A pass costs c_g + c_pc m rays, so at a cost T
//   E = (s rho / m + B) (c_g + c_pc m) / T,
// least at m* = sqrt(s rho c_g / (B c_pc)), where the two errors stand as their costs do.
// Counted in rays, not seconds, so that a render with a seed is reproducible.

namespace lucerna {

class Film;

struct PcBalance {
    double sensitivity = 0;             // s
    double sampleRelativeVariance = 0;  // rho
    double passRelmse = 0;              // B
    double passRays = 0;                // c_g
    double sampleRays = 0;              // c_pc
};

// s and B from mir's two films: `rest` (the direct light, the clamp's residual, emitters seen)
// and `vplLight` (the VPLs' light without Pc; both halves are read with the same `pc`, so that
// their difference is the gather's alone). The other members are left as they are.
void measureImageTerms(const Film& rest, const Film& vplLight, double pc, PcBalance& b);

// m*, within [least, most]; `fallback` while a measure is missing (not positive or not finite).
int balancedPcSamples(const PcBalance& b, int least, int most, int fallback);

}  // namespace lucerna
