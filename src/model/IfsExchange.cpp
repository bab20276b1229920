#include "model/IfsExchange.h"

#include "core/ifs/Attractor.h"
#include "model/AttractorItem.h"
#include "model/FlameItem.h"
#include "model/FractalItem.h"
#include "model/ProjectIO.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonObject>

#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace awb {

namespace {

struct ExchangeTr {
    Q_DECLARE_TR_FUNCTIONS(awb::IfsExchange)
};

} // namespace

// The entry as the JSON of a custom "fractal" item (read back through the item's own reader,
// which checks it as it checks a file).
QJsonObject importedFractalJson(const FractintEntry &e, const QStringList &colours, int samples)
{
    QJsonArray maps;
    for (const AffineMap &f : e.maps) {
        QJsonArray A;
        for (Eigen::Index r = 0; r < f.A.rows(); ++r)
            A.append(ProjectIO::rowToJson(f.A.row(r)));
        maps.append(QJsonObject{{"A", A}, {"b", ProjectIO::rowToJson(f.b)}});
    }
    const Mat cage = fractintControlCage(e);
    QJsonArray points;
    for (Eigen::Index r = 0; r < cage.rows(); ++r)
        points.append(ProjectIO::rowToJson(cage.row(r)));
    QJsonArray probabilities;
    for (double p : e.probabilities)
        probabilities.append(p);
    // Fractint's own way: the chaos game with the entry's probabilities (in space too: the 3D
    // view streams it, FractalItem).
    const QJsonObject algorithm{{"mode", "random"},
                                {"samples", samples > 0 ? samples
                                                        : e.dimension == 2 ? 400000 : 200000},
                                {"seed", 1},
                                {"probabilities", probabilities},
                                // deterministic iteration, if the user switches to it: the
                                // deepest that stays under 2^31 images, at most 8
                                {"depth", std::min(8, AlgorithmSpec::maxDepthFor(
                                                          int(e.maps.size())))}};
    const Mat centre = cage.colwise().mean();
    QJsonArray start;  // (not QJsonArray{array}: clang takes that for a copy of the inner one)
    start.append(ProjectIO::rowToJson(centre.row(0)));
    QJsonObject json{{"type", "fractal"},
                     {"name", QString::fromStdString(e.name)},
                     {"preset", "custom"},
                     {"weights", "nearest"},
                     {"maps", maps},
                     {"control_points", points},
                     {"algorithm", algorithm},
                     {"start_set", QJsonObject{{"kind", "point"}, {"points", start}}}};
    if (!colours.isEmpty())
        json["style"] = QJsonObject{{"color_by", "map"},
                                    {"colors", QJsonArray::fromStringList(colours)}};
    return json;
}

std::unique_ptr<Item> importedFractal(const FractintEntry &e, const QStringList &colours,
                                     int samples)
{
    auto item = std::make_unique<FractalItem>();
    const QJsonObject json = importedFractalJson(e, colours, samples);
    // Read and checked as a project file's item is (ProjectIO): what the import writes, the
    // next command loads.
    const FieldReader fields(json, QString());
    item->read(fields);
    item->checkLoaded(fields);
    item->setName(json["name"].toString());
    return item;
}

ImportedItems importFractintText(const QByteArray &text, const QString &fileName)
{
    std::istringstream in(text.toStdString());
    // A file of bare rows (Fractint 10, 15) is one entry named after the file.
    const FractintFile file =
        readFractintIfs(in, QFileInfo(fileName).completeBaseName().toStdString());
    const std::string name = QFileInfo(fileName).fileName().toStdString();
    ImportedItems out;
    for (const FractintProblem &p : file.problems)
        out.problems << QString::fromStdString(p.describe(name));
    for (const FractintProblem &w : file.warnings)
        out.warnings << QString::fromStdString(w.describe(name));
    for (const FractintEntry &e : file.entries) {
        std::unique_ptr<Item> item;
        try {
            item = importedFractal(e);
        } catch (const LoadError &error) {
            out.problems << ExchangeTr::tr("%1, line %2: entry %3: %4 (%5)")
                                .arg(QString::fromStdString(name))
                                .arg(e.line)
                                .arg(QString::fromStdString(e.name), error.message, error.field);
            continue;
        } catch (const std::exception &error) {
            out.problems << ExchangeTr::tr("%1, line %2: %3")
                                .arg(QString::fromStdString(name))
                                .arg(e.line)
                                .arg(QString::fromUtf8(error.what()));
            continue;
        }
        out.items.push_back(std::move(item));
    }
    return out;
}

