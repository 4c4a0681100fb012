#pragma once
// The processes a command's work is shared among: the ranks of a distributed run under mpirun
// (app/mpi_session.h implements this with MPI; nothing else includes mpi.h). Code that takes a
// ProcessGroup* treats nullptr as this process alone.
//
// Every process calls the collective operations in the same order with arrays of the same length;
// each returns on every process once all have called it. A process that leaves the sequence (a
// crash) leaves the others waiting in their next call until mpirun ends the job.

#include <cstddef>
#include <span>
#include <vector>

namespace lucerna {

class ProcessGroup {
public:
    virtual ~ProcessGroup() = default;

    virtual int rank() const = 0;  // this process, 0 .. size() - 1
    virtual int size() const = 0;

    // Every process's `values`, concatenated in rank order, on every process.
    virtual std::vector<double> allGather(std::span<const double> values) = 0;

    // The sum over the processes of `values`, added in rank order ((v0 + v1) + v2 ...; MPI_Reduce
    // promises no order), so that a run's result does not depend on timing: on rank 0, `values`
    // becomes the sum; elsewhere it is left as it was. Arrays of any length: they travel in
    // blocks and slices, so that no process holds more than a block besides its own array.
    virtual void sumToRoot(std::span<double> values) = 0;
};

inline int rankOf(const ProcessGroup* group) { return group ? group->rank() : 0; }
inline int sizeOf(const ProcessGroup* group) { return group ? group->size() : 1; }

}  // namespace lucerna
