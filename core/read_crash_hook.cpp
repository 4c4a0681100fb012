#include "core/read_crash_hook.h"

#include <QString>

#include <cstdlib>

namespace lucerna {

void crashHereWhenTesting(const char* kind) {
    if (qEnvironmentVariable("LUCERNA_TEST_CRASH_READING") == QLatin1String(kind)) std::abort();
}

}  // namespace lucerna
