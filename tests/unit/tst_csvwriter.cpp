#include <QtTest>

#include "core/trend/csvwriter.h"
#include "core/trend/trendrecorder.h"

#include <QTemporaryDir>
#include <limits>

using namespace dd;

class TestCsvWriter : public QObject
{
    Q_OBJECT
private:
    static QByteArray readAll(const QString &path)
    {
        QFile f(path);
        if (!f.open(QIODevice::ReadOnly))
            return "<cannot open>";
        return f.readAll();
    }

    static QList<TrendChannel> channels()
    {
        return {{QStringLiteral("speed"), QStringLiteral("Speed"), QStringLiteral("r/min"), 0},
                {QStringLiteral("torque"), QStringLiteral("Torque"), QStringLiteral("%"), 1},
                {QStringLiteral("inputs"), QStringLiteral("Inputs"), QString(), 0}};
    }

private slots:
    void header()
    {
        QCOMPARE(CsvWriter::headerLine(channels()), QByteArray("time_s,speed [r/min],torque [%],inputs\n"));
        QCOMPARE(CsvWriter::headerLine({}), QByteArray("time_s\n"));
        const QList<TrendChannel> odd{{QStringLiteral("a,b"), {}, QStringLiteral("\"x\""), 0},
                                      {QStringLiteral("temp"), {}, QStringLiteral("°C"), 0}};
        QCOMPARE(CsvWriter::headerLine(odd),
                 QByteArray("time_s,\"a,b [\"\"x\"\"]\",temp [\xc2\xb0"
                            "C]\n"));
    }

    void time_data()
    {
        QTest::addColumn<qint64>("time");
        QTest::addColumn<qint64>("origin");
        QTest::addColumn<QByteArray>("text");
        QTest::newRow("zero") << qint64(5000) << qint64(5000) << QByteArray("0.000000");
        QTest::newRow("1 us") << qint64(1) << qint64(0) << QByteArray("0.000001");
        QTest::newRow("1.25 s") << qint64(1250000) << qint64(0) << QByteArray("1.250000");
        QTest::newRow("10 min") << qint64(600000000 + 77) << qint64(77) << QByteArray("600.000000");
        QTest::newRow("before origin") << qint64(0) << qint64(1500001) << QByteArray("-1.500001");
        QTest::newRow("extremes") << std::numeric_limits<qint64>::max() << std::numeric_limits<qint64>::min()
                                  << QByteArray("18446744073709.551615");
    }
    void time()
    {
        QFETCH(qint64, time);
        QFETCH(qint64, origin);
        QFETCH(QByteArray, text);
        QCOMPARE(CsvWriter::formatTime(time, origin), text);
    }

    void values_data()
    {
        QTest::addColumn<double>("value");
        QTest::addColumn<QByteArray>("text");
        QTest::newRow("int") << 1500.0 << QByteArray("1500");
        QTest::newRow("tenth") << 0.1 << QByteArray("0.1");
        QTest::newRow("negative") << -2.5 << QByteArray("-2.5");
        QTest::newRow("zero") << 0.0 << QByteArray("0");
        QTest::newRow("minus zero") << -0.0 << QByteArray("0");
        QTest::newRow("third") << 1.0 / 3.0 << QByteArray("0.3333333333333333");
        QTest::newRow("million") << 1e6 << QByteArray("1000000");
        QTest::newRow("position") << -2147483648.0 << QByteArray("-2147483648");
        QTest::newRow("small") << 1e-6 << QByteArray("0.000001");
        QTest::newRow("tiny") << 1.5e-7 << QByteArray("1.5e-07");
        QTest::newRow("huge") << 1e20 << QByteArray("1e+20");
        QTest::newRow("nan") << std::numeric_limits<double>::quiet_NaN() << QByteArray("nan");
        QTest::newRow("inf") << std::numeric_limits<double>::infinity() << QByteArray("inf");
        QTest::newRow("-inf") << -std::numeric_limits<double>::infinity() << QByteArray("-inf");
    }
    void values()
    {
        QFETCH(double, value);
        QFETCH(QByteArray, text);
        QCOMPARE(CsvWriter::formatValue(value), text);
        if (std::isfinite(value))
            QCOMPARE(text.toDouble(), value == 0.0 ? 0.0 : value); // round-trips
    }

    void snapshotMergesRowsByTime()
    {
        TrendSnapshot snap;
        snap.channels = channels();
        snap.originUs = 1000;
        snap.series = {
            {{1000, 1500}, {11000, 1502}, {21000, 1499}}, // speed: every 10 ms
            {{1000, 12.5}, {21000, 13}},                  // torque: every 20 ms
            {{6000, 5}, {21000, 7}, {21000, 6}},          // inputs: odd times, a duplicate
        };
        const QByteArray expected = "time_s,speed [r/min],torque [%],inputs\n"
                                    "0.000000,1500,12.5,\n"
                                    "0.005000,,,5\n"
                                    "0.010000,1502,,\n"
                                    "0.020000,1499,13,7\n"
                                    "0.020000,,,6\n";
        QCOMPARE(CsvWriter::toCsv(snap), expected);
    }

