#pragma once
// Looking things up in a model import (core/mesh/model_import.h) from the import tests.

#include "core/mesh/model_import.h"
#include "file_helpers.h"

#include <QStringList>
#include <QtTest>

#include <algorithm>
#include <cmath>

namespace lucerna::test {

inline void writeFile(const QString& path, const QByteArray& text) { QVERIFY(writeTestFile(path, text)); }

inline bool near(double a, double b, double tol = 1e-5) { return std::abs(a - b) <= tol * std::max(1.0, std::abs(b)); }
inline bool near(const V3d& a, const V3d& b, double tol = 1e-5) { return near(a.x, b.x, tol) && near(a.y, b.y, tol) && near(a.z, b.z, tol); }

inline const Object* objectNamed(const ModelImport& m, const std::string& name) {
    for (const Object& o : m.objects)
        if (o.name == name) return &o;
    return nullptr;
}
inline const Material* materialNamed(const ModelImport& m, const std::string& name) {
    for (const Material& x : m.materials)
        if (x.name == name) return &x;
    return nullptr;
}
inline const Light* lightNamed(const ModelImport& m, const std::string& name) {
    for (const Light& l : m.lights)
        if (l.name == name) return &l;
    return nullptr;
}
inline bool reportHas(const std::vector<std::string>& report, const std::string& a, const std::string& b = {}) {
    for (const std::string& line : report)
        if (line.find(a) != std::string::npos && line.find(b) != std::string::npos) return true;
    return false;
}
inline QString joined(const std::vector<std::string>& report) {
    QStringList l;
    for (const std::string& s : report) l << QString::fromStdString(s);
    return l.join(" | ");
}

}  // namespace lucerna::test
