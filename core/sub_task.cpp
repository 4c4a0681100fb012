#include "core/sub_task.h"

namespace lucerna {

SubTask::SubTask(const TaskContext& job, double seconds)
    : job_(job), deadline_(deadlineIn(seconds)), watcher_([this] { watch(); }) {}

SubTask::~SubTask() {
    {
        const std::lock_guard lock(mutex_);
        done_ = true;
    }
    wake_.notify_all();
    watcher_.join();
}

void SubTask::setDeadline(double seconds) {
    const std::lock_guard lock(mutex_);
    deadline_ = deadlineIn(seconds);
}

SubTask::Clock::time_point SubTask::deadlineIn(double seconds) {
    if (!(seconds < 1e9)) return Clock::time_point::max();
    return Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

// Polls the job every 10 ms: its token is another's, which nothing here can wait on.
void SubTask::watch() {
    std::unique_lock lock(mutex_);
    while (!wake_.wait_for(lock, std::chrono::milliseconds(10), [this] { return done_; }))
        if (job_.isCancelled() || Clock::now() >= deadline_) token_.cancel();
}

}  // namespace lucerna
