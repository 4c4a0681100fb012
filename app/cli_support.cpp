#include "app/cli_support.h"

#include "core/number_format.h"
#include "core/process_group.h"
#include "core/task_system.h"

#include <chrono>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <thread>
#include <unistd.h>

namespace lucerna::cli {

namespace {
// The one piece of global state: a signal handler can only reach a flag of this type.
volatile std::sig_atomic_t gInterrupted = 0;  // signals received
extern "C" void onInterrupt(int) { gInterrupted = gInterrupted + 1; }

// Only async-signal-safe calls: write and _exit.
const char* gExitMessage = "";
extern "C" void onInterruptExit(int) {
    const ssize_t written = ::write(STDERR_FILENO, gExitMessage, std::strlen(gExitMessage));
    (void)written;
    ::_exit(130);
}
}  // namespace

void exitOnInterrupt(const char* message) {
    gExitMessage = message;
    std::signal(SIGINT, onInterruptExit);
    std::signal(SIGTERM, onInterruptExit);
}

void checkOutputPath(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::path folder = fs::path(path).parent_path();
    if (folder.empty()) folder = ".";
    if (fs::is_directory(path, ec)) throw UsageError(path + ": is a folder, not a file");
    if (!fs::exists(folder, ec)) throw UsageError(path + ": the folder " + folder.string() + " does not exist");
    if (!fs::is_directory(folder, ec)) throw UsageError(path + ": " + folder.string() + " is not a folder");
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
        throw UsageError(path + ": cannot write in the folder " + folder.string() + " (" + std::strerror(errno) + ")");
}

void catchInterrupts() {
    std::signal(SIGINT, onInterrupt);
    std::signal(SIGTERM, onInterrupt);
}

bool interrupted() { return gInterrupted != 0; }
int interruptCount() { return int(gInterrupted); }

Imath::V3d parseVector(const std::string& option, const std::string& text) {
    Imath::V3d v;
    size_t begin = 0;
    for (int i = 0; i < 3; ++i) {
        const size_t end = i < 2 ? text.find(',', begin) : text.size();
        if (end == std::string::npos) throw UsageError(option + ": expected X,Y,Z, got '" + text + "'");
        v[i] = parseNumber<double>(option, text.substr(begin, end - begin), -1e30, 1e30);
        begin = end + 1;
    }
    return v;
}

void waitShowingProgress(TaskHandle& job, const std::string& label, int cancelAfter, ProgressLines lines) {
    const bool tty = lines != ProgressLines::Never && isatty(STDERR_FILENO);
    const bool everyTenSeconds = !tty && lines == ProgressLines::Also;
    const auto start = std::chrono::steady_clock::now();
    double lastLine = 0;
    // Checked every few milliseconds, so that a short job's wall time is its own (a grid of a
    // tenth of a second took up to 0.1 s more when this slept 100 ms); the line every 0.1 s.
    while (!job.isFinished()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
        if (interruptCount() >= cancelAfter) job.cancel();
        const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if ((tty && t - lastLine >= 0.1) || (everyTenSeconds && t - lastLine >= 10)) {
            const double p = job.progress();
            const std::string left = p > 0.01 ? formatDuration(t * (1.0 - p) / p) + " left" : "estimating";
            std::fprintf(stderr, "%s%s: %5.1f%%  %s elapsed, %s%s", tty ? "\r" : "", label.c_str(), 100.0 * p,
                         formatDuration(t).c_str(), left.c_str(), tty ? "   " : "\n");
            lastLine = t;
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

void agreeOnOutcome(ProcessGroup* processes, std::exception_ptr error) {
    if (!processes || processes->size() == 1) {
        if (error) std::rethrow_exception(error);
        return;
    }
    const double mine = error ? 1.0 : 0.0;
    const std::vector<double> failed = processes->allGather(std::span(&mine, 1));
    int speaker = -1;  // rank 0 if it failed, else the lowest failing rank
    for (int r = 0; r < int(failed.size()) && speaker < 0; ++r)
        if (failed[size_t(r)] > 0) speaker = r;
    if (speaker < 0) return;
    if (processes->rank() != speaker) throw QuietExit{2};
    if (speaker == 0) std::rethrow_exception(error);
    try {
        std::rethrow_exception(error);
    } catch (const UsageError& e) {
        throw UsageError("rank " + std::to_string(speaker) + ": " + e.what());
    }
}

int runCommand(int (*impl)(const std::vector<std::string>&), const std::vector<std::string>& args) {
    return runCommand([&] { return impl(args); });
}

int runCommand(const std::function<int()>& impl) {
    try {
        return impl();
    } catch (const QuietExit& e) {
        return e.status;
    } catch (const UsageError& e) {
        std::cerr << "lucerna: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "lucerna: internal error: " << e.what() << "\n";
        return 1;
    }
}

std::optional<GridMethod> parseGridMethod(const std::string& text, bool allowAuto) {
    const auto method = gridMethodFromName(text);
    if (method || (allowAuto && text == "auto")) return method;
    std::string names;
    for (GridMethod known : kGridMethods) names += std::string(names.empty() ? "" : ", ") + gridMethodName(known);
    throw UsageError("--method: expected one of " + names + (allowAuto ? ", auto" : "") + ", got '" + text + "'");
}

}  // namespace lucerna::cli
