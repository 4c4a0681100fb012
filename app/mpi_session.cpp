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
        // A rank waiting in a collective yields its core instead of spinning on it (unless the
        // user set otherwise): waiting costs nothing then, while a spinning
        // rank on a shared or oversubscribed node took the core from the ranks still working
        // (a small grid on 2 ranks here: 8.6 s spinning, 1.3 s yielding; docs/benchmarks-history.md,
        // "MPI (issue 23): the first versions").
        ::setenv("OMPI_MCA_mpi_yield_when_idle", "1", 0);
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

    // A reduce-scatter in rank order, then a gather: rank k adds up slice k of every rank's
    // block (rank 0's values first, then 1's, ...), and rank 0 collects the slices' sums. Each
    // rank sends and receives about two arrays whatever the number of ranks, where gathering
    // every array at rank 0 would have it receive N - 1 of them through its one link; the sums
    // are the same, added in the same order. Blocks of 4 Mi values keep the buffers at 48 MB,
    // kept from call to call (fresh memory costs a page fault a page).
    void sumToRoot(std::span<double> values) override {
        const size_t ranks = size_t(size_), me = size_t(rank_);
        const size_t blockSize = std::max<size_t>(ranks, size_t(1) << 22);
        std::vector<double>& received = received_;
        std::vector<double>& sum = sum_;
        std::vector<int> sendCounts(ranks), sendOffsets(ranks), receiveCounts(ranks), receiveOffsets(ranks);
        for (size_t begin = 0; begin < values.size(); begin += blockSize) {
            const size_t n = std::min(blockSize, values.size() - begin);
            const size_t slice = (n + ranks - 1) / ranks;  // rank k sums [k slice, (k + 1) slice)
            const auto sliceLength = [&](size_t k) { return std::min(slice, n - std::min(n, k * slice)); };
            const size_t mine = sliceLength(me);
            for (size_t k = 0; k < ranks; ++k) {
                sendCounts[k] = count(sliceLength(k));
                sendOffsets[k] = count(k * slice);
                receiveCounts[k] = count(mine);
                receiveOffsets[k] = count(k * mine);
            }
            received.resize(mine * ranks);
            MPI_Alltoallv(values.data() + begin, sendCounts.data(), sendOffsets.data(), MPI_DOUBLE, received.data(),
                          receiveCounts.data(), receiveOffsets.data(), MPI_DOUBLE, MPI_COMM_WORLD);
            sum.assign(received.begin(), received.begin() + std::ptrdiff_t(mine));  // rank 0's
            for (size_t r = 1; r < ranks; ++r)
                for (size_t i = 0; i < mine; ++i) sum[i] += received[r * mine + i];
            MPI_Gatherv(sum.data(), count(mine), MPI_DOUBLE, values.data() + begin, sendCounts.data(),
                        sendOffsets.data(), MPI_DOUBLE, 0, MPI_COMM_WORLD);
        }
    }

private:
    int rank_ = 0, size_ = 1;
    std::vector<double> received_, sum_;  // sumToRoot's
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
