// ItemController: the regularity panel and the analysis charts (distances to the exact curve,
// lengths, box-counting dimension), computed on a worker thread that a newer edit cancels.

#include "gui/app/ItemController.h"
#include "model/ItemAnalysisJson.h"

#include "gui/views/BackgroundPriority.h"

#include "core/analysis/Geometry.h"
#include "core/analysis/HausdorffBracket.h"
#include "core/analysis/Spectrum.h"
#include "core/ifs/Attractor.h"
#include "core/schemes/Scheme.h"
#include "gui/app/FrameBudget.h"
#include "gui/views/AnalysisCharts.h"
#include "gui/views/AttractorView.h"
#include "gui/views/RegularityPanel.h"
#include "model/AttractorItem.h"
#include "model/ExactCurve.h"
#include "model/FileWriting.h"
#include "model/NumberFormat.h"
#include "model/RegularityCertificate.h"
#include "model/SubdivisionCurveItem.h"

#include <QFileDialog>
#include <QJsonDocument>

#include <algorithm>
#include <cmath>

namespace awb {

// What the worker thread computes for the analysis charts.
struct AnalysisResult {
    QList<AnalysisCharts::DistanceSeries> distances;
    double rate = 0.0;
    std::vector<double> lengths;
    double exactLength = 0.0;
    BoxDimension box;
    bool cancelled = false;
};

namespace {

// Deterministic levels are analysed while they have at most this many start-set images: the
// charts must come quickly, even for many maps.
constexpr double analysisImages = 60000.0;

Mat planePoints(const Ifs &ifs, const StartSet &start, int depth, const std::atomic<bool> *cancel)
{
    if (ifs.views.empty())
        return {};
    PointCollector collector(ifs.views.front(), 2'000'000);
    IterationControl control;
    control.cancel = cancel;
    iterate(ifs, start, depth, collector, control);
    return collector.points();
}

} // namespace

// What the regularity depends on: the scheme (its JSON) and the number of control points.
QString ItemController::regularityKey(const SubdivisionCurveItem &curve)
{
    return QString::fromUtf8(QJsonDocument(curve.scheme().toJson()).toJson())
           + QString::number(curve.controlPoints(0).size());
}

void ItemController::setRegularityPanel(RegularityPanel *panel)
{
    m_regularity = panel;
    connect(panel, &RegularityPanel::saveCertificateRequested, this, [this] {
        const QString file = QFileDialog::getSaveFileName(
            m_attractor, tr("Save Regularity Certificate"),
            m_item ? m_item->name() + QStringLiteral(".certificate.json") : QString(),
            tr("Regularity certificate (*.json)"));
        QString why;
        if (file.isEmpty())
            return;
        if (!saveCertificate(file, &why))
            emit editRefused(why);
        else
            emit notice(tr("Saved the regularity certificate to %1").arg(file));
    });
    updateRegularity();
}

bool ItemController::saveCertificate(const QString &file, QString *error)
{
    const auto *curve = qobject_cast<const SubdivisionCurveItem *>(m_item.data());
    const auto r = m_regularity ? m_regularity->result() : nullptr;
    // The result must be the current scheme's.
    if (!curve || !r || m_regularity->resultKey() != regularityKey(*curve)) {
        if (error)
            *error = tr("No certificate: the regularity of the current curve is not computed "
                        "yet.");
        return false;
    }
    QString why;
    const QByteArray bytes = regularityCertificate(curve->scheme(), *r, &why);
    if (bytes.isEmpty() || !writeWholeFile(file, bytes, &why)) {
        if (error)
            *error = tr("No certificate was saved: %1").arg(why);
        return false;
    }
    return true;
}

// The regularity depends only on the scheme and the number of control points: a drag of a
// point does not restart it (the panel skips an unchanged key).
void ItemController::updateRegularity()
{
    if (!m_regularity)
        return;
    const auto *curve = qobject_cast<const SubdivisionCurveItem *>(m_item.data());
    if (!curve) {
        m_regularity->showMessage(tr("Regularity: only for subdivision curves"));
        return;
    }
    // The model's specRegularity (as analyse --json and Python): it says itself where it does
    // not apply (a complex de Casteljau parameter, refused parameters).
    m_regularity->analyse(curve->scheme(), int(curve->controlPoints(0).size()),
                          regularityKey(*curve));
}

void ItemController::cancelAnalysis()
{
    m_analysisTimer.stop();
    m_cancel = true;
    if (m_worker.joinable())
        m_worker.join();
    m_cancel = false;
}

void ItemController::startAnalysis()
{
    if (m_budget->inGesture()) {
        m_analysisTimer.start(); // the renderer has the cores now
        return;
    }
    cancelAnalysis();
    AttractorItem *item = drawnItem();
    if (!item)
        return;
    const auto d = item->derivedIfs();
    if (!d)
        return;
    StartSet start;
    try {
        start = item->coreStartSet(*d);
    } catch (const std::exception &) {
        return;
    }
    const auto scheme = realScheme(item);
    const Mat P = item->controlPointSetCount() > 0 ? toMatrix(item->controlPoints(0)) : Mat();
    const int maxDepth = item->algorithm().depth;
    const quint64 ticket = ++m_analysisTicket;
    m_workerDone = false;
    emit analysisStarted();
    // The curve the attractor is measured against (a closed-form limit curve, or for a
    // complex Bézier curve the Takagi image of 004 Conj. 3.7.1, where the distance levels off
    // at O(y^2) instead of going to 0): its samples for the length chart, its exact pieces for
    // the certified distance (core HausdorffBracket, as attractor-cli analyse reports it).
    const auto exactCurve = exactCurveOf(item, kExactSamples);
    const Mat exact = exactCurve ? exactCurve->points : Mat();
    const auto certified = certifiedExactCurveOf(item);
    std::shared_ptr<const CertifiedCurve> curve = certified ? certified->curve : nullptr;
    // The legend says Fᵏ(X₀) (named in applyAnalysis: no Qt string on the worker, whose copy
    // would be released at the thread's exit while Qt Charts frees the shared text on the GUI
    // thread, an order ThreadSanitizer cannot see inside the uninstrumented Qt); what it is
    // measured against goes to the chart's tooltip.
    m_charts->setDistanceReference(certified ? tr("Fᵏ(X₀) to the %1").arg(certified->label)
                                             : QString());
    // A flame's maps are not the affine parts whose IFS `d` holds: nothing of theirs measured.
    const bool flame = bool(d->chaos);
    const std::string flameNote = flameBoxDimensionNote().toStdString();
    m_worker = std::thread([this, d, start, scheme, P, exact, curve, maxDepth, ticket, flame,
                            flameNote] {
        lowerThisThreadPriority(); // the pictures' workers first
        auto result = std::make_shared<AnalysisResult>();
        try {
            if (exact.rows() > 1)
                result->exactLength = polygonLength(exact);
            if (scheme && P.rows() > 0) {
                for (int k = 0; k <= 8 && !m_cancel; ++k) {
                    const Mat level = k == 0 ? P : subdivide(*scheme, P, k);
                    result->lengths.push_back(polygonLength(level));
                    if (level.rows() > 20000)
                        break;
                }
            }
            AnalysisCharts::DistanceSeries series;
            Mat deepest;
            for (int k = 0; k <= maxDepth && !m_cancel && !d->iterate && !flame; ++k) {
                if (imageCount(d->ifs, k) * double(std::max<Eigen::Index>(1, start.vertices.rows()))
                    > analysisImages)
                    break;
                deepest = planePoints(d->ifs, start, k, &m_cancel);
                if (curve && deepest.rows() > 0 && !m_cancel) {
                    // The midpoint of the certified bracket (relative width 1e-3).
                    HausdorffBracketOptions options;
                    options.cancel = &m_cancel;
                    const HausdorffBracket h = hausdorffBracket(deepest, *curve, options);
                    series.depth.push_back(k);
                    series.distance.push_back(h.value.mid());
                }
                m_inbox.post([this, k, maxDepth] {
                    emit analysisProgress(double(k + 1) / double(maxDepth + 2));
                });
            }
            if (!series.depth.empty())
                result->distances.append(series);
            if (d->subdivision && !d->A.real.empty()) {
                double rate = 0.0;
                for (const Mat &A : d->A.real)
                    rate = std::max(rate, spectrum(A).spectralRadius);
                result->rate = rate < 1.0 ? rate : 0.0;
            }
            if (flame)
                result->box.note = flameNote;
            else if (deepest.rows() >= 16 && !m_cancel)
                result->box = boxCountingDimension(deepest);
        } catch (const std::exception &e) {
            result->box.note = e.what();
        }
        result->cancelled = m_cancel;
        m_workerDone = true;
        // Moved: the GUI thread holds the only reference, so that the result (whose series
        // Qt Charts gets) is released there, not at this thread's exit.
        m_inbox.post([this, result = std::move(result), ticket] {
            if (ticket == m_analysisTicket)
                applyAnalysis(result);
        });
    });
}

void ItemController::applyAnalysis(const std::shared_ptr<AnalysisResult> &result)
{
    if (!result->cancelled) {
        QList<AnalysisCharts::DistanceSeries> distances = result->distances;
        for (auto &series : distances)
            series.name = tr("Fᵏ(X₀)");
        m_charts->setDistances(distances, result->rate);
        m_charts->setPolygonLengths(result->lengths, result->exactLength);
        m_charts->setBoxCounting(result->box);
    }
    emit analysisFinished(result->cancelled);
}

} // namespace awb
