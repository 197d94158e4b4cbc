#pragma once

#include "core/common/error.h"
#include "core/trend/trendchannel.h"
#include "core/trend/trendsnapshot.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QFile>
#include <QList>
#include <QMap>
#include <optional>

namespace dd {

// Trend recordings as CSV, for the GUI's export and the CLI's `monitor -o FILE.csv`.
//
// Format (UTF-8 without BOM, LF line ends, comma separator, '.' decimal point whatever
// the locale):
//   time_s,speed [r/min],torque [%],bus-voltage [V]
//   0.000000,1500,12.5,311
//   0.010000,1502,,311.5
// - Header: `time_s`, then per channel `<id> [<unit>]`, or just `<id>` when the unit is
//   empty. A field containing a comma, a quote or a line break is quoted ("" for "):
//   csvField() in core/common/csvfield.h.
// - One row per sample time. Rows are merged in time order over all channels; channels
//   sampled at the same time (one reading of the drive) share a row, and a channel
//   without a sample at a row's time has an empty cell. A channel with two samples at the
//   same time gives two rows with that time.
// - time_s is (time - origin) in seconds with exactly six decimals (µs resolution),
//   computed in integers, so it is exact; negative before the origin.
// - Values use the shortest text that reads back to the same double: plain decimals for
//   0 and magnitudes in [1e-6, 1e15) ("1500", "0.1", "-2.5"), exponent form otherwise
//   ("1e+20"); non-finite values are written "nan", "inf", "-inf".
// - A gap in a recording (TrendRecorder::appendGap(): link lost, drive silent, recording
//   stopped) is a row whose cells are "nan" at the time the gap began: spreadsheet and
//   plotting tools (pandas, gnuplot, matplotlib) break the line there instead of joining
//   the samples either side. Empty cells still mean "not sampled in this reading".
//
// Two ways to write:
// - save(): a whole snapshot, atomically (QSaveFile: the file appears complete or not at
//   all, an existing file is replaced only on success).
// - open() / writeRow() / close(): streaming for long recordings. The header is written at
//   open() and every row is flushed to the operating system as it is written, so an
//   interrupted recording leaves a valid file with every row written so far. Not atomic by
//   design: an existing file at the path is truncated at open().
class CsvWriter
{
    Q_DECLARE_TR_FUNCTIONS(dd::CsvWriter)
public:
    CsvWriter();
    ~CsvWriter(); // closes
    CsvWriter(const CsvWriter &) = delete;
    CsvWriter &operator=(const CsvWriter &) = delete;

    // Pieces of the format (each line ends with '\n').
    static QByteArray headerLine(const QList<TrendChannel> &channels);
    static QByteArray rowLine(qint64 timeUs, qint64 originUs, const QList<std::optional<double>> &values);
    static QByteArray formatTime(qint64 timeUs, qint64 originUs);
    static QByteArray formatValue(double value);

    // The whole text of a snapshot.
    static QByteArray toCsv(const TrendSnapshot &snapshot);
    // Writes toCsv(snapshot) to `path` atomically.
    static Error save(const QString &path, const TrendSnapshot &snapshot);

    // Streaming. originUs: time zero of the time_s column; when not given, the time of the
    // first row written.
    Error open(const QString &path, const QList<TrendChannel> &channels, std::optional<qint64> originUs = std::nullopt);
    bool isOpen() const { return m_file.isOpen(); }
    QString path() const { return m_file.fileName(); }
    qint64 rowCount() const { return m_rows; }
    // One row: values by channel id (ids not opened with are ignored, missing ones are
    // empty cells), e.g. DriveReply::samples() at DriveReply::sampleTimeUs().
    Error writeRow(qint64 timeUs, const QMap<QString, double> &values);
    // One row: values in channel order (nullopt = empty cell); extra values are ignored.
    Error writeRow(qint64 timeUs, const QList<std::optional<double>> &values);
    // One row at a time in seconds on the same clock (rounded to the µs), for samplers
    // that count seconds since their start: open(path, channels, 0) then this.
    Error writeRowAtSeconds(double timeS, const QMap<QString, double> &values);
    Error close();

private:
    Error writeBytes(const QByteArray &bytes);

    QFile m_file;
    QList<TrendChannel> m_channels;
    std::optional<qint64> m_originUs;
    qint64 m_rows = 0;
};

} // namespace dd
