#include "model/RegularityCertificate.h"

#include "core/analysis/InvariantPolytope.h"
#include "core/schemes/Scheme.h"
#include "model/ProjectIO.h"
#include "model/SchemeRegularity.h"
#include "model/SchemeSpec.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>

namespace awb {

namespace {

struct CertificateTr {
    Q_DECLARE_TR_FUNCTIONS(awb::RegularityCertificate)
};

const QString kFormat = QStringLiteral("awb-regularity-certificate");

// A refusal with its reason; caught in verifyRegularityCertificate.
struct Rejected {
    QString message;
};

double numberAt(const QJsonValue &v, const QString &where)
{
    if (!v.isDouble() || !std::isfinite(v.toDouble()))
        throw Rejected{CertificateTr::tr("%1 is not a finite number").arg(where)};
    return v.toDouble();
}

int indexAt(const QJsonValue &v, const QString &where)
{
    const double d = numberAt(v, where);
    if (d != std::floor(d) || d < 0 || d > 1e6)
        throw Rejected{CertificateTr::tr("%1 is not an index").arg(where)};
    return int(d);
}

QJsonArray arrayAt(const QJsonObject &o, const QString &key, const QString &where)
{
    if (!o.value(key).isArray())
        throw Rejected{CertificateTr::tr("%1 has no array \"%2\"").arg(where, key)};
    return o.value(key).toArray();
}

Vec vectorAt(const QJsonValue &v, const QString &where)
{
    const QJsonArray a = v.toArray();
    if (!v.isArray())
        throw Rejected{CertificateTr::tr("%1 is not an array of numbers").arg(where)};
    Vec x(a.size());
    for (qsizetype k = 0; k < a.size(); ++k)
        x(k) = numberAt(a[k], QStringLiteral("%1[%2]").arg(where).arg(k + 1));
    return x;
}

PolytopeCertificate polytopeFrom(const QJsonObject &p)
{
    if (p.value("format").toString() != QStringLiteral("awb-invariant-polytope"))
        throw Rejected{CertificateTr::tr("\"polytope\" is not an awb-invariant-polytope object")};
    PolytopeCertificate c;
    const QJsonArray matrices = arrayAt(p, "matrices", "polytope");
    for (qsizetype i = 0; i < matrices.size(); ++i) {
        const QJsonArray rows = matrices[i].toArray();
        Mat A(rows.size(), rows.size());
        for (qsizetype r = 0; r < rows.size(); ++r) {
            const Vec row = vectorAt(rows[r], QStringLiteral("polytope.matrices[%1][%2]")
                                                  .arg(i + 1)
                                                  .arg(r + 1));
            if (row.size() != rows.size())
                throw Rejected{CertificateTr::tr("polytope.matrices[%1] is not square").arg(i + 1)};
            A.row(r) = row.transpose();
        }
        c.matrices.push_back(A);
    }
    for (const QJsonValue &v : arrayAt(p, "smp", "polytope"))
        c.smp.push_back(indexAt(v, "polytope.smp"));
    c.rhoHat = numberAt(p.value("rhoHat"), "polytope.rhoHat");
    const QJsonArray vertices = arrayAt(p, "vertices", "polytope");
    for (qsizetype j = 0; j < vertices.size(); ++j)
        c.vertices.push_back(
            vectorAt(vertices[j], QStringLiteral("polytope.vertices[%1]").arg(j + 1)));
    const QJsonArray lambda = arrayAt(p, "lambda", "polytope");
    for (qsizetype j = 0; j < lambda.size(); ++j) {
        std::vector<std::vector<std::pair<int, double>>> perMap;
        for (const QJsonValue &map : lambda[j].toArray()) {
            std::vector<std::pair<int, double>> terms;
            for (const QJsonValue &term : map.toArray()) {
                const QJsonArray pair = term.toArray();
                if (pair.size() != 2)
                    throw Rejected{CertificateTr::tr("polytope.lambda[%1] holds a term that is not "
                                      "[index, coefficient]")
                                       .arg(j + 1)};
                terms.emplace_back(indexAt(pair[0], "polytope.lambda"),
                                   numberAt(pair[1], "polytope.lambda"));
            }
            perMap.push_back(std::move(terms));
        }
        c.lambda.push_back(std::move(perMap));
    }
    return c;
}

// The matrices whose JSR gives the scheme's exponent, and the shift and cap of
// r = shift - log_N rho: derived from the scheme by the analysis itself with no time for a
// search (the transition matrices are plain linear algebra).
Regularity derivedMatrices(const SchemeSpec &spec)
{
    RegularityOptions o;
    o.timeBudget = 1e-6;
    o.polytopeBudget = 0.0;
    const int m = spec.kind == SchemeSpec::Kind::Matrices && !spec.matrices.empty()
                      ? int(spec.matrices.front().rows())
                      : 0;
    return specRegularity(spec, m, o);
}

bool isUniform(const SchemeSpec &spec)
{
    return spec.kind != SchemeSpec::Kind::Matrices && spec.kind != SchemeSpec::Kind::Bezier
           && spec.kind != SchemeSpec::Kind::EndInterpolatingBSpline;
}

} // namespace

QByteArray regularityCertificate(const SchemeSpec &scheme, const Regularity &r, QString *error)
{
    if (!r.exact || !r.certificate) {
        if (error)
            *error = CertificateTr::tr("the regularity is not exact: no invariant polytope closed, so there is "
                        "no certificate (%1)")
                         .arg(QString::fromStdString(r.polytopeNote));
        return {};
    }
    const QJsonObject polytope =
        QJsonDocument::fromJson(QByteArray::fromStdString(certificateJson(*r.certificate)))
            .object();
    QJsonArray smp;
    for (int i : r.smp)
        smp.append(i);
    const bool uniform = isUniform(scheme);
    const QJsonObject root{{"format", kFormat},
                           {"version", 1},
                           {"scheme", scheme.toJson()},
                           {"arity", r.arity},
                           {"shift", uniform ? r.sumRules : 0},
                           {"cap", uniform ? double(r.sumRules) : r.upper},
                           {"holder", QJsonObject{{"lower", r.lower}, {"upper", r.upper}}},
                           {"smp", smp},
                           {"polytope", polytope}};
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

CertificateCheck verifyRegularityCertificate(const QByteArray &json)
{
    CertificateCheck out;
    try {
        QJsonParseError parse;
        const QJsonDocument doc = QJsonDocument::fromJson(json, &parse);
        if (parse.error != QJsonParseError::NoError || !doc.isObject())
            throw Rejected{CertificateTr::tr("not JSON: %1 at offset %2")
                               .arg(parse.errorString())
                               .arg(parse.offset)};
        const QJsonObject root = doc.object();
        if (root.value("format").toString() != kFormat || root.value("version").toInt() != 1)
            throw Rejected{CertificateTr::tr("not an attractor-workbench regularity certificate (format %1, "
                              "version 1)")
                               .arg(kFormat)};
        // The scheme, read as a project's item reads it, and its matrices derived anew.
        SchemeSpec spec;
        try {
            spec = SchemeSpec::fromJson(FieldReader(root.value("scheme").toObject(),
                                                    QStringLiteral("scheme.")));
        } catch (const LoadError &e) {
            throw Rejected{QStringLiteral("%1: %2").arg(e.field, e.message)};
        }
        out.scheme = QString::fromStdString(spec.makeScheme()->name());
        const Regularity derived = derivedMatrices(spec);
        if (!derived.applies || derived.transition.empty())
            throw Rejected{CertificateTr::tr("the scheme has no difference scheme to certify: %1")
                               .arg(QString::fromStdString(derived.message))};
        const PolytopeCertificate cert = polytopeFrom(root.value("polytope").toObject());
        if (cert.matrices.size() != derived.transition.size())
            throw Rejected{CertificateTr::tr("the certificate has %1 matrices, the scheme's analysis %2")
                               .arg(cert.matrices.size())
                               .arg(derived.transition.size())};
        for (size_t i = 0; i < cert.matrices.size(); ++i) {
            const Mat &T = derived.transition[i];
            if (cert.matrices[i].rows() != T.rows()
                || (cert.matrices[i] - T).cwiseAbs().maxCoeff()
                       > 1e-12 * std::max(1.0, T.cwiseAbs().maxCoeff()))
                throw Rejected{CertificateTr::tr("matrix %1 of the certificate is not the scheme's (the "
                                  "transition matrix T_%2 of its difference scheme)")
                                   .arg(i + 1)
                                   .arg(i)};
        }
        const int N = derived.arity;
        const bool uniform = isUniform(spec);
        const double shift = uniform ? derived.sumRules : 0.0;
        const double cap = uniform ? derived.sumRules : numberAt(root.value("cap"), "cap");
        if (root.value("arity").toInt() != N || root.value("shift").toDouble() != shift)
            throw Rejected{CertificateTr::tr("arity %1 and shift %2 do not match the scheme's (%3 and %4)")
                               .arg(root.value("arity").toInt())
                               .arg(root.value("shift").toDouble())
                               .arg(N)
                               .arg(shift)};
        // The polytope itself.
        const PolytopeVerdict v = verifyPolytopeCertificate(cert);
        if (!v.ok)
            throw Rejected{QString::fromStdString(v.message)};
        out.smp = cert.smp;
        out.jsrLower = v.lower;
        out.jsrUpper = v.upper;
        const double logN = std::log(double(N));
        out.lower = std::min(cap, v.upper > 0 ? shift - std::log(v.upper) / logN : cap);
        out.upper = std::min(cap, v.lower > 0 ? shift - std::log(v.lower) / logN : cap);
        // The claim: what is proved must lie inside it.
        const QJsonObject holder = root.value("holder").toObject();
        const double lo = numberAt(holder.value("lower"), "holder.lower");
        const double hi = numberAt(holder.value("upper"), "holder.upper");
        const double tol = 1e-9 * std::max(1.0, std::abs(out.upper));
        if (lo > out.lower + tol || hi < out.upper - tol)
            throw Rejected{CertificateTr::tr("the claimed Hölder exponent [%1, %2] is not what the polytope "
                              "proves: [%3, %4]")
                               .arg(lo, 0, 'g', 15)
                               .arg(hi, 0, 'g', 15)
                               .arg(out.lower, 0, 'g', 15)
                               .arg(out.upper, 0, 'g', 15)};
        out.ok = true;
        out.message = CertificateTr::tr("certificate verified: the Hölder exponent of the %1 lies in "
                         "[%2, %3]; JSR in [%4, %5]")
                          .arg(out.scheme)
                          .arg(out.lower, 0, 'g', 15)
                          .arg(out.upper, 0, 'g', 15)
                          .arg(out.jsrLower, 0, 'g', 15)
                          .arg(out.jsrUpper, 0, 'g', 15);
    } catch (const Rejected &r) {
        out.ok = false;
        out.message = CertificateTr::tr("certificate rejected: %1").arg(r.message);
    } catch (const InputError &e) {
        out.ok = false;
        out.message = CertificateTr::tr("certificate rejected: %1").arg(QString::fromStdString(e.what()));
    }
    return out;
}

} // namespace awb
