#pragma once
// Running a program as a user would from a shell, for the tests of the command line: its exit
// status (-1 when it crashed or did not finish in time) and what it printed.

#include <QProcess>
#include <QString>
#include <QStringList>

namespace lucerna::test {

struct Run {
    int exitCode = -1;
    QString out, err;
};

inline Run runProgram(const QString& program, const QStringList& args, int timeoutMs = 300000) {
    QProcess p;
    p.start(program, args);
    p.waitForFinished(timeoutMs);
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, QString::fromUtf8(p.readAllStandardOutput()),
            QString::fromUtf8(p.readAllStandardError())};
}

// The lucerna executable of this build (LUCERNA_BINARY, tests/CMakeLists.txt).
inline Run runLucerna(const QStringList& args, int timeoutMs = 300000) {
    return runProgram(LUCERNA_BINARY, args, timeoutMs);
}

}  // namespace lucerna::test
