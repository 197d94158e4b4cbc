#pragma once

#include "core/drive/drivetypes.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonObject>
#include <optional>

namespace dd {

class ParameterDictionary;
struct Metric;

// Text and JSON forms of the Drive API's value types, shared by the commands.
class CliDescribe
{
    Q_DECLARE_TR_FUNCTIONS(dd::Cli)
public:
    static QJsonObject identity(const DriveIdentity &id);
    static QJsonObject status(const DriveStatus &s);
    static QString statusText(const DriveStatus &s);
    static QJsonArray channels(const QList<ChannelInfo> &channels);
    static QJsonObject discovered(const DiscoveredDrive &d);
    static QString discoveredText(const DiscoveredDrive &d);
    // {"index", "key", "name", "unit"[, "value"]}
    static QJsonObject parameter(const ParameterDictionary &dict, int index, std::optional<qint64> value);
    // "  Name      value" rows with the names padded to one width.
    // "12.3 ms", "9.1 %", "—" for a metric without value; times with `msDecimals` decimals.
    static QString metric(const Metric &m, const QString &key, int msDecimals = 1);
    static QString table(const QList<QPair<QString, QString>> &rows);

    // Terminal columns of `text`: East Asian wide and fullwidth characters (Chinese) take
    // two, so that translated tables stay aligned.
    static int displayWidth(const QString &text);
    // `text` and spaces up to `width` columns: after it (left-aligned) or before it.
    static QString padRight(const QString &text, int width);
    static QString padLeft(const QString &text, int width);
};

} // namespace dd
