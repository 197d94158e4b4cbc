#pragma once

#include <QCoreApplication>
#include <QJsonValue>
#include <QList>
#include <QString>
#include <optional>

namespace dd {

// Strict parsing of the numbers and lists found on the command line. Each returns
// std::nullopt and a translated message naming `what` when the text does not fit.
class CliValues
{
    Q_DECLARE_TR_FUNCTIONS(dd::Cli)
public:
    // Decimal, or hexadecimal with 0x; an optional sign. No leading zeros read as octal.
    static std::optional<qint64> integer(const QString &text, qint64 min, qint64 max, const QString &what,
                                         QString *error);
    static std::optional<double> real(const QString &text, double min, double max, const QString &what, QString *error);
    // "9600,19200" → {9600, 19200}; empty items are an error.
    static std::optional<QList<qint64>> integerList(const QString &text, qint64 min, qint64 max, const QString &what,
                                                    QString *error);
    // "on" / "off" (also 1/0, true/false, yes/no).
    static std::optional<bool> onOff(const QString &text, const QString &what, QString *error);
    // The part of a capture before its trigger, the same for capture and step (--pre): a
    // percentage of the whole record ("25%", 0 to 99.9) or seconds ("0.1s", 0 to maxSeconds).
    // A bare number is refused: the unit must be spelled.
    struct PreTrigger
    {
        bool percent = false;
        double value = 0.0;
    };
    static std::optional<PreTrigger> preTrigger(const QString &text, double maxSeconds, QString *error);

    // A value that may be missing (a parameter absent from a file or a drive): the number, or
    // null in JSON and "-" in text.
    static QJsonValue json(const std::optional<qint64> &v);
    static QString text(const std::optional<qint64> &v);
};

} // namespace dd
