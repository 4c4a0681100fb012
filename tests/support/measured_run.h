#pragma once
// The built `lucerna` run as a child whose own cost is measured: fork/exec and wait4 rather than
// QProcess, so that its peak resident set (ru_maxrss) and CPU time are its own. It runs under an
// address-space limit of 4 GB (none under AddressSanitizer, which reserves terabytes of shadow)
// and 20 s of CPU, so that a regression fails a test instead of eating the machine.

#include "sanitizers.h"

#include <QDir>
#include <QFile>
#include <QStringList>
#include <QTemporaryDir>

#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <functional>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace lucerna::test {

inline constexpr rlim_t kAddressSpace = rlim_t(4) << 30;

struct Run {
    int exitCode = -1;  // -1: killed by a signal (see `signal`)
    int signal = 0;
    QByteArray out, err;
    double cpuSeconds = 0, wallSeconds = 0;
    long maxRssMb = 0;
};

inline QByteArray readAll(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// Runs lucerna with `args` in `dir`. `whileRunning(pid)` is called once the child exists (for
// signals); the child is killed after `wallLimitSeconds`.
inline Run runLucerna(const QStringList& args, const QString& dir, const std::function<void(pid_t)>& whileRunning = {},
               double wallLimitSeconds = 30, rlim_t addressSpace = kAddressSpace) {
    static QTemporaryDir logs;
    static int serial = 0;
    const QString outPath = logs.filePath(QString("out-%1").arg(serial)), errPath = logs.filePath(QString("err-%1").arg(serial));
    ++serial;
    std::vector<std::string> argvText{LUCERNA_BINARY};
    for (const QString& a : args) argvText.push_back(a.toStdString());
    std::vector<char*> argv;
    for (std::string& a : argvText) argv.push_back(a.data());
    argv.push_back(nullptr);
    const std::string out = outPath.toStdString(), err = errPath.toStdString(), cwd = dir.toStdString();

    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = ::fork();
    if (pid == 0) {  // only async-signal-safe calls until exec
        const int o = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
        const int e = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
        const int in = ::open("/dev/null", O_RDONLY);
        if (o < 0 || e < 0 || in < 0 || ::dup2(o, 1) < 0 || ::dup2(e, 2) < 0 || ::dup2(in, 0) < 0) ::_exit(120);
        const rlimit as{addressSpace, addressSpace}, cpu{20, 20};
        if (!kAddressSanitizer) ::setrlimit(RLIMIT_AS, &as);
        ::setrlimit(RLIMIT_CPU, &cpu);
        if (::chdir(cwd.c_str()) != 0) ::_exit(121);
        ::execv(argv[0], argv.data());
        ::_exit(122);
    }
    Run r;
    if (pid < 0) return r;
    if (whileRunning) whileRunning(pid);
    int status = 0;
    rusage usage{};
    for (;;) {
        const pid_t done = ::wait4(pid, &status, WNOHANG, &usage);
        if (done == pid) break;
        if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > wallLimitSeconds) {
            ::kill(pid, SIGKILL);
            ::wait4(pid, &status, 0, &usage);
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    r.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
    r.cpuSeconds = double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                   1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
    r.maxRssMb = usage.ru_maxrss / 1024;
    r.out = readAll(outPath);
    r.err = readAll(errPath);
    return r;
}

inline QString describe(const QStringList& args, const Run& r) {
    return QString("lucerna %1: exit %2 (signal %3), %4 s CPU, %5 s wall, %6 MB, stderr: %7")
        .arg(args.join(' '))
        .arg(r.exitCode)
        .arg(r.signal)
        .arg(r.cpuSeconds)
        .arg(r.wallSeconds)
        .arg(r.maxRssMb)
        .arg(QString::fromUtf8(r.err));
}

// One line of printable text: no NUL, no control character but the final newline.
inline bool isOnePrintableLine(const QByteArray& s) {
    if (s.isEmpty() || !s.endsWith('\n')) return false;
    for (qsizetype i = 0; i + 1 < s.size(); ++i)
        if (static_cast<unsigned char>(s[i]) < 0x20 || s[i] == 0x7f) return false;
    return true;
}

// The entries of `dir` other than `keep` (hidden ones included).
inline QStringList leftovers(const QString& dir, const QStringList& keep) {
    QStringList left;
    for (const QString& f : QDir(dir).entryList(QDir::AllEntries | QDir::Hidden | QDir::System | QDir::NoDotAndDotDot))
        if (!keep.contains(f)) left << f;
    return left;
}

}  // namespace lucerna::test
