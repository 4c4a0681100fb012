#pragma once
// A render shared among processes (`mpirun -n N lucerna render`, app/mpi_session.h): each
// process renders its share of the passes into its own film (pass_loop.h, PassLoopOptions'
// share), then the films are pooled in double precision on rank 0, added in rank order so that
// a run is reproducible (Film::additive): the path-type backends' half-buffers summed with their
// sample counts, the Metropolis backends' normalised halves averaged with weights by their
// passes. Per-light layers pool layer by layer.

#include "core/process_group.h"
#include "render/backend/backend.h"

namespace lucerna {

// Collective: every process calls it once its passes are done. On rank 0 the backend's films are
// then the pooled ones (Backend::rewriteFilms), so that its frame is the whole run's;
// the other processes' films stay their own (with unit half scales).
void poolFilms(Backend& backend, ProcessGroup& group);

// The seed of a process's own Metropolis chains: the render's seed on rank 0 (so that one rank
// renders what one process does), a seed derived from it elsewhere.
uint64_t processSeed(uint64_t seed, int rank);

}  // namespace lucerna
