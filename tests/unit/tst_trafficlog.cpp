// TrafficLog: the frame monitor's saved files (CSV and text), written atomically.
#include "core/link/trafficlog.h"

#include <QDateTime>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace dd;

namespace {
TrafficLog::Entry serialEntry()
{
    TrafficLog::Entry e;
    e.record.wallclockMs = QDateTime(QDate(2024, 5, 1), QTime(12, 34, 56, 789)).toMSecsSinceEpoch();
    e.record.timestampUs = 1500123;
    e.record.direction = TrafficRecord::Direction::Tx;
    e.record.link = QStringLiteral("/dev/ttyUSB0");
    e.record.bytes = QByteArray::fromHex("010300640014041A");
    e.meaning = QStringLiteral("#1 read PA0–PA19");
    return e;
}

TrafficLog::Entry canEntry()
{
    TrafficLog::Entry e;
    e.record.wallclockMs = QDateTime(QDate(2024, 5, 1), QTime(12, 34, 57, 5)).toMSecsSinceEpoch();
    e.record.timestampUs = 2500000;
    e.record.direction = TrafficRecord::Direction::Rx;
    e.record.link = QStringLiteral("virtualcan:can0");
    e.record.isCan = true;
    e.record.canId = 0x65;
    e.record.bytes = QByteArray::fromHex("011088D2040000FF");
    e.record.note = QStringLiteral("late, \"retry\" 2");
    e.meaning = QStringLiteral("#1 heartbeat: idle, position 1234");
    return e;
}
} // namespace

class TestTrafficLog : public QObject
{
    Q_OBJECT

private slots:
    void formatByName()
    {
        QCOMPARE(TrafficLog::formatForPath(QStringLiteral("a.csv")), TrafficLog::Format::Csv);
        QCOMPARE(TrafficLog::formatForPath(QStringLiteral("A.CSV")), TrafficLog::Format::Csv);
        QCOMPARE(TrafficLog::formatForPath(QStringLiteral("a.txt")), TrafficLog::Format::Text);
        QCOMPARE(TrafficLog::formatForPath(QStringLiteral("a.csv.log")), TrafficLog::Format::Text);
    }

    void csvLines()
    {
        QCOMPARE(TrafficLog::csvHeader(), QByteArray("time,time_us,link,direction,can_id,data,meaning,note\n"));
        const QByteArray serial = TrafficLog::csvLine(serialEntry());
        const QList<QByteArray> f = serial.trimmed().split(',');
        QCOMPARE(f.size(), 8);
        QVERIFY2(f.at(0).startsWith("2024-05-01T12:34:56.789"), f.at(0).constData());
        QCOMPARE(QDateTime::fromString(QString::fromLatin1(f.at(0)), Qt::ISODateWithMs).toMSecsSinceEpoch(),
                 serialEntry().record.wallclockMs);
        QCOMPARE(serial.mid(serial.indexOf(",1500123,")),
                 QByteArray(",1500123,/dev/ttyUSB0,TX,,01 03 00 64 00 14 04 1A,#1 read PA0–PA19,\n"));
        const QByteArray can = TrafficLog::csvLine(canEntry());
        QCOMPARE(can.mid(can.indexOf(",2500000,")),
                 QByteArray(",2500000,virtualcan:can0,RX,065,01 10 88 D2 04 00 00 FF,"
                            "\"#1 heartbeat: idle, position 1234\",\"late, \"\"retry\"\" 2\"\n"));
    }

    void extendedCanId()
    {
        TrafficLog::Entry e = canEntry();
        e.record.canExtended = true;
        e.record.canId = 0x1ABCDE;
        QVERIFY(TrafficLog::csvLine(e).contains(",RX,001ABCDE,"));
    }

    void textLines()
    {
        QCOMPARE(
            TrafficLog::textLine(serialEntry()),
            QByteArray("2024-05-01 12:34:56.789  /dev/ttyUSB0  TX    01 03 00 64 00 14 04 1A  #1 read PA0–PA19\n"));
        QCOMPARE(TrafficLog::textLine(canEntry()),
                 QByteArray("2024-05-01 12:34:57.005  virtualcan:can0  RX    065#01 10 88 D2 04 00 00 FF  "
                            "#1 heartbeat: idle, position 1234  [late, \"retry\" 2]\n"));
    }

    void saveBothFormats()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QList<TrafficLog::Entry> entries{serialEntry(), canEntry()};
        const QString csv = dir.filePath(QStringLiteral("t.csv"));
        QVERIFY(!TrafficLog::save(csv, entries));
        QFile f(csv);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), TrafficLog::toBytes(entries, TrafficLog::Format::Csv));
        f.close();
        const QString txt = dir.filePath(QStringLiteral("t.txt"));
        QVERIFY(!TrafficLog::save(txt, entries));
        QFile t(txt);
        QVERIFY(t.open(QIODevice::ReadOnly));
        QCOMPARE(t.readAll(), TrafficLog::textLine(entries.at(0)) + TrafficLog::textLine(entries.at(1)));
    }

    void saveFailsCleanly()
    {
        const Error e = TrafficLog::save(QStringLiteral("/nonexistent-dir/x/t.csv"), {serialEntry()});
        QVERIFY(e.isError());
        QCOMPARE(e.code, ErrorCode::FileError);
        QVERIFY2(e.message.contains(QLatin1String("t.csv")), qPrintable(e.message));
    }
};

QTEST_APPLESS_MAIN(TestTrafficLog)
#include "tst_trafficlog.moc"
