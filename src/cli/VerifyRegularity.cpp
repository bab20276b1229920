// attractor-cli verify-regularity: re-checks the certificate of an exact Hölder exponent
// (`analyse --item NAME --json --certificate FILE`, the Analysis dock's Save Certificate)
// without any search: the scheme's matrices derived anew, the invariant polytope verified map
// by map and vertex by vertex, the claimed exponent compared with what it proves
// (model/RegularityCertificate). Exit 0: verified; 1: rejected, with the first reason.

#include "cli/CommandSupport.h"
#include "cli/ProjectCommands.h"

#include "model/RegularityCertificate.h"

#include <QCommandLineParser>
#include <QFile>
#include <QJsonArray>
#include <QJsonObject>

namespace awb::cli {

int verifyRegularity(const QStringList &args)
{
    return guarded([&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(CliTr::tr(
            "Re-check the certificate of an exact Hölder exponent, independently of the search "
            "that found it."));
        parser.addPositionalArgument("certificate", CliTr::tr("The certificate (.json)."));
        parser.addOptions({{"json", CliTr::tr("Print JSON instead of text.")}});
        parseOrFail(parser, args, 1);
        const QString file = parser.positionalArguments().first();
        QFile in(file);
        if (!in.open(QIODevice::ReadOnly))
            throw Failure{CliTr::tr("%1: %2").arg(file, in.errorString())};
        if (in.size() > 64ll * 1024 * 1024)
            throw Failure{CliTr::tr("%1: larger than 64 MiB, not a certificate").arg(file)};
        const CertificateCheck c = verifyRegularityCertificate(in.readAll());
        if (parser.isSet("json")) {
            QJsonArray smp;
            for (int i : c.smp)
                smp.append(i);
            QJsonObject o{{"ok", c.ok}, {"message", c.message}};
            if (c.ok) {
                o["holder"] = QJsonObject{{"lower", c.lower}, {"upper", c.upper}};
                o["jsr"] = QJsonObject{{"lower", c.jsrLower}, {"upper", c.jsrUpper}};
                o["smp"] = smp;
                o["scheme"] = c.scheme;
            }
            printJson(o);
        } else {
            (c.ok ? out() : err()) << file << ": " << c.message << "\n";
        }
        return c.ok ? 0 : 1;
    });
}

} // namespace awb::cli
