#include "app/cli_support.h"

#include <csignal>
#include <iostream>

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
