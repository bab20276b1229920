#pragma once
// Reads a Qt Linguist .ts file for the translation tests: every current message (vanished and
// obsolete ones are skipped) with its context, source, translation(s) and state.

#include <QFile>
#include <QList>
#include <QString>
#include <QStringList>
#include <QXmlStreamReader>

#include <algorithm>

namespace awb::test {

struct TsMessage {
    QString context;
    QString source;
    QString comment;            // the disambiguation
    QStringList translations;   // one, or one per plural form
    bool numerus = false;
    bool unfinished = false;    // type="unfinished" or an empty translation
};

inline QList<TsMessage> readTs(const QString &path, QString *error = nullptr)
{
    QList<TsMessage> out;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        if (error)
            *error = file.errorString();
        return out;
    }
    QXmlStreamReader xml(&file);
    QString context;
    TsMessage m;
    bool skip = false;
    while (!xml.atEnd()) {
        xml.readNext();
        if (xml.isStartElement()) {
            const auto name = xml.name();
            if (name == QLatin1String("name")) {
                context = xml.readElementText();
            } else if (name == QLatin1String("message")) {
                m = TsMessage{};
                m.context = context;
                m.numerus = xml.attributes().value(QLatin1String("numerus")) == QLatin1String("yes");
                skip = false;
            } else if (name == QLatin1String("source")) {
                m.source = xml.readElementText();
            } else if (name == QLatin1String("comment")) {
                m.comment = xml.readElementText();
            } else if (name == QLatin1String("translation")) {
                const QString type = xml.attributes().value(QLatin1String("type")).toString();
                skip = type == QLatin1String("vanished") || type == QLatin1String("obsolete");
                m.unfinished = type == QLatin1String("unfinished");
                if (!m.numerus)
                    m.translations = {xml.readElementText()};
            } else if (name == QLatin1String("numerusform")) {
                m.translations << xml.readElementText();
            }
        } else if (xml.isEndElement() && xml.name() == QLatin1String("message")) {
            if (!skip) {
                if (m.translations.isEmpty()
                    || std::any_of(m.translations.begin(), m.translations.end(),
                                   [](const QString &t) { return t.isEmpty(); }))
                    m.unfinished = true;
                out << m;
            }
            m = TsMessage{};
            skip = false;
        }
    }
    if (xml.hasError() && error)
        *error = xml.errorString();
    return out;
}

// The translation of `source` in `context` in `messages` (empty: none).
inline QString tsTranslation(const QList<TsMessage> &messages, const QString &context,
                             const QString &source)
{
    for (const TsMessage &m : messages)
        if (m.context == context && m.source == source && !m.translations.isEmpty())
            return m.translations.first();
    return {};
}

} // namespace awb::test
