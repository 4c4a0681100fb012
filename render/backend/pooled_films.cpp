#include "render/backend/pooled_films.h"

#include "render/trace/rng.h"

namespace lucerna {

void poolFilms(ProgressiveBackend& backend, ProcessGroup& group) {
    std::vector<Film> pooled;
    for (const Film* film : backend.films()) {
        std::vector<double> values = film->additive();
        group.sumToRoot(values);
        if (group.rank() == 0) pooled.push_back(Film::fromAdditive(film->width(), film->height(), values));
    }
    if (group.rank() == 0) backend.adoptFilms(std::move(pooled));
}

uint64_t processSeed(uint64_t seed, int rank) { return rank == 0 ? seed : hashSeed(seed, uint64_t(rank), 0x72616e6b); }

}  // namespace lucerna
