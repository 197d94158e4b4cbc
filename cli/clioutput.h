#pragma once

#include "core/common/error.h"

#include <QCoreApplication>
#include <QJsonObject>
#include <QString>
#include <QTextStream>

namespace dd {

struct TrafficRecord;

// Where the CLI's words go. Results go to stdout: text, or with --json one compact JSON
// document per command (one per line for monitor). Progress, warnings, errors and the
// --trace frames go to stderr, so stdout stays parseable.
class CliOutput
{
    Q_DECLARE_TR_FUNCTIONS(dd::Cli)
public:
    explicit CliOutput(bool json = false);

    bool isJson() const { return m_json; }
    void setJson(bool json) { m_json = json; }

    // The result of a command: `json` in JSON mode, `text` (may be several lines) otherwise.
    void result(const QJsonObject &json, const QString &text);
    void line(const QString &text);         // stdout, text mode only
    void jsonLine(const QJsonObject &json); // stdout, always
    void note(const QString &text);         // stderr, "drivedesk-cli: ..."
    // A failed command: the message on stderr; in JSON mode also a document on stdout
    // {"command", "ok": false, "exitCode", "error": {"code", "message"}} merged into `partial`.
    void failure(const QString &command, int exitCode, const Error &error, const QJsonObject &partial = {});
    void trace(const TrafficRecord &record); // stderr, one timestamped line per frame

    static QJsonObject errorJson(const Error &error);

private:
    QTextStream m_out;
    QTextStream m_err;
    bool m_json = false;
};

} // namespace dd
