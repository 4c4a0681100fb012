#include "app/cli_support.h"

#include "core/task_system.h"

#include <chrono>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <thread>
#include <unistd.h>

namespace lucerna::cli {

namespace {
// The one piece of global state: a signal handler can only reach a flag of this type.
volatile std::sig_atomic_t gInterrupted = 0;
extern "C" void onInterrupt(int) { gInterrupted = 1; }
}  // namespace

void catchInterrupts() {
    std::signal(SIGINT, onInterrupt);
    std::signal(SIGTERM, onInterrupt);
}

bool interrupted() { return gInterrupted != 0; }

std::string formatSeconds(double s) {
    char buf[32];
    if (s < 60) std::snprintf(buf, sizeof buf, "%.1f s", s);
    else std::snprintf(buf, sizeof buf, "%d min %02d s", int(s) / 60, int(s) % 60);
    return buf;
}

void waitShowingProgress(TaskHandle& job, const std::string& label) {
    const bool tty = isatty(STDERR_FILENO);
    const auto start = std::chrono::steady_clock::now();
    while (!job.isFinished()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        if (interrupted()) job.cancel();
        if (tty) {
            const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            const double p = job.progress();
            const std::string left = p > 0.01 ? formatSeconds(t * (1.0 - p) / p) + " left" : "estimating";
            std::fprintf(stderr, "\r%s: %5.1f%%  %s elapsed, %s   ", label.c_str(), 100.0 * p,
                         formatSeconds(t).c_str(), left.c_str());
        }
    }
    job.wait();
    if (tty) std::fputs("\n", stderr);
    job.rethrowIfFailed();
}

void addBackendOption(const std::string& nameValue, std::map<std::string, std::string>& options,
                      const std::string& where) {
    const auto eq = nameValue.find('=');
    if (eq == std::string::npos || eq == 0) throw UsageError(where + " expects name=value, got '" + nameValue + "'");
    options[nameValue.substr(0, eq)] = nameValue.substr(eq + 1);
}

int runCommand(int (*impl)(const std::vector<std::string>&), const std::vector<std::string>& args) {
    try {
        return impl(args);
    } catch (const UsageError& e) {
        std::cerr << "lucerna: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "lucerna: internal error: " << e.what() << "\n";
        return 1;
    }
}

}  // namespace lucerna::cli
