#pragma once
// The background task system every long job uses (DESIGN.md, "The flow of data"), on oneTBB:
// a task arena sized to the machine (or to --threads), cancellation that reaches every parallel
// loop at tile granularity, progress, and publication of the newest result.
//
// A job never runs on the thread that submits it: each submitted job gets a thread of its own that
// enters the arena, so the GUI or the command line stays free to show progress and to cancel.

// Qt defines `emit` as a macro and oneTBB has a member function of that name: keep the macro
// away from TBB's headers, whichever is included first.
#pragma push_macro("emit")
#undef emit
#include <tbb/task_arena.h>
#include <tbb/task_group.h>
#pragma pop_macro("emit")

#include <atomic>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>

namespace lucerna {

// Shared, copyable flag. Cheap to poll from inner loops.
class CancellationToken {
public:
    CancellationToken() : flag_(std::make_shared<std::atomic<bool>>(false)) {}
    void cancel() const { flag_->store(true, std::memory_order_relaxed); }
    bool isCancelled() const { return flag_->load(std::memory_order_relaxed); }

private:
    std::shared_ptr<std::atomic<bool>> flag_;
};

// What a running job sees: its token, its progress slot, and parallel loops bound to both.
class TaskContext {
public:
    explicit TaskContext(CancellationToken token) : token_(std::move(token)) {}

    bool isCancelled() const { return token_.isCancelled(); }
    const CancellationToken& token() const { return token_; }

    // Fraction done in [0, 1], for display; a job that cannot tell leaves it at 0.
    void setProgress(double fraction) { progress_.store(fraction, std::memory_order_relaxed); }
    double progress() const { return progress_.load(std::memory_order_relaxed); }

    // Runs body(i) for i in [begin, end) on the arena's threads, one index per task (use an index
    // per tile). Indices not yet started when the token is cancelled are skipped.
    void parallelFor(int begin, int end, const std::function<void(int)>& body);

private:
    CancellationToken token_;
    std::atomic<double> progress_{0.0};
};

class TaskHandle;

class TaskSystem {
public:
    // threads <= 0: one per hardware thread.
    explicit TaskSystem(int threads = 0);
    ~TaskSystem();
    TaskSystem(const TaskSystem&) = delete;
    TaskSystem& operator=(const TaskSystem&) = delete;

    int threadCount() const { return threads_; }

    // Starts job in the background. An exception escaping the job is kept in the handle.
    std::shared_ptr<TaskHandle> submit(std::function<void(TaskContext&)> job);

private:
    int threads_;
    std::unique_ptr<tbb::task_arena> arena_;
};

class TaskHandle {
public:
    ~TaskHandle();  // cancels and waits: a handle never outlives its job
    void cancel() { context_.token().cancel(); }
    void wait();
    bool isFinished() const { return finished_.load(std::memory_order_acquire); }
    double progress() const { return context_.progress(); }
    bool isCancelled() const { return context_.isCancelled(); }
    // Rethrows what the job threw, if anything (after it finished).
    void rethrowIfFailed();

private:
    friend class TaskSystem;
    explicit TaskHandle(CancellationToken token) : context_(std::move(token)) {}

    TaskContext context_;
    std::thread thread_;
    std::atomic<bool> finished_{false};
    std::exception_ptr error_;
};

// The newest value of something a job produces (a frame, a figure), for whoever displays it.
// Older values that nobody fetched are simply replaced.
template <class T>
class Latest {
public:
    void publish(std::shared_ptr<const T> value) {
        std::lock_guard lock(mutex_);
        value_ = std::move(value);
        ++version_;
    }
    std::shared_ptr<const T> get() const {
        std::lock_guard lock(mutex_);
        return value_;
    }
    // Increments on every publish; lets a viewer skip values it already shows.
    uint64_t version() const {
        std::lock_guard lock(mutex_);
        return version_;
    }

private:
    mutable std::mutex mutex_;
    std::shared_ptr<const T> value_;
    uint64_t version_ = 0;
};

}  // namespace lucerna
