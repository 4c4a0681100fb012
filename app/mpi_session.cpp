#include "app/mpi_session.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#if LUCERNA_HAVE_MPI
#include <mpi.h>
#endif

namespace lucerna {

bool launchedByMpirun() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK"})
        if (std::getenv(name)) return true;
    return false;
}

#if LUCERNA_HAVE_MPI

namespace {

// Arrays of more elements than an int counts do not occur here (a film of 16384 x 16384 is 1.6e9
// doubles and goes in slices); allGather's are a few per grid point.
int count(size_t n) {
    if (n > size_t(std::numeric_limits<int>::max())) throw std::runtime_error("mpi: an array too large to send at once");
    return int(n);
}

class MpiSession final : public ProcessGroup {
public:
    MpiSession(int& argc, char**& argv) {
        int provided = 0;
        // The grid's exchanges run on a worker thread while the main thread waits: serialised,
        // never two threads in MPI at once.
        if (MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &provided) != MPI_SUCCESS)
            throw std::runtime_error("mpi: MPI_Init_thread failed");
        if (provided < MPI_THREAD_SERIALIZED) {
            MPI_Finalize();
            throw std::runtime_error("mpi: this MPI offers no serialised threading (MPI_THREAD_SERIALIZED)");
        }
        MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
        MPI_Comm_size(MPI_COMM_WORLD, &size_);
    }
    ~MpiSession() override { MPI_Finalize(); }
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;

    int rank() const override { return rank_; }
    int size() const override { return size_; }

    std::vector<double> allGather(std::span<const double> values) override {
        std::vector<double> all(values.size() * size_t(size_));
        MPI_Allgather(values.data(), count(values.size()), MPI_DOUBLE, all.data(), count(values.size()), MPI_DOUBLE,
                      MPI_COMM_WORLD);
        return all;
    }

    void sumToRoot(std::span<double> values) override {
        // Slices small enough that rank 0's buffer of one slice per process stays near 256 MB.
        const size_t slice = std::max<size_t>(size_t(1) << 16, (size_t(1) << 25) / size_t(size_));
        std::vector<double> gathered(rank_ == 0 ? std::min(slice, values.size()) * size_t(size_) : 0);
        for (size_t begin = 0; begin < values.size(); begin += slice) {
            const size_t n = std::min(slice, values.size() - begin);
            MPI_Gather(values.data() + begin, count(n), MPI_DOUBLE, gathered.data(), count(n), MPI_DOUBLE, 0,
                       MPI_COMM_WORLD);
            if (rank_ != 0) continue;
            // In rank order: rank 0's own values are where they were, then 1's, 2's, ...
            for (int r = 1; r < size_; ++r) {
                const double* theirs = gathered.data() + size_t(r) * n;
                for (size_t i = 0; i < n; ++i) values[begin + i] += theirs[i];
            }
        }
    }

private:
    int rank_ = 0, size_ = 1;
};

}  // namespace

std::unique_ptr<ProcessGroup> startMpiSession(int& argc, char**& argv) {
    if (!launchedByMpirun()) return nullptr;
    return std::make_unique<MpiSession>(argc, argv);
}

#else

std::unique_ptr<ProcessGroup> startMpiSession(int&, char**&) {
    if (!launchedByMpirun()) return nullptr;
    const char* rank = std::getenv("OMPI_COMM_WORLD_RANK");
    if (!rank) rank = std::getenv("PMIX_RANK");
    if (!rank) rank = std::getenv("PMI_RANK");
    if (rank && std::strcmp(rank, "0") == 0)
        std::fputs("lucerna: warning: built without MPI: each process mpirun started runs the whole command alone\n",
                   stderr);
    return nullptr;
}

#endif

}  // namespace lucerna