    void saveIsAtomicAndExact()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("trend.csv"));
        TrendRecorder rec;
        rec.setChannels(channels().mid(0, 2));
        rec.appendSamples(2000000, {{QStringLiteral("speed"), 100}, {QStringLiteral("torque"), 1.5}});
        rec.appendSamples(2100000, {{QStringLiteral("speed"), 110}, {QStringLiteral("torque"), -1.5}});
        QVERIFY(!CsvWriter::save(path, rec.snapshotAll()));
        QCOMPARE(readAll(path),
                 QByteArray("time_s,speed [r/min],torque [%]\n"
                            "0.000000,100,1.5\n"
                            "0.100000,110,-1.5\n"));
        // Only the window, one channel.
        QVERIFY(!CsvWriter::save(path, rec.snapshot(2050000, 2200000, {QStringLiteral("torque")})));
        QCOMPARE(readAll(path), QByteArray("time_s,torque [%]\n0.100000,-1.5\n"));
        // No temporary files left behind.
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList{QStringLiteral("trend.csv")});
    }

    void saveFailsCleanly()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("missing/sub/trend.csv"));
        const Error e = CsvWriter::save(path, TrendSnapshot{});
        QCOMPARE(e.code, ErrorCode::FileError);
        QVERIFY(e.message.contains(path));
        QVERIFY(!QFile::exists(path));
    }

    void streamingFlushesEveryRow()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("monitor.csv"));
        CsvWriter w;
        QVERIFY(!w.open(path, channels()));
        QVERIFY(w.isOpen());
        QCOMPARE(readAll(path), QByteArray("time_s,speed [r/min],torque [%],inputs\n"));
        // Origin = first row's time when not given.
        QVERIFY(!w.writeRow(5000000,
                            QMap<QString, double>{{QStringLiteral("speed"), 1500},
                                                  {QStringLiteral("inputs"), 3},
                                                  {QStringLiteral("unknown"), 9}}));
        // Visible on disk before close().
        QCOMPARE(readAll(path),
                 QByteArray("time_s,speed [r/min],torque [%],inputs\n"
                            "0.000000,1500,,3\n"));
        QVERIFY(!w.writeRow(5020000, QList<std::optional<double>>{1501, 2.25, std::nullopt, 99}));
        QCOMPARE(w.rowCount(), 2);
        QVERIFY(!w.close());
        QVERIFY(!w.isOpen());
        QCOMPARE(readAll(path),
                 QByteArray("time_s,speed [r/min],torque [%],inputs\n"
                            "0.000000,1500,,3\n"
                            "0.020000,1501,2.25,\n"));
        QCOMPARE(w.writeRow(0, QMap<QString, double>{}).code, ErrorCode::InvalidArgument);
    }

    void streamingInSeconds()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("s.csv"));
        CsvWriter w;
        QVERIFY(!w.open(path, channels().mid(0, 2), qint64(0)));
        QVERIFY(!w.writeRowAtSeconds(0.0, {{QStringLiteral("speed"), 1}}));
        QVERIFY(!w.writeRowAtSeconds(0.1, {{QStringLiteral("torque"), 2}}));
        QVERIFY(!w.writeRowAtSeconds(12.3456789, {{QStringLiteral("speed"), 3}}));
        QCOMPARE(w.writeRowAtSeconds(std::numeric_limits<double>::quiet_NaN(), {}).code, ErrorCode::InvalidArgument);
        QVERIFY(!w.close());
        QCOMPARE(readAll(path),
                 QByteArray("time_s,speed [r/min],torque [%]\n"
                            "0.000000,1,\n"
                            "0.100000,,2\n"
                            "12.345679,3,\n"));
    }

    void streamingWithExplicitOrigin()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("m.csv"));
        {
            CsvWriter w;
            QVERIFY(!w.open(path, channels().mid(0, 1), qint64(1000000)));
            QVERIFY(!w.writeRow(3500000, QMap<QString, double>{{QStringLiteral("speed"), -7}}));
        } // the destructor closes
        QCOMPARE(readAll(path), QByteArray("time_s,speed [r/min]\n2.500000,-7\n"));
        CsvWriter w;
        QCOMPARE(w.open(dir.filePath(QStringLiteral("no/such/dir.csv")), channels()).code, ErrorCode::FileError);
        QVERIFY(!w.isOpen());
    }
};

QTEST_GUILESS_MAIN(TestCsvWriter)
#include "tst_csvwriter.moc"
