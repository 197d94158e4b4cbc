// Interop: drivedesk-cli against a servo-modbus drive served by pymodbus (Debian's
// python3-pymodbus, a Modbus stack nobody here wrote) on a socat pseudo-terminal pair,
// addresses 1 and 7, at 9600, 19200 and 115200 baud: scan, backup of PA0..PA59, set and
// read-back, diff and restore, monitor. A pty pair delivers every reply at once, far sooner
// than the wire would (the stale-reply rule, docs/reliability.md). The peer script is
// tests/interop/pymodbus_servo.py. A missing tool fails the test: CI installs it
// (packaging/install-deps.sh).

#include "tests/support/childprocess.h"
#include "tests/support/clirun.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

using namespace dd;
using namespace dd::test;

namespace {
const QString Python = QStringLiteral("/usr/bin/python3"); // Debian's, where python3-pymodbus lives
} // namespace

class TestPymodbus : public QObject
{
    Q_OBJECT

    QString m_socat;
    QString m_script;
    QTemporaryDir m_dir;
    QProcess m_socatProcess;
    QProcess m_peer;
    int m_baud = 0;

    QString port() const { return m_dir.filePath(QStringLiteral("drivedesk")); }

    CliRun cli(const QStringList &args, int address = 7)
    {
        QStringList all{QStringLiteral("--family"), QStringLiteral("servo-modbus"), QStringLiteral("--port"), port(),
                        QStringLiteral("--baud"), QString::number(m_baud), QStringLiteral("--address"),
                        QString::number(address), QStringLiteral("--json"),
                        // pymodbus (Python) answers in 5-90 ms on a loaded machine, far beyond
                        // the allowance a drive needs: a user says how long this peer may take.
                        QStringLiteral("--timeout"), QStringLiteral("400"), QStringLiteral("--retries"),
                        QStringLiteral("3")};
        return runCli(all + args, 30000);
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

    // socat makes the pty pair; pymodbus serves one end at `baud` (QVERIFY inside).
    void startPeers(int baud)
    {
        stopPeers();
        m_baud = baud;
        const QString peerEnd = m_dir.filePath(QStringLiteral("pymodbus"));
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
        m_peer.start(Python, {m_script, peerEnd, QString::number(baud), QStringLiteral("1,7")});
        QVERIFY2(m_peer.waitForStarted(5000), "python3 did not start");
        QByteArray said;
        QTRY_VERIFY2_WITH_TIMEOUT((said += m_peer.readAll()).contains("ready")
                                      || m_peer.state() == QProcess::NotRunning,
                                  "pymodbus did not start", 15000);
        QVERIFY2(m_peer.state() == QProcess::Running, said.constData());
    }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_socat = QStandardPaths::findExecutable(QStringLiteral("socat"));
        if (m_socat.isEmpty())
            QFAIL("socat is not installed (apt install socat; packaging/install-deps.sh)");
        QProcess probe;
        probe.start(Python, {QStringLiteral("-c"), QStringLiteral("import pymodbus.server.async_io")});
        if (!probe.waitForFinished(20000) || probe.exitCode() != 0)
            QFAIL("python3-pymodbus (with python3-serial-asyncio) is not installed "
                  "(apt install python3-pymodbus python3-serial-asyncio; packaging/install-deps.sh)");
        m_script = qEnvironmentVariable("DRIVEDESK_SOURCE_DIR") + QStringLiteral("/tests/interop/pymodbus_servo.py");
        QVERIFY2(QFile::exists(m_script), qPrintable(m_script));
    }

    void cleanupTestCase() { stopPeers(); }

    void commissioning_data()
    {
        QTest::addColumn<int>("baud");
        QTest::newRow("9600") << 9600;
        QTest::newRow("19200") << 19200;
        QTest::newRow("115200") << 115200;
    }

    void commissioning()
    {
        QFETCH(int, baud);
        startPeers(baud);
        if (QTest::currentTestFailed())
            return;

        // scan finds both drives (and nothing at the silent addresses around them). pymodbus
        // (Python) answers in 5-90 ms on a loaded machine, far beyond the scan's adaptive
        // probe timeout at 115200 (a few ms): --timeout says how long this peer may take.
        CliRun r = cli({QStringLiteral("scan"), QStringLiteral("--from"), QStringLiteral("1"), QStringLiteral("--to"),
                        QStringLiteral("8"), QStringLiteral("--bauds"), QString::number(baud)});
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        QList<int> found;
        for (const QJsonValue &d : r.json().value(QLatin1String("drives")).toArray()) {
            QCOMPARE(d[QLatin1String("firmware")].toString(), QStringLiteral("7051"));
            found << d[QLatin1String("address")].toInt();
        }
        QCOMPARE(found, (QList<int>{1, 7}));
        QVERIFY2(!r.err.contains("qt.modbus"), r.err.constData()); // no third-party noise

        // backup of PA0..PA59
        const QString file = m_dir.filePath(QStringLiteral("backup-%1.json").arg(baud));
        r = cli({QStringLiteral("backup"), QStringLiteral("-o"), file});
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        QFile f(file);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray saved = f.readAll();
        for (int n : {0, 5, 17, 59})
            QVERIFY2(saved.contains(QStringLiteral("\"PA%1\"").arg(n).toUtf8()), saved.constData());

        // set + read-back
        r = cli({QStringLiteral("set"), QStringLiteral("PA10=1234")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        const QJsonObject set = r.json().value(QLatin1String("parameters")).toArray().at(0).toObject();
        QCOMPARE(set.value(QLatin1String("result")).toString(), QStringLiteral("verified"));
        r = cli({QStringLiteral("get"), QStringLiteral("PA10")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        QVERIFY2(r.out.contains("1234"), r.out.constData());

        // diff shows exactly that change; restore undoes it, verified
        r = cli({QStringLiteral("diff"), file});
        QVERIFY2(r.exitCode == 1, qPrintable(r.text())); // like diff(1): 1 = the sides differ
        QCOMPARE(r.json().value(QLatin1String("different")).toInt(), 1);
        r = cli({QStringLiteral("restore"), file});
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        QCOMPARE(r.json().value(QLatin1String("verified")).toArray(), QJsonArray{QStringLiteral("PA10")});
        r = cli({QStringLiteral("get"), QStringLiteral("PA10")});
        QVERIFY2(r.out.contains("110"), r.out.constData());

        // monitor: DP-SPd (register 0) and DP-trq (register 7) as pymodbus holds them
        r = cli({QStringLiteral("monitor"), QStringLiteral("speed,torque"), QStringLiteral("--rate"),
                 QStringLiteral("5"), QStringLiteral("--duration"), QStringLiteral("1.5")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        const QList<QJsonObject> lines = r.jsonLines();
        QVERIFY2(lines.size() >= 2, r.out.constData());
        QCOMPARE(lines.first().value(QLatin1String("speed")).toDouble(), 1.0);
        QCOMPARE(lines.first().value(QLatin1String("torque")).toDouble(), 71.0);
    }
};

QTEST_GUILESS_MAIN(TestPymodbus)
#include "tst_pymodbus.moc"
