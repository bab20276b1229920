#include "model/StartSetText.h"

#include <QRegularExpression>

#include "model/AttractorItem.h"

#include <QCoreApplication>
#include <QMap>
#include <QStringList>

#include <cmath>

namespace awb {

namespace {

// lupdate takes the context of StartTextTr::tr() from the macro.
struct StartTextTr {
    Q_DECLARE_TR_FUNCTIONS(awb::StartSetText)
};

double finiteNumber(const QString &n)
{
    bool ok = false;
    const double v = n.trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(v))
        throw StartSetTextError{StartTextTr::tr("'%1' is not a finite number").arg(n.trimmed())};
    return v;
}

} // namespace

StartSet::Kind parseStartSetText(const QString &text, Mat *points, int dim)
{
    const qsizetype colon = text.indexOf(':');
    const QString kind = text.left(colon);
    const QMap<QString, int> count = {{"point", 1}, {"segment", 2}, {"triangle", 3}};
    if (colon < 0 || !(count.contains(kind) || kind == "polygon" || kind == "points"))
        throw StartSetTextError{StartTextTr::tr("a start set is written point:x,y | "
                                                "segment:x1,y1,x2,y2 | "
                                                "triangle:x1,y1,x2,y2,x3,y3 | polygon:... | "
                                                "points:... | lifted:x,y,c1,...;... | "
                                                "net:i,j,... | vertex-limits, got '%1'")
                                    .arg(text),
                                true};
    QList<double> v;
    for (const QString &n : text.mid(colon + 1).split(',', Qt::SkipEmptyParts))
        v << finiteNumber(n);
    if (v.size() % dim || v.isEmpty() || (count.contains(kind) && v.size() != dim * count[kind])
        || (kind == "polygon" && v.size() < 3 * dim))
        throw StartSetTextError{
            StartTextTr::tr("a %1 needs %2 coordinates (%3 per point), got %4")
                .arg(kind)
                .arg(count.contains(kind) ? QString::number(dim * count[kind])
                                          : StartTextTr::tr("a multiple of %1").arg(dim))
                .arg(dim)
                .arg(v.size())};
    *points = Mat(v.size() / dim, dim);
    for (int i = 0; i < v.size() / dim; ++i)
        for (int c = 0; c < dim; ++c)
            (*points)(i, c) = v[dim * i + c];
    if (kind == "segment")
        return StartSet::Kind::Polyline;
    if (kind == "triangle" || kind == "polygon")
        return StartSet::Kind::Polygon;
    return StartSet::Kind::Points;
}

std::vector<int> netIndicesFromText(const QString &text)
{
    std::vector<int> net;
    static const QRegularExpression between(QStringLiteral("[,;\\s]+"));
    for (const QString &n : text.split(between, Qt::SkipEmptyParts)) {
        bool ok = false;
        const int i = n.toInt(&ok);
        if (!ok || i < 0)
            throw StartSetTextError{
                StartTextTr::tr("'%1' is not a net point index (an integer from 0)").arg(n)};
        net.push_back(i);
    }
    if (net.empty())
        throw StartSetTextError{StartTextTr::tr("net: needs at least one index")};
    return net;
}

StartSet startSetFromText(const AttractorItem &item, const DerivedIfs &d, const QString &text)
{
    if (text.startsWith("lifted:")) {
        // Points of the lifted space, ';' between points: lifted:x,y,c1,..;x,y,c1,..
        std::vector<std::vector<double>> lifted;
        for (const QString &point : text.mid(7).split(';', Qt::SkipEmptyParts)) {
            std::vector<double> p;
            for (const QString &n : point.split(',', Qt::SkipEmptyParts))
                p.push_back(finiteNumber(n));
            lifted.push_back(std::move(p));
        }
        if (lifted.empty())
            throw StartSetTextError{StartTextTr::tr("lifted: needs at least one point")};
        try {
            return StartSet::points(liftedStartPoints(d, lifted));
        } catch (const InputError &e) {
            throw StartSetTextError{QString::fromStdString(e.what())};
        }
    }
    if (text.startsWith("net:")) {
        // Control points by index (0-based): net:0,9,18
        const std::vector<int> net = netIndicesFromText(text.mid(4));
        try {
            return netStartSet(d, net);
        } catch (const InputError &e) {
            throw StartSetTextError{QString::fromStdString(e.what())};
        }
    }
    if (text == "vertex-limits") {
        // The limit positions of the vertices of the mesh refined `depth` times (exact).
        if (!d.vertexLimitStart)
            throw StartSetTextError{StartTextTr::tr("vertex-limits needs a mesh item; '%1' is a %2")
                                        .arg(item.name(), item.typeName())};
        return StartSet::points(Mat(0, 3));
    }
    Mat pts;
    const StartSet::Kind kind = parseStartSetText(text, &pts, item.pointDimension());
    return {kind, d.toIfsSpace(pts)};
}

} // namespace awb
