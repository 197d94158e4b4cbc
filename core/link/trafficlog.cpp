#include "core/link/trafficlog.h"

#include "core/common/csvfield.h"

#include <QDateTime>
#include <QDir>
#include <QSaveFile>

namespace dd {

TrafficLog::Format TrafficLog::formatForPath(const QString &path)
{
    return path.endsWith(QLatin1String(".csv"), Qt::CaseInsensitive) ? Format::Csv : Format::Text;
}

QByteArray TrafficLog::csvHeader()
{
    return QByteArrayLiteral("time,time_us,link,direction,can_id,data,meaning,note\n");
}

QByteArray TrafficLog::csvLine(const Entry &entry)
{
    const TrafficRecord &r = entry.record;
    QDateTime when = QDateTime::fromMSecsSinceEpoch(r.wallclockMs);
    when = when.toOffsetFromUtc(when.offsetFromUtc()); // ISO text with the offset
    QByteArray line;
    line += when.toString(Qt::ISODateWithMs).toLatin1();
    line += ',';
    line += QByteArray::number(r.timestampUs);
    line += ',';
    line += csvField(r.link);
    line += ',';
    line += r.directionText().toLatin1();
    line += ',';
    if (r.isCan)
        line += QByteArray::number(r.canId, 16).toUpper().rightJustified(r.canExtended ? 8 : 3, '0');
    line += ',';
    line += r.bytes.toHex(' ').toUpper();
    line += ',';
    line += csvField(entry.meaning);
    line += ',';
    line += csvField(r.note);
    line += '\n';
    return line;
}

QByteArray TrafficLog::textLine(const Entry &entry)
{
    const TrafficRecord &r = entry.record;
    QString line = QDateTime::fromMSecsSinceEpoch(r.wallclockMs).toString(QStringLiteral("yyyy-MM-dd HH:mm:ss.zzz"));
    line += QLatin1String("  ") + r.link + QLatin1String("  ") + r.directionText().leftJustified(4)
        + QLatin1String("  ") + r.hexText();
    if (!entry.meaning.isEmpty())
        line += QLatin1String("  ") + entry.meaning;
    if (!r.note.isEmpty())
        line += QLatin1String("  [") + r.note + QLatin1Char(']');
    line.replace(QLatin1Char('\n'), QLatin1Char(' '));
    return line.toUtf8() + '\n';
}

QByteArray TrafficLog::toBytes(const QList<Entry> &entries, Format format)
{
    QByteArray out;
    if (format == Format::Csv)
        out += csvHeader();
    for (const Entry &e : entries)
        out += format == Format::Csv ? csvLine(e) : textLine(e);
    return out;
}

Error TrafficLog::save(const QString &path, const QList<Entry> &entries)
{
    const QByteArray bytes = toBytes(entries, formatForPath(path));
    const QString shown = QDir::toNativeSeparators(path);
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return {
            ErrorCode::FileError,
            tr("Cannot write %1: %2. Is the folder writable and the disk not full?").arg(shown, file.errorString())};
    // Qt 6.4's QSaveFile::commit() ignores a failed flush: flush and check first.
    if (file.write(bytes) != bytes.size() || !file.flush()) {
        const QString why = file.errorString();
        file.cancelWriting();
        return {ErrorCode::FileError,
                tr("Cannot write %1: %2. The previous file, if any, is unchanged.").arg(shown, why)};
    }
    if (!file.commit())
        return {ErrorCode::FileError,
                tr("Cannot write %1: %2. The previous file, if any, is unchanged.").arg(shown, file.errorString())};
    return Error::none();
}

} // namespace dd
