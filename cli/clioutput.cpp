#include "cli/clioutput.h"

#include "core/link/trafficrecord.h"

#include <QJsonDocument>
#include <cstdio>

namespace dd {

CliOutput::CliOutput(bool json)
    : m_out(stdout)
    , m_err(stderr)
    , m_json(json)
{
    m_out.setEncoding(QStringConverter::Utf8);
    m_err.setEncoding(QStringConverter::Utf8);
}

void CliOutput::result(const QJsonObject &json, const QString &text)
{
    if (m_json)
        jsonLine(json);
    else if (!text.isEmpty())
        line(text);
}

void CliOutput::line(const QString &text)
{
    if (m_json)
        return;
    m_out << text;
    if (!text.endsWith(QLatin1Char('\n')))
        m_out << '\n';
    m_out.flush();
}

void CliOutput::jsonLine(const QJsonObject &json)
{
    m_out << QString::fromUtf8(QJsonDocument(json).toJson(QJsonDocument::Compact)) << '\n';
    m_out.flush();
}

void CliOutput::note(const QString &text)
{
    m_err << "drivedesk-cli: " << text;
    if (!text.endsWith(QLatin1Char('\n')))
        m_err << '\n';
    m_err.flush();
}

QJsonObject CliOutput::errorJson(const Error &error)
{
    QJsonObject e{{QStringLiteral("code"), errorCodeName(error.code)}, {QStringLiteral("message"), error.message}};
    if (error.driveCode)
        e.insert(QStringLiteral("driveCode"), error.driveCode);
    return e;
}

void CliOutput::failure(const QString &command, int exitCode, const Error &error, const QJsonObject &partial)
{
    note(error.message.isEmpty() ? errorCodeName(error.code) : error.message);
    if (!m_json)
        return;
    QJsonObject doc = partial;
    if (!command.isEmpty())
        doc.insert(QStringLiteral("command"), command);
    doc.insert(QStringLiteral("ok"), false);
    doc.insert(QStringLiteral("exitCode"), exitCode);
    doc.insert(QStringLiteral("error"), errorJson(error));
    jsonLine(doc);
}

void CliOutput::trace(const TrafficRecord &r)
{
    m_err << QStringLiteral("%1 %2 %3 %4")
                 .arg(double(r.timestampUs) / 1e6, 12, 'f', 6)
                 .arg(r.directionText(), -4)
                 .arg(r.link, r.hexText());
    if (!r.note.isEmpty())
        m_err << "  (" << r.note << ')';
    m_err << '\n';
    m_err.flush();
}

} // namespace dd
