#pragma once
// `--backend auto`: a measurement, not a guess. Every method that is consistent for the scene
// (measured_auto_settings.h) runs as two independent replicas; short interleaved pilots measure
// each method's error per unit of cost, tile by tile (film_measures.h); then every pass goes to
// the method whose next pass takes the most off the relmse of the combination, measured again as
// the render goes; and the image is every method's film combined per tile by inverse-error
// weights cross-fitted between the replicas. A method best by far takes nearly all the time and
// all the weight; methods that each do a part of the image best share it.
//
// Its film's halves are the combinations of replica 0's and of replica 1's images, so the film's
// estimated relmse stays an honest error estimate. diagnostics() says what was measured and
// decided ("auto": one line; "auto_methods": the methods that carry the image now).

#include "render/backend/backend.h"

#include <memory>

namespace lucerna {

// The measured auto backend for `scene`. Throws std::invalid_argument as its candidates do for
// bad options.
std::unique_ptr<Backend> makeMeasuredAutoBackend(SceneSnapshot scene, const RenderSettings& settings);

}  // namespace lucerna
