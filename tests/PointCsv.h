#pragma once
// Reading the CSV of `attractor-cli points` / writePointsCsv in the tests: the x, y columns as
// rows of a matrix and, when asked, the map column.

#include "core/Types.h"

#include <QByteArray>
#include <QList>

#include <vector>

namespace awb::test {

inline Mat csvPoints(const QByteArray &csv, std::vector<int> *maps = nullptr)
{
    QList<QByteArray> lines = csv.trimmed().split('\n');
    lines.removeFirst();  // the header
    Mat out(lines.size(), 2);
    for (int i = 0; i < lines.size(); ++i) {
        const QList<QByteArray> f = lines[i].split(',');
        out(i, 0) = f[0].toDouble();
        out(i, 1) = f[1].toDouble();
        if (maps)
            maps->push_back(f[2].toInt());
    }
    return out;
}

} // namespace awb::test
