#pragma once
// A part of a running job with its own cancellation: cancelled when the job is, at a deadline,
// or by cancel(). What a job uses to try something for a while and drop it (a pilot run whose
// preparation a time limit between passes would not cut) without cancelling itself.

#include "core/task_system.h"

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace lucerna {

class SubTask {
public:
    // `seconds` from now to the deadline; infinite or beyond a billion: none.
    SubTask(const TaskContext& job, double seconds);
    ~SubTask();  // stops watching; the part must have returned
    SubTask(const SubTask&) = delete;
    SubTask& operator=(const SubTask&) = delete;

    TaskContext& context() { return context_; }
    void cancel() { token_.cancel(); }
    // A new deadline, `seconds` from now (infinite: none).
    void setDeadline(double seconds);

private:
    using Clock = std::chrono::steady_clock;
    static Clock::time_point deadlineIn(double seconds);
    void watch();

    const TaskContext& job_;
    CancellationToken token_;
    TaskContext context_{token_};
    std::mutex mutex_;
    std::condition_variable wake_;
    Clock::time_point deadline_;
    bool done_ = false;
    std::thread watcher_;  // last: it starts once the rest is built
};

}  // namespace lucerna
