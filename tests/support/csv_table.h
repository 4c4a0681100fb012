#pragma once
// The CSV files the commands write (bench.csv, grid CSVs), read back by column name.

#include <QFile>
#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

namespace lucerna::test {

struct CsvTable {
    QStringList header;
    std::vector<QStringList> rows;

    // The file at `path` (a header line, then rows); empty when it cannot be read.
    static CsvTable read(const QString& path) {
        CsvTable t;
        QFile f(path);
        if (!f.open(QIODevice::ReadOnly)) return t;
        const QStringList lines = QString::fromUtf8(f.readAll()).trimmed().split('\n');
        t.header = lines.value(0).split(',');
        for (const QString& line : lines.mid(1)) t.rows.push_back(line.split(','));
        return t;
    }

    // The text of the named column in `row` (empty when either is missing).
    QString text(size_t row, const QString& column) const {
        return row < rows.size() ? rows[row].value(header.indexOf(column)) : QString();
    }
    // The named column of `row` as a number; nothing when it is not one.
    std::optional<double> number(size_t row, const QString& column) const {
        bool isNumber = false;
        const double value = text(row, column).toDouble(&isNumber);
        if (!isNumber) return std::nullopt;
        return value;
    }
};

}  // namespace lucerna::test
