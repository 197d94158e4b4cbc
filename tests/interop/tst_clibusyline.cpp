// Interop: drivedesk-cli ping on a line where another master never stops talking — a Python
// peer (tests/interop/other_master.py: its own CRC, nothing from DriveDesk) on a socat
// pseudo-terminal pair, asking address 9 every 0.5 ms. The link waits for a quiet line only so
// long (docs/reliability.md, "A line that is never quiet"), then sends; ping must end, say
// why nothing answered, and count what it saw: every request closed (a timeout or a
// checksum error), the requests sent on the busy line counted (issue 11, link health) — and
// the other master's requests taken for what they are, not for our reply failing its CRC.

#include "tests/support/childprocess.h"
#include "tests/support/clirun.h"

#include <QFile>
#include <QJsonObject>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

using namespace dd::test;

class TestCliBusyLine : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    QProcess m_socat;
    QProcess m_master;

    QString port() const { return m_dir.filePath(QStringLiteral("drivedesk")); }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        const QString socat = QStandardPaths::findExecutable(QStringLiteral("socat"));
        if (socat.isEmpty())
            QFAIL("socat is not installed (apt install socat; packaging/install-deps.sh)");
        const QString script = qEnvironmentVariable("DRIVEDESK_SOURCE_DIR")
            + QStringLiteral("/tests/interop/other_master.py");
        QVERIFY2(QFile::exists(script), qPrintable(script));
        const QString masterEnd = m_dir.filePath(QStringLiteral("master"));
        dieWithParent(m_socat);
        m_socat.start(
            socat,
            {QStringLiteral("pty,raw,echo=0,link=") + port(), QStringLiteral("pty,raw,echo=0,link=") + masterEnd});
        QVERIFY2(m_socat.waitForStarted(5000), "socat did not start");
        QTRY_VERIFY2_WITH_TIMEOUT(QFile::exists(port()) && QFile::exists(masterEnd), "socat made no pty pair", 5000);
        dieWithParent(m_master);
        m_master.setProcessChannelMode(QProcess::MergedChannels);
        m_master.start(QStringLiteral("/usr/bin/python3"), {script, masterEnd, QStringLiteral("0.5")});
        QVERIFY2(m_master.waitForStarted(5000), "python3 did not start");
        QByteArray said;
        QTRY_VERIFY2_WITH_TIMEOUT((said += m_master.readAll()).contains("ready")
                                      || m_master.state() != QProcess::Running,
                                  "the other master did not start", 10000);
        QVERIFY2(m_master.state() == QProcess::Running, said.constData());
    }

    void cleanupTestCase()
    {
        for (QProcess *p : {&m_master, &m_socat}) {
            p->kill();
            p->waitForFinished(3000);
        }
    }

    void pingEndsAndCountsTheBusyLine()
    {
        const CliRun r = runCli({"--family", "servo-modbus", "--port", port(), "--baud", "115200", "--address", "1",
                                 "--timeout", "10", "--retries", "1", "--json", "ping", "--count", "2"});
        QCOMPARE(r.exitCode, 1);
        const QJsonObject j = r.json();
        QCOMPARE(j.value("ok").toBool(), false);
        QCOMPARE(j.value("answered").toInt(), 0);
        // 2 pings, each asked twice; every one of them ended, none is left "out".
        QCOMPARE(j.value("requests").toInt(), 4);
        QCOMPARE(j.value("timeouts").toInt(), 4);
        QCOMPARE(j.value("checksumErrors").toInt(), 0);
        QVERIFY2(j.value("busyLineSends").toInt() >= 1, qPrintable(r.text()));
        QCOMPARE(j.value("retries").toInt(), 2);
        QVERIFY2(r.text().contains("never quiet") && r.text().contains("another master"), qPrintable(r.text()));
        QVERIFY2(r.text().contains("A frame from address 9 arrived instead"), qPrintable(r.text()));
        QVERIFY2(!r.text().contains("CRC"), qPrintable(r.text()));
        QVERIFY2(!r.text().contains("raise the timeout"), qPrintable(r.text()));
    }
};

QTEST_GUILESS_MAIN(TestCliBusyLine)
#include "tst_clibusyline.moc"
