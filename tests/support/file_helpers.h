#pragma once
// Files the tests write for themselves (broken inputs, models, scenes).

#include <QByteArray>
#include <QFile>
#include <QString>

namespace lucerna::test {

// `bytes` as the whole content of the file at `path`; false when it cannot be written.
inline bool writeTestFile(const QString& path, const QByteArray& bytes) {
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

}  // namespace lucerna::test
