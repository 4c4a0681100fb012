#include "core/task_system.h"

#include <tbb/parallel_for.h>

namespace lucerna {

void TaskContext::parallelFor(int begin, int end, const std::function<void(int)>& body) {
    tbb::task_group_context group;
    tbb::parallel_for(
        tbb::blocked_range<int>(begin, end, 1),
        [&](const tbb::blocked_range<int>& range) {
            for (int i = range.begin(); i != range.end(); ++i) {
                if (isCancelled()) {
                    group.cancel_group_execution();
                    return;
                }
                body(i);
            }
        },
        group);
}

TaskSystem::TaskSystem(int threads)
    : threads_(threads > 0 ? threads : tbb::this_task_arena::max_concurrency()),
      // One slot is reserved for the job's own thread, which enters the arena and works too.
      arena_(std::make_unique<tbb::task_arena>(threads_, 1)) {}

TaskSystem::~TaskSystem() = default;

std::shared_ptr<TaskHandle> TaskSystem::submit(std::function<void(TaskContext&)> job) {
    auto handle = std::shared_ptr<TaskHandle>(new TaskHandle(CancellationToken()));
    TaskHandle* h = handle.get();
    tbb::task_arena* arena = arena_.get();
    h->thread_ = std::thread([h, arena, job = std::move(job)] {
        try {
            arena->execute([&] { job(h->context_); });
        } catch (...) {
            h->error_ = std::current_exception();
        }
        h->finished_.store(true, std::memory_order_release);
    });
    return handle;
}

TaskHandle::~TaskHandle() {
    cancel();
    wait();
}

void TaskHandle::wait() {
    if (thread_.joinable()) thread_.join();
}

void TaskHandle::rethrowIfFailed() {
    if (isFinished() && error_) std::rethrow_exception(error_);
}

}  // namespace lucerna
