#pragma once
// The preview comes first on the cores (issue 6): while anyone holds the gate (the user drags,
// the preview draws a frame), the converging render waits between passes. A counter, so that
// overlapping holders (a drag during a preview frame) release it only when both are done.

#include <atomic>
#include <memory>

namespace lucerna {

class YieldGate {
public:
    void hold() { holders_->fetch_add(1, std::memory_order_relaxed); }
    void release() { holders_->fetch_sub(1, std::memory_order_relaxed); }
    bool isHeld() const { return holders_->load(std::memory_order_relaxed) > 0; }
    // Shared with the render jobs, which may outlive a window being torn down.
    std::shared_ptr<std::atomic<int>> counter() const { return holders_; }

    // Holds the gate for a scope.
    class Scope {
    public:
        explicit Scope(std::shared_ptr<std::atomic<int>> c) : c_(std::move(c)) { c_->fetch_add(1); }
        ~Scope() { c_->fetch_sub(1); }
        Scope(const Scope&) = delete;
        Scope& operator=(const Scope&) = delete;

    private:
        std::shared_ptr<std::atomic<int>> c_;
    };

private:
    std::shared_ptr<std::atomic<int>> holders_ = std::make_shared<std::atomic<int>>(0);
};

}  // namespace lucerna
