#include "render/backend/pooled_films.h"

#include "render/trace/rng.h"

namespace lucerna {

void poolFilms(Backend& backend, ProcessGroup& group) {
    // Blocks of 4 Mi values (32 MB): the film is pooled in place, never copied whole.
    constexpr size_t kBlock = size_t(1) << 22;
    backend.rewriteFilms([&](Film& film) {
        film.rewriteAdditive(kBlock, [&](std::span<double> block) { group.sumToRoot(block); });
    });
}

uint64_t processSeed(uint64_t seed, int rank) { return rank == 0 ? seed : hashSeed(seed, uint64_t(rank), 0x72616e6b); }

}  // namespace lucerna
