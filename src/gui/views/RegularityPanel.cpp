#include "gui/views/RegularityPanel.h"

#include "core/schemes/Scheme.h"
#include "model/SchemeRegularity.h"
#include "model/SchemeSpec.h"

#include "core/analysis/Regularity.h"
#include "core/schemes/Scheme.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QToolButton>
#include <QVBoxLayout>

namespace awb {

namespace {
// "C^2" as a reader writes it: C², C^infinity as C^∞.
QString superscripted(const std::string &label)
{
    static const QString digits = QStringLiteral("⁰¹²³⁴⁵⁶⁷⁸⁹");
    const QString s = QString::fromStdString(label);
    const qsizetype caret = s.indexOf(QLatin1Char('^'));
    if (caret < 0)
        return s;
    const QString exponent = s.mid(caret + 1);
    if (exponent == QLatin1String("infinity"))
        return s.left(caret) + QStringLiteral("∞");
    QString out = s.left(caret);
    for (QChar c : exponent) {
        if (!c.isDigit())
            return s;
        out += digits.at(c.digitValue());
    }
    return out;
}
} // namespace

QString mathText(const QString &ascii)
{
    // The core writes its formulas in ASCII (they also go to attractor-cli's JSON): on screen
    // they read as the papers write them.
    static const QString subs = QStringLiteral("₀₁₂₃₄₅₆₇₈₉");
    static const QString sups = QStringLiteral("⁰¹²³⁴⁵⁶⁷⁸⁹");
    QString s = ascii;
    s.replace(QStringLiteral("rho_n"), QStringLiteral("ρₙ"));
    s.replace(QStringLiteral("rho("), QStringLiteral("ρ("));
    s.replace(QStringLiteral(" - "), QStringLiteral(" − "));
    s.replace(QStringLiteral(" .. "), QStringLiteral(" … "));
    s.replace(QStringLiteral("X0"), QStringLiteral("X₀"));
    s.replace(QStringLiteral("||"), QStringLiteral("‖"));
    s.replace(QStringLiteral(" <= "), QStringLiteral(" ≤ "));
    s.replace(QStringLiteral(" >= "), QStringLiteral(" ≥ "));
    s.replace(QStringLiteral(" * "), QStringLiteral(" · "));
    // ^{k+1} -> ᵏ⁺¹ where every character has a superscript (else left as written).
    static const QString supFrom = QStringLiteral("0123456789+-kn()");
    static const QString supTo = QStringLiteral("⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻ᵏⁿ⁽⁾");
    for (qsizetype at = s.indexOf(QStringLiteral("^{")); at >= 0;
         at = s.indexOf(QStringLiteral("^{"), at + 1)) {
        const qsizetype end = s.indexOf(QLatin1Char('}'), at);
        if (end < 0)
            break;
        QString sup;
        for (QChar c : s.mid(at + 2, end - at - 2)) {
            const qsizetype k = supFrom.indexOf(c);
            if (k < 0) {
                sup.clear();
                break;
            }
            sup += supTo.at(k);
        }
        if (!sup.isEmpty())
            s.replace(at, end - at + 1, sup);
    }
    // F^k: a letter exponent after a capital or a closing bracket.
    for (qsizetype at = s.indexOf(QStringLiteral("^k")); at >= 0;
         at = s.indexOf(QStringLiteral("^k"), at))
        s.replace(at, 2, QStringLiteral("ᵏ"));
    QString out;
    for (int i = 0; i < s.size(); ++i) {
        // log_2 -> log₂, z^3 -> z³, ^(1/k) -> ^(1/k) (left as it is: no superscript slash)
        if ((s[i] == QLatin1Char('_') || s[i] == QLatin1Char('^')) && i + 1 < s.size()
            && s[i + 1].isDigit()) {
            const QString &table = s[i] == QLatin1Char('_') ? subs : sups;
            ++i;
            while (i < s.size() && s[i].isDigit())
                out += table.at(s[i++].digitValue());
            --i;
            continue;
        }
        out += s[i];
    }
    return out;
}

QString regularityText(const Regularity &r)
{
    if (!r.applies || r.infinite || (r.divergent && r.transition.empty()))
        return QString::fromStdString(r.message);
    // Bounds equal to rounding are the exponent itself: "exact", not "width 2.4e-13".
    const bool exact = r.width() <= 1e-9 * std::max(1.0, std::abs(r.upper));
    QString text = r.exact ? QObject::tr("%1, Hölder regularity r = %2 (exact: invariant "
                                         "polytope, certificate)")
                                 .arg(superscripted(r.smoothnessLabel()))
                                 .arg(r.upper, 0, 'g', 12)
                   : exact ? QObject::tr("%1, Hölder regularity r = %2 (exact)")
                               .arg(superscripted(r.smoothnessLabel()))
                               .arg(r.upper, 0, 'g', 8)
                         : QObject::tr("%1, Hölder regularity r in [%2, %3] (width %4)")
                               .arg(superscripted(r.smoothnessLabel()))
                               .arg(r.lower, 0, 'g', 8)
                               .arg(r.upper, 0, 'g', 8)
                               .arg(r.width(), 0, 'g', 2);
    if (r.sobolev)
        text += QObject::tr("; Sobolev (L²) exponent s₂ = %1").arg(*r.sobolev, 0, 'g', 8);
    if (!r.notes.empty())
        text += QStringLiteral("; ") + QString::fromStdString(r.notes).trimmed();
    return text;
}

RegularityPanel::RegularityPanel(QWidget *parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("regularityPanel"));
    m_summary = new QLabel(tr("Regularity: no curve scheme"));
    m_summary->setObjectName(QStringLiteral("regularitySummary"));
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_method = new QLabel;
    m_method->setObjectName(QStringLiteral("regularityMethod"));
    m_method->setWordWrap(true);
    m_method->setTextInteractionFlags(Qt::TextSelectableByMouse);
    QFont small = m_method->font();
    small.setPointSizeF(small.pointSizeF() * 0.85);
    m_method->setFont(small);
    m_progress = new QProgressBar;
    m_progress->setRange(0, 100);
    m_progress->setMaximumWidth(140);
    m_progress->setFormat(tr("Regularity %p%"));
    m_progress->setVisible(false);
    m_cancel = new QToolButton;
    m_cancel->setObjectName(QStringLiteral("regularityCancel"));
    m_cancel->setText(tr("Cancel"));
    m_cancel->setToolTip(tr("Stop the regularity analysis; the bounds reached so far stay"));
    m_cancel->setVisible(false);
    connect(m_cancel, &QToolButton::clicked, this, &RegularityPanel::cancel);
    m_save = new QToolButton;
    m_save->setObjectName(QStringLiteral("regularitySaveCertificate"));
    m_save->setText(tr("Save Certificate…"));
    m_save->setToolTip(tr("The invariant polytope that proves the exponent, as JSON: "
                          "attractor-cli verify-regularity re-checks it without any search"));
    m_save->setVisible(false);
    connect(m_save, &QToolButton::clicked, this, &RegularityPanel::saveCertificateRequested);
    auto *row = new QHBoxLayout;
    row->addWidget(m_summary, 1);
    row->addWidget(m_progress);
    row->addWidget(m_cancel);
    row->addWidget(m_save);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 2, 4, 2);
    layout->addLayout(row);
    layout->addWidget(m_method);
}

