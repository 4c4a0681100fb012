#pragma once
// What the headless commands share: the one-line usage error (exit status 2), number parsing
// for options, the Ctrl-C flag, and the wrapper that turns exceptions into exit statuses.

#include "render/photometry/grid_calculation.h"

#include <Imath/ImathVec.h>

#include <charconv>
#include <exception>
#include <functional>
#include <memory>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace lucerna::cli {

// Bad usage or bad input: exit status 2 with this one line.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

template <class T>
T parseNumber(const std::string& option, const std::string& text, T lo, T hi) {
    T value{};
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || ptr != text.data() + text.size() || !(value >= lo && value <= hi))
        throw UsageError(option + ": expected a number in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                         "], got '" + text + "'");
    return value;
}

// --method's value: a grid method, or nothing for "auto" where allowAuto; UsageError listing the
// names otherwise.
std::optional<GridMethod> parseGridMethod(const std::string& text, bool allowAuto);

// Adds "name=value" (an --option's value) to `options`; UsageError, naming `where`, when it has
// no name or '='.
void addBackendOption(const std::string& nameValue, std::map<std::string, std::string>& options,
                      const std::string& where = "--option");

// Routes SIGINT and SIGTERM to a flag that long commands poll (they stop within a pass and
// write nothing, or, for `render --save-on-interrupt`, at the next pass boundary and write what
// converged so far). interruptCount() counts the signals since.
void catchInterrupts();
bool interrupted();
int interruptCount();

// Until a long command has work that polls the flag (while it loads its scene, say), SIGINT and
// SIGTERM end it at once with `message` (a whole line, a string literal) on standard error and
// exit status 130, as the flag would once the work runs: nothing has been written yet. A later
// catchInterrupts() hands the signals to the flag.
void exitOnInterrupt(const char* message);

// Refuses (UsageError, exit 2) an output path that cannot be written, before any work is done:
// its folder missing, not a folder or not writable, or the path itself a folder.
void checkOutputPath(const std::string& path);

// "X,Y,Z" as three numbers; UsageError naming `option` otherwise.
Imath::V3d parseVector(const std::string& option, const std::string& text);

}  // namespace lucerna::cli

namespace lucerna {
class TaskHandle;
class ProcessGroup;
}

namespace lucerna::cli {

// Waits for a job, cancelling it once `cancelAfter` interrupts have come (a first Ctrl-C may be
// the job's own to answer), and shows "LABEL: 42.0%  1.2 s elapsed, 3.4 s left"
// on standard error while it runs when that is a terminal. Rethrows what the job threw.
// How: on a terminal, one line redrawn; ProgressLines::Also adds a line every 10 s where
// standard error is no terminal (rank 0 of a distributed run, whose output mpirun forwards);
// ProgressLines::Never shows nothing (the other ranks).
enum class ProgressLines { TerminalOnly, Also, Never };
void waitShowingProgress(TaskHandle& job, const std::string& label, int cancelAfter = 1,
                         ProgressLines lines = ProgressLines::TerminalOnly);

// A process of a distributed command that leaves without a word (agreeOnOutcome): runCommand
// returns `status` and prints nothing.
struct QuietExit {
    int status = 2;
};

// The processes of a distributed command agree on a phase that may fail (the setup: arguments,
// scene, backend; or the work), so that none is left waiting for another in MPI. Each calls this
// with what its phase threw, or nothing. When any failed, every process leaves: one speaks, by
// rethrowing its error (rank 0's own; when rank 0 is fine, the lowest failing rank's, its
// message prefixed "rank N: "), the others throw QuietExit. Alone (nullptr), it rethrows the
// error if there is one.
void agreeOnOutcome(ProcessGroup* processes, std::exception_ptr error);

// A distributed command's setup (`setUp()`: arguments, scene, backend), run by every process and
// agreed on (agreeOnOutcome), so that every process leaves, or none: what it made, where every
// process's setup succeeded.
template <class SetUp>
std::optional<std::invoke_result_t<SetUp&>> setUpTogether(ProcessGroup* processes, SetUp&& setUp) {
    std::optional<std::invoke_result_t<SetUp&>> made;
    std::exception_ptr failure;
    try {
        made.emplace(setUp());
    } catch (...) {
        failure = std::current_exception();
    }
    agreeOnOutcome(processes, failure);
    return made;
}

// Runs a command: UsageError gives "lucerna: MESSAGE" and 2, any other exception "lucerna:
// internal error: ..." and 1, QuietExit its status and nothing.
int runCommand(int (*impl)(const std::vector<std::string>&), const std::vector<std::string>& args);
int runCommand(const std::function<int()>& impl);

}  // namespace lucerna::cli
