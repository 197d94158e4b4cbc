// Shuoke discovery on a serial bus: handshake scan over addresses and baud rates, with the
// query-address broadcast that skips silent rates; simulated drives over a pty.
#include <QtTest>

#include "core/drive/driveconnection.h"
#include "core/drive/drivereply.h"
#include "core/drive/shuoke/shuokebackend.h"
#include "core/drive/shuoke/shuokediscovery.h"
#include "core/drive/shuoke/shuoketransport.h"
#include "sim/bus/simserialbus.h"
#include "tests/support/shuokeserialbench.h"

#include <memory>

using namespace dd;
using namespace dd::shuoke;

class TestShuokeSerialDiscovery : public QObject
{
    Q_OBJECT

    std::unique_ptr<ShuokeSerialBench> m_bench;

    static SimShuokeDrive::Config config(quint8 address, int baudCode)
    {
        SimShuokeDrive::Config c;
        c.address = address;
        c.baudCode = baudCode;
        c.powerUpWindowMs = 0;
        return c;
    }

    bool start(const QList<SimShuokeDrive::Config> &drives, const QString &framing = QStringLiteral("rtu"),
               const QVariantMap &options = {})
    {
        const auto f = framing == QLatin1String("ascii") ? SimShuokeSerialDevice::Framing::Ascii
                                                         : SimShuokeSerialDevice::Framing::Rtu;
        ConnectionSettings s;
        s.framing = framing;
        s.baud = 9600;
        s.options = options;
        m_bench = ShuokeSerialBench::create(drives, s, f);
        return m_bench != nullptr;
    }

    QList<DiscoveredDrive> scan(const ScanOptions &o, int *skipped = nullptr, Error *error = nullptr)
    {
        Discovery *d = m_bench->connection()->createDiscovery(o);
        QSignalSpy finished(d, &Discovery::finished);
        d->start();
        if (!finished.wait(60000))
            return {};
        if (error)
            *error = finished.first().first().value<Error>();
        if (skipped)
            *skipped = static_cast<ShuokeDiscovery *>(d)->skippedBauds();
        return d->results();
    }

private slots:
    void cleanup() { m_bench.reset(); }

    void findsDrivesAtUnknownAddressesAndBauds_data()
    {
        QTest::addColumn<QString>("framing");
        QTest::newRow("rtu") << QStringLiteral("rtu");
        QTest::newRow("ascii") << QStringLiteral("ascii");
    }
    void findsDrivesAtUnknownAddressesAndBauds()
    {
        QFETCH(QString, framing);
        QVERIFY(start({config(5, 7), config(9, 8)}, framing)); // 19200 and 38400
        ScanOptions o;
        o.from = 1;
        o.to = 12;
        o.bauds = {9600, 19200, 38400};
        int skipped = -1;
        Error error;
        const QList<DiscoveredDrive> found = scan(o, &skipped, &error);
        QVERIFY2(!error, qPrintable(error.message));
        QCOMPARE(found.size(), 2);
        QCOMPARE(found.at(0).address, 5);
        QCOMPARE(found.at(0).baud, 19200);
        QCOMPARE(found.at(1).address, 9);
        QCOMPARE(found.at(1).baud, 38400);
        QCOMPARE(found.at(0).framing, framing);
        QCOMPARE(skipped, 1);                                    // nobody answered the broadcast at 9600
        QCOMPARE(m_bench->backend()->transport()->baud(), 9600); // left as it was
    }

    void twoDrivesAtOneBaudCollideButTheScanFindsBoth()
    {
        QVERIFY(start({config(2, 6), config(11, 6)}));
        ScanOptions o;
        o.from = 1;
        o.to = 12;
        int skipped = -1;
        const QList<DiscoveredDrive> found = scan(o, &skipped);
        QCOMPARE(found.size(), 2);
        QCOMPARE(found.at(0).address, 2);
        QCOMPARE(found.at(1).address, 11);
        QCOMPARE(skipped, 0);
        QVERIFY(m_bench->bus()->stats().collisions >= 1); // the broadcast was answered twice
        // every address was asked with the handshake
        int handshakes = 0;
        for (const TrafficRecord &r : m_bench->records())
            if (r.direction == TrafficRecord::Direction::Tx && r.bytes.size() == 5
                && quint8(r.bytes.at(1)) == CmdHandshake)
                ++handshakes;
        QCOMPARE(handshakes, 12); // the garbled broadcast found nobody: every address is asked
    }

    void singleDriveAnswersTheBroadcast()
    {
        QVERIFY(start({config(33, 6)}));
        ScanOptions o;
        o.from = 30;
        o.to = 36;
        const QList<DiscoveredDrive> found = scan(o);
        QCOMPARE(found.size(), 1);
        QCOMPARE(found.first().address, 33);
    }

    void broadcastAddressSetting_data()
    {
        QTest::addColumn<int>("hostBroadcast");
        QTest::addColumn<int>("found");
        QTest::newRow("host 255, drive 255") << 255 << 1;
        QTest::newRow("host 0, drive 255") << 0 << 0;
    }
    void broadcastAddressSetting()
    {
        QFETCH(int, hostBroadcast);
        QFETCH(int, found);
        SimShuokeDrive::Config c = config(200, 6);
        c.broadcasts = {255};
        QVERIFY(start({c}, QStringLiteral("rtu"), {{QStringLiteral("shuoke.broadcast"), hostBroadcast}}));
        ScanOptions o;
        o.from = 1;
        o.to = 3; // the drive is outside: only the broadcast can find it
        int skipped = -1;
        const QList<DiscoveredDrive> drives = scan(o, &skipped);
        QCOMPARE(drives.size(), found);
        if (found)
            QCOMPARE(drives.first().address, 200);
        QCOMPARE(skipped, found ? 0 : 1);
    }

    void cancel()
    {
        QVERIFY(start({config(3, 6)}, QStringLiteral("rtu"), {{QStringLiteral("shuoke.scanSkipSilent"), false}}));
        ScanOptions o;
        o.from = 1;
        o.to = 247;
        Discovery *d = m_bench->connection()->createDiscovery(o);
        QSignalSpy finished(d, &Discovery::finished);
        QSignalSpy progress(d, &Discovery::progress);
        d->start();
        QVERIFY(progress.wait(5000));
        d->cancel();
        QVERIFY(finished.wait(5000));
        QCOMPARE(finished.first().first().value<Error>().code, ErrorCode::Cancelled);
        QVERIFY(progress.count() < 20);
    }
};

QTEST_GUILESS_MAIN(TestShuokeSerialDiscovery)
#include "tst_shuokeserialdiscovery.moc"
