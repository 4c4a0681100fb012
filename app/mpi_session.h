#pragma once
// Distributed runs, `mpirun -n N lucerna render|grid ...` (README, "On a cluster"): the one
// place that knows MPI. It is compiled in when CMake's FindMPI finds it (LUCERNA_HAVE_MPI) and
// started only when a launcher started this process, as its environment says; otherwise, or in
// a build without MPI, every command runs as one process, as it always has.

#include "core/process_group.h"

#include <memory>

namespace lucerna {

// Whether mpirun (Open MPI's, or another PMI launcher) started this process: OMPI_COMM_WORLD_SIZE,
// PMIX_RANK or PMI_RANK in its environment.
bool launchedByMpirun();

// The ranks of this run, MPI initialised, when MPI is compiled in and launchedByMpirun(); MPI is
// finalised when the object goes (before the process exits). nullptr otherwise; a build without
// MPI started by mpirun then says once, on its rank 0, that each process runs the whole command.
// Throws std::runtime_error when MPI cannot start or gives less than serialised threading.
std::unique_ptr<ProcessGroup> startMpiSession(int& argc, char**& argv);

}  // namespace lucerna
