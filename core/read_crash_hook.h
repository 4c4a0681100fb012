#pragma once
// Test hook, compiled in always (the tests run the Release build): a file reader that crashes, so
// that a test can check that a crash while reading a file loses no work (ui/document/autosave.h).

namespace lucerna {

// Called where the read of a file of `kind` ("open", "import", "luminaire") starts: aborts the
// process, as a crashing reader would, when the environment variable LUCERNA_TEST_CRASH_READING
// is `kind`; otherwise does nothing.
void crashHereWhenTesting(const char* kind);

}  // namespace lucerna
