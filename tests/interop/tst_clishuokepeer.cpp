// Interop: drivedesk-cli against a Shuoke drive that is not our simulator — a small PeerPython
// peer written from the seed alone (tests/interop/shuoke_peer.py: its own CRC, framing and
// command set, nothing imported from DriveDesk) on a socat pseudo-terminal pair. It answers
// every request at once, without wire pacing (issue 11: "a peer with no wire pacing for each
// serial family"; servo-modbus has pymodbus, libmodbus and mbpoll). RTU and ASCII: scan,
// info (identity and model), get, set with read-back, jog and stop. A missing tool fails the
// test: CI installs it (packaging/install-deps.sh).

#include "tests/support/childprocess.h"
#include "tests/support/clirun.h"

#include <QFile>
#include <QJsonArray>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

using namespace dd;
using namespace dd::test;

namespace {
const QString PeerPython = QStringLiteral("/usr/bin/python3");
constexpr int PeerAddress = 3;
} // namespace

class TestCliShuokePeer : public QObject
{
    Q_OBJECT

    QString m_socat;
    QString m_script;
    QTemporaryDir m_dir;
    QProcess m_socatProcess;
    QProcess m_peer;
    QByteArray m_peerLog;
    QString m_framing;

    QString port() const { return m_dir.filePath(QStringLiteral("drivedesk")); }

    CliRun cli(const QStringList &args)
    {
        const QStringList all{QStringLiteral("--family"),  QStringLiteral("shuoke"),
                              QStringLiteral("--framing"), m_framing,
                              QStringLiteral("--port"),    port(),
                              QStringLiteral("--baud"),    QStringLiteral("9600"),
                              QStringLiteral("--address"), QString::number(PeerAddress),
                              QStringLiteral("--json")};
        return runCli(all + args, 30000);
    }

    // What the peer took since the last call, one "cmd 0xNN DATA" line per request.
    QByteArray peerLog()
    {
        m_peerLog += m_peer.readAll();
        return m_peerLog;
    }

    void stopPeers()
    {
        for (QProcess *p : {&m_peer, &m_socatProcess}) {
            if (p->state() != QProcess::NotRunning) {
                p->kill();
                p->waitForFinished(3000);
            }
        }
    }

    void startPeers(const QString &framing)
    {
        stopPeers();
        m_framing = framing;
        m_peerLog.clear();
        const QString peerEnd = m_dir.filePath(QStringLiteral("peer"));
        QFile::remove(port());
        QFile::remove(peerEnd);
        dieWithParent(m_socatProcess);
        m_socatProcess.start(
            m_socat,
            {QStringLiteral("pty,raw,echo=0,link=") + port(), QStringLiteral("pty,raw,echo=0,link=") + peerEnd});
        QVERIFY2(m_socatProcess.waitForStarted(5000), "socat did not start");
        QTRY_VERIFY2_WITH_TIMEOUT(QFile::exists(port()) && QFile::exists(peerEnd), "socat made no pty pair", 5000);
        dieWithParent(m_peer);
        m_peer.setProcessChannelMode(QProcess::MergedChannels);
        m_peer.start(PeerPython, {m_script, peerEnd, QString::number(PeerAddress), framing});
        QVERIFY2(m_peer.waitForStarted(5000), "python3 did not start");
        QTRY_VERIFY2_WITH_TIMEOUT(peerLog().contains("ready") || m_peer.state() == QProcess::NotRunning,
                                  "the peer did not start", 10000);
        QVERIFY2(m_peer.state() == QProcess::Running, m_peerLog.constData());
    }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_socat = QStandardPaths::findExecutable(QStringLiteral("socat"));
        if (m_socat.isEmpty())
            QFAIL("socat is not installed (apt install socat; packaging/install-deps.sh)");
        m_script = qEnvironmentVariable("DRIVEDESK_SOURCE_DIR") + QStringLiteral("/tests/interop/shuoke_peer.py");
        QVERIFY2(QFile::exists(m_script), qPrintable(m_script));
    }

    void cleanupTestCase() { stopPeers(); }

    void commissioning_data()
    {
        QTest::addColumn<QString>("framing");
        QTest::newRow("rtu") << QStringLiteral("rtu");
        QTest::newRow("ascii") << QStringLiteral("ascii");
    }

    void commissioning()
    {
        QFETCH(QString, framing);
        startPeers(framing);
        if (QTest::currentTestFailed())
            return;

        CliRun r = cli({QStringLiteral("scan"), QStringLiteral("--from"), QStringLiteral("1"), QStringLiteral("--to"),
                        QStringLiteral("4"), QStringLiteral("--bauds"), QStringLiteral("9600")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        const QJsonArray drives = r.json().value(QLatin1String("drives")).toArray();
        QCOMPARE(drives.size(), 1);
        QCOMPARE(drives.at(0)[QLatin1String("address")].toInt(), PeerAddress);

        r = cli({QStringLiteral("info")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        QCOMPARE(r.json().value(QLatin1String("identity"))[QLatin1String("model")].toString(), QStringLiteral("M6505"));

        r = cli({QStringLiteral("get"), QStringLiteral("max-speed"), QStringLiteral("acceleration")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        const QJsonArray got = r.json().value(QLatin1String("parameters")).toArray();
        QCOMPARE(got.at(0)[QLatin1String("value")].toInt(), 10000);
        QCOMPARE(got.at(1)[QLatin1String("value")].toInt(), 50000);

        // 100000 needs all four bytes (it reads back whole).
        r = cli({QStringLiteral("set"), QStringLiteral("max-speed=100000")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        const QJsonObject set = r.json().value(QLatin1String("parameters")).toArray().at(0).toObject();
        QCOMPARE(set.value(QLatin1String("result")).toString(), QStringLiteral("verified"));
        QCOMPARE(set.value(QLatin1String("readBack")).toInt(), 100000);
        QVERIFY2(peerLog().contains("cmd 0x27 a0860100"), m_peerLog.constData());

        r = cli({QStringLiteral("jog"), QStringLiteral("3000"), QStringLiteral("--duration"), QStringLiteral("0.3")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        QCOMPARE(r.json().value(QLatin1String("stopped")).toBool(), true);
        QTRY_VERIFY2(peerLog().contains("cmd 0x33 b80b0000"), m_peerLog.constData()); // +3000
        const qsizetype jog = m_peerLog.indexOf("cmd 0x33 b80b0000");
        QVERIFY2(m_peerLog.indexOf("cmd 0x3D", jog) > jog, m_peerLog.constData()); // then the stop
    }
};

QTEST_GUILESS_MAIN(TestCliShuokePeer)
#include "tst_clishuokepeer.moc"