QByteArray readExchangeFile(const QString &fileName)
{
    QFile f(fileName);
    if (f.size() > ProjectIO::maxFileBytes)
        throw InputError(ExchangeTr::tr("%1: the file is larger than %2 MB")
                             .arg(fileName)
                             .arg(ProjectIO::maxFileBytes / (1024 * 1024))
                             .toStdString());
    if (!f.open(QIODevice::ReadOnly))
        throw InputError(
            ExchangeTr::tr("cannot read %1: %2").arg(fileName, f.errorString()).toStdString());
    return f.readAll();
}

ImportedItems importFractint(const QString &fileName)
{
    return importFractintText(readExchangeFile(fileName), fileName);
}

namespace {

// The maps of a lifted IFS as maps of what is drawn, when its plane (or space) block is
// decoupled: with the one view p = X V + c, each f(X) = X A + b has A V = V M for some M, and
// then f moves p to p M + (b V + c - c M) whatever X is over p (000 §2: the drawn coordinates
// of a lifted curve are those of the curve). nullopt when a map mixes in the free coordinates.
std::optional<std::vector<AffineMap>> drawnMaps(const Ifs &ifs)
{
    if (ifs.views.size() != 1 || ifs.maps.empty())
        return std::nullopt;
    const Mat &V = ifs.views.front().V;
    const RowVec &c = ifs.views.front().c;
    const Eigen::Index k = V.cols();
    if ((k != 2 && k != 3) || V.rows() != ifs.dim())
        return std::nullopt;
    const Eigen::ColPivHouseholderQR<Mat> qr(V);
    if (qr.rank() < k)
        return std::nullopt;
    std::vector<AffineMap> out;
    for (const AffineMap &f : ifs.maps) {
        const Mat AV = f.A * V;
        const Mat M = qr.solve(AV);
        if ((AV - V * M).norm() > 1e-12 * std::max(1.0, AV.norm()))
            return std::nullopt;
        out.push_back({M, f.b * V + c - c * M});
    }
    return out;
}

} // namespace

std::optional<FractintEntry> fractintEntryOf(const AttractorItem &item, QString *why,
                                             const QString &format)
{
    FractintEntry e;
    e.name = item.name().toStdString();
    if (dynamic_cast<const FlameItem *>(&item)) {
        if (why)
            *why = ExchangeTr::tr("%1 is a fractal flame: its xforms are not affine maps, and %2 "
                                  "holds affine maps only (export it as a flam3 flame)")
                       .arg(item.name(), format);
        return std::nullopt;
    }
    const auto *fractal = dynamic_cast<const FractalItem *>(&item);
    if (fractal && fractal->fractal().preset == FractalSpec::Preset::Custom) {
        e.maps = fractal->fractal().maps;
    } else {
        const auto d = item.derivedIfs();
        if (!d) {
            if (why)
                *why = ExchangeTr::tr("%1 cannot be computed: %2")
                           .arg(item.name(), item.derivedError());
            return std::nullopt;
        }
        const Ifs &ifs = d->ifs;
        const int dim = ifs.dim();
        const bool plain = (dim == 2 || dim == 3) && ifs.views.size() == 1
                           && ifs.views.front().V.rows() == dim
                           && ifs.views.front().V.cols() == dim
                           && ifs.views.front().V.isIdentity(0) && ifs.views.front().c.isZero(0);
        if (plain) {
            e.maps = ifs.maps;
        } else if (auto drawn = drawnMaps(ifs)) {
            e.maps = std::move(*drawn);
        } else {
            if (why)
                *why = ExchangeTr::tr("the IFS of %1 acts in a space of dimension %2 that is "
                                      "drawn through a projection (000 §2), and its maps do not "
                                      "act on the drawn coordinates alone: %3 holds maps of the "
                                      "plane or of space only")
                           .arg(item.name())
                           .arg(dim)
                           .arg(format);
            return std::nullopt;
        }
    }
    e.dimension = e.maps.empty() ? 2 : e.maps.front().dim();
    const std::vector<double> &p = item.algorithm().probabilities;
    for (std::size_t i = 0; i < e.maps.size(); ++i)
        e.probabilities.push_back(p.size() == e.maps.size() ? p[i]
                                                            : 1.0 / double(e.maps.size()));
    return e;
}

} // namespace awb
