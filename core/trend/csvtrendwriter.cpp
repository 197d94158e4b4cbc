#include "trend/csvtrendwriter.h"

namespace dd {

CsvTrendWriter::~CsvTrendWriter()
{
    close();
}

QString CsvTrendWriter::quoted(const QString &cell)
{
    if (!cell.contains(QLatin1Char(',')) && !cell.contains(QLatin1Char('"'))
        && !cell.contains(QLatin1Char('\n')) && !cell.contains(QLatin1Char('\r')))
        return cell;
    QString q = cell;
    q.replace(QLatin1Char('"'), QLatin1String("\"\""));
    return QLatin1Char('"') + q + QLatin1Char('"');
}

QString CsvTrendWriter::headerCell(const ChannelInfo &channel)
{
    return channel.unit.isEmpty() ? channel.id : QStringLiteral("%1 [%2]").arg(channel.id, channel.unit);
}

Error CsvTrendWriter::open(const QString &path, const QList<ChannelInfo> &channels)
{
    close();
    m_file.setFileName(path);
    if (!m_file.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Text))
        return {ErrorCode::FileError,
                tr("Cannot write %1: %2. Check the folder exists and is writable.")
                    .arg(path, m_file.errorString())};
    m_channels = channels;
    m_rows = 0;
    m_headerWritten = false;
    return {};
}

Error CsvTrendWriter::setChannels(const QList<ChannelInfo> &channels)
{
    if (m_headerWritten)
        return {ErrorCode::InvalidArgument, tr("The CSV header of %1 is already written.").arg(path())};
    m_channels = channels;
    return {};
}

Error CsvTrendWriter::streamError() const
{
    return {ErrorCode::FileError, tr("Writing %1 failed: %2 (disk full?).").arg(path(), m_file.errorString())};
}

Error CsvTrendWriter::writeHeader()
{
    QStringList cells{QStringLiteral("time [s]")};
    for (const ChannelInfo &c : m_channels)
        cells << quoted(headerCell(c));
    const QByteArray line = cells.join(QLatin1Char(',')).toUtf8() + '\n';
    if (m_file.write(line) != line.size())
        return streamError();
    m_headerWritten = true;
    return {};
}

Error CsvTrendWriter::writeRow(double timeS, const QMap<QString, double> &values)
{
    if (!m_file.isOpen())
        return {ErrorCode::FileError, tr("The CSV file is not open.")};
    if (!m_headerWritten) {
        if (Error e = writeHeader())
            return e;
    }
    QStringList cells{QString::number(timeS, 'f', 6)};
    for (const ChannelInfo &c : m_channels) {
        const auto it = values.constFind(c.id);
        cells << (it == values.constEnd() ? QString() : QString::number(*it, 'f', qBound(0, c.decimals, 9)));
    }
    const QByteArray line = cells.join(QLatin1Char(',')).toUtf8() + '\n';
    if (m_file.write(line) != line.size() || !m_file.flush())
        return streamError();
    ++m_rows;
    return {};
}

Error CsvTrendWriter::close()
{
    if (!m_file.isOpen())
        return {};
    Error e;
    if (!m_headerWritten)
        e = writeHeader();
    if (!m_file.flush() && !e)
        e = streamError();
    m_file.close();
    return e;
}

} // namespace dd
