#pragma once

#include "common/error.h"
#include "drive/drivetypes.h"

#include <QCoreApplication>
#include <QFile>
#include <QMap>
#include <QTextStream>
#include <memory>

namespace dd {

// Writes sampled channels as CSV: a header row "time [s],speed [r/min],..." (channel ids
// with their units), then one row per sample, time in seconds since the start. Rows are
// flushed as they come, so an interrupted recording keeps everything up to the last
// sample. A channel missing from a sample leaves its cell empty. Decimal point always '.'.
class CsvTrendWriter
{
    Q_DECLARE_TR_FUNCTIONS(dd::CsvTrendWriter)
public:
    CsvTrendWriter() = default;
    ~CsvTrendWriter();

    Error open(const QString &path, const QList<ChannelInfo> &channels);
    // Replaces the channels (their header) of a file opened but not yet written to.
    Error setChannels(const QList<ChannelInfo> &channels);
    Error writeRow(double timeS, const QMap<QString, double> &values);
    Error close();
    bool isOpen() const { return m_file.isOpen(); }
    QString path() const { return m_file.fileName(); }
    qint64 rowCount() const { return m_rows; }

    static QString headerCell(const ChannelInfo &channel);   // "speed [r/min]"
    static QString quoted(const QString &cell);              // RFC 4180 quoting when needed

private:
    Error writeHeader();
    Error streamError() const;

    QFile m_file;
    QList<ChannelInfo> m_channels;
    qint64 m_rows = 0;
    bool m_headerWritten = false;
};

} // namespace dd
