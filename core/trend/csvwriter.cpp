#include "core/trend/csvwriter.h"
#include "core/common/csvfield.h"

#include <QCoreApplication>
#include <QLocale>
#include <QSaveFile>
#include <cmath>
#include <limits>

namespace dd {

namespace {

Error fileError(const QString &message)
{
    return Error{ErrorCode::FileError, message, 0};
}

} // namespace

CsvWriter::CsvWriter() = default;

CsvWriter::~CsvWriter()
{
    close();
}

QByteArray CsvWriter::headerLine(const QList<TrendChannel> &channels)
{
    QByteArray line = "time_s";
    for (const TrendChannel &c : channels) {
        line += ',';
        line += csvField(c.unit.isEmpty() ? c.id : c.id + QStringLiteral(" [") + c.unit + QLatin1Char(']'));
    }
    line += '\n';
    return line;
}

QByteArray CsvWriter::formatTime(qint64 timeUs, qint64 originUs)
{
    // Difference in unsigned arithmetic so that no pair of times overflows.
    const bool negative = timeUs < originUs;
    const quint64 d = negative ? static_cast<quint64>(originUs) - static_cast<quint64>(timeUs)
                               : static_cast<quint64>(timeUs) - static_cast<quint64>(originUs);
    QByteArray frac = QByteArray::number(d % 1000000u);
    frac.prepend(QByteArray(6 - frac.size(), '0'));
    return (negative ? "-" : "") + QByteArray::number(d / 1000000u) + '.' + frac;
}

QByteArray CsvWriter::formatValue(double value)
{
    if (std::isnan(value))
        return "nan";
    if (std::isinf(value))
        return value > 0 ? "inf" : "-inf";
    if (value == 0.0)
        return "0"; // also for -0
    const double mag = std::fabs(value);
    const char format = mag >= 1e-6 && mag < 1e15 ? 'f' : 'g';
    return QByteArray::number(value, format, QLocale::FloatingPointShortest);
}

QByteArray CsvWriter::rowLine(qint64 timeUs, qint64 originUs, const QList<std::optional<double>> &values)
{
    QByteArray line = formatTime(timeUs, originUs);
    for (const auto &v : values) {
        line += ',';
        if (v)
            line += formatValue(*v);
    }
    line += '\n';
    return line;
}

QByteArray CsvWriter::toCsv(const TrendSnapshot &snapshot)
{
    const qsizetype n = snapshot.channels.size();
    QByteArray out = headerLine(snapshot.channels);
    // k-way merge of the per-channel series by time.
    QList<qsizetype> next(n, 0);
    QList<std::optional<double>> row(n);
    for (;;) {
        qint64 t = std::numeric_limits<qint64>::max();
        bool any = false;
        for (qsizetype c = 0; c < n && c < snapshot.series.size(); ++c) {
            const auto &s = snapshot.series.at(c);
            if (next[c] < s.size()) {
                t = std::min(t, s.at(next[c]).timeUs);
                any = true;
            }
        }
        if (!any)
            break;
        for (qsizetype c = 0; c < n; ++c) {
            row[c].reset();
            if (c >= snapshot.series.size())
                continue;
            const auto &s = snapshot.series.at(c);
            if (next[c] < s.size() && s.at(next[c]).timeUs == t)
                row[c] = s.at(next[c]++).value;
        }
        out += rowLine(t, snapshot.originUs, row);
    }
    return out;
}

Error CsvWriter::save(const QString &path, const TrendSnapshot &snapshot)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        return fileError(tr("Cannot write the CSV file %1: %2. Check that the folder exists "
                            "and is writable.")
                             .arg(path, file.errorString()));
    }
    const QByteArray text = toCsv(snapshot);
    if (file.write(text) != text.size() || !file.commit()) {
        return fileError(tr("Writing the CSV file %1 failed: %2. Is the disk full?").arg(path, file.errorString()));
    }
    return Error::none();
}

Error CsvWriter::open(const QString &path, const QList<TrendChannel> &channels, std::optional<qint64> originUs)
{
    close();
    m_file.setFileName(path);
    if (!m_file.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
        return fileError(tr("Cannot write the CSV file %1: %2. Check that the folder exists "
                            "and is writable.")
                             .arg(path, m_file.errorString()));
    }
    m_channels = channels;
    m_originUs = originUs;
    m_rows = 0;
    const Error e = writeBytes(headerLine(channels));
    if (e)
        m_file.close();
    return e;
}

Error CsvWriter::writeRow(qint64 timeUs, const QMap<QString, double> &values)
{
    QList<std::optional<double>> row(m_channels.size());
    for (qsizetype c = 0; c < m_channels.size(); ++c) {
        const auto it = values.constFind(m_channels.at(c).id);
        if (it != values.cend())
            row[c] = it.value();
    }
    return writeRow(timeUs, row);
}

Error CsvWriter::writeRow(qint64 timeUs, const QList<std::optional<double>> &values)
{
    if (!m_file.isOpen())
        return Error{ErrorCode::InvalidArgument, tr("The CSV file is not open."), 0};
    if (!m_originUs)
        m_originUs = timeUs;
    QList<std::optional<double>> row = values.mid(0, m_channels.size());
    row.resize(m_channels.size());
    const Error e = writeBytes(rowLine(timeUs, *m_originUs, row));
    if (!e)
        ++m_rows;
    return e;
}

Error CsvWriter::writeRowAtSeconds(double timeS, const QMap<QString, double> &values)
{
    if (!std::isfinite(timeS) || std::fabs(timeS) > 9.2e12) // beyond qint64 µs
        return Error{ErrorCode::InvalidArgument, tr("The sample time is not a valid number."), 0};
    return writeRow(static_cast<qint64>(std::llround(timeS * 1e6)), values);
}

Error CsvWriter::writeBytes(const QByteArray &bytes)
{
    if (m_file.write(bytes) != bytes.size() || !m_file.flush()) {
        return fileError(
            tr("Writing the CSV file %1 failed: %2. Is the disk full?").arg(m_file.fileName(), m_file.errorString()));
    }
    return Error::none();
}

Error CsvWriter::close()
{
    if (!m_file.isOpen())
        return Error::none();
    const bool ok = m_file.flush();
    const QString why = m_file.errorString();
    m_file.close();
    if (!ok) {
        return fileError(tr("Writing the CSV file %1 failed: %2. Is the disk full?").arg(m_file.fileName(), why));
    }
    return Error::none();
}

} // namespace dd