RegularityPanel::~RegularityPanel() { m_worker.stop(); }

void RegularityPanel::cancel() { m_worker.cancel(); }

void RegularityPanel::showMessage(const QString &message)
{
    m_worker.bump();
    m_running = false;
    m_key.clear();
    m_summary->setText(message);
    m_method->clear();
    m_progress->setVisible(false);
    m_cancel->setVisible(false);
    m_save->setVisible(false);
    m_result.reset();
}

void RegularityPanel::analyse(const SchemeSpec &spec, int m, const QString &key)
{
    if (key == m_key && !key.isEmpty())
        return;
    m_worker.stop();
    m_key = key;
    m_running = true;
    QString name = SchemeSpec::kindNames().value(int(spec.kind));
    try {
        if (!spec.isComplex())
            name = QString::fromStdString(spec.makeScheme()->name());
    } catch (const std::exception &) {
    }
    m_summary->setText(tr("Regularity of %1: computing…").arg(name));
    m_method->clear();
    m_result.reset();
    m_save->setVisible(false);
    m_progress->setValue(0);
    m_progress->setVisible(true);
    m_cancel->setVisible(true);
    const double budget = m_budget;
    m_worker.start([this, spec, m, budget](const std::atomic<bool> *cancel, quint64 generation) {
        RegularityOptions o;
        o.timeBudget = budget;
        o.cancel = cancel;
        o.progress = [this, generation](double lo, double hi, double fraction) {
            m_worker.post([=, this] { showProgress(lo, hi, fraction, generation); });
        };
        const Regularity r = specRegularity(spec, m, o);
        m_worker.post([=, this] { showResult(r, generation); });
    });
}

void RegularityPanel::showProgress(double lower, double upper, double fraction, quint64 generation)
{
    if (!m_worker.isCurrent(generation) || !m_running)
        return;
    m_progress->setValue(int(100 * fraction));
    m_method->setText(tr("so far: r in [%1, %2]").arg(lower, 0, 'g', 8).arg(upper, 0, 'g', 8));
}

void RegularityPanel::showResult(const Regularity &r, quint64 generation)
{
    if (!m_worker.isCurrent(generation))
        return;
    m_running = false;
    m_progress->setVisible(false);
    m_cancel->setVisible(false);
    m_summary->setText(tr("Regularity: %1").arg(regularityText(r)));
    m_method->setText(mathText(QString::fromStdString(r.method)));
    m_result = std::make_shared<const Regularity>(r);
    m_save->setVisible(r.exact && r.certificate);
    emit finished();
}

QString RegularityPanel::summary() const { return m_summary->text(); }
QString RegularityPanel::method() const { return m_method->text(); }

} // namespace awb
