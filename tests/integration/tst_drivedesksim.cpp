// drivedesk-sim as integrators use it: the executable, its first line, its exit codes,
// --link, --state, SIGTERM — with DriveDesk's own client stack on the other side. Also the
// keep-alive between programs: a jog whose program is killed while another program monitors
// the same drive is stopped by the drive's 2 s watchdog (three processes on one CAN bus).
#include <QtTest>

#include "tests/support/childprocess.h"
#include "tests/support/clirun.h"

#include "core/drive/drive.h"
#include "core/drive/driveconnection.h"
#include "core/drive/drivereply.h"

#include <QElapsedTimer>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <csignal>
#include <optional>

using namespace dd;

namespace {

QString simPath()
{
    return qEnvironmentVariable("DRIVEDESK_BINARY_DIR") + QStringLiteral("/app/drivedesk-sim");
}

// Waits for a DriveReply and returns it (the drive owns it).
DriveReply *await(DriveReply *r, int ms = 5000)
{
    if (!r->isFinished()) {
        QSignalSpy spy(r, &DriveReply::finished);
        spy.wait(ms);
    } else {
        QCoreApplication::processEvents();
    }
    return r;
}

// The speed readings a running `drivedesk-cli --json monitor speed` printed since the last
// call (JSON lines; an incomplete last line waits for the next call).
class SpeedLines
{
public:
    explicit SpeedLines(QProcess *p)
        : m_process(p)
    {
    }
    // Reads what arrived; returns the last speed read, if any line came.
    std::optional<double> poll()
    {
        m_pending += m_process->readAllStandardOutput();
        std::optional<double> last;
        int nl;
        while ((nl = m_pending.indexOf('\n')) >= 0) {
            const QJsonObject o = QJsonDocument::fromJson(m_pending.left(nl)).object();
            m_pending.remove(0, nl + 1);
            if (o.contains(QLatin1String("speed")))
                last = o.value(QLatin1String("speed")).toDouble();
        }
        return last;
    }
    // Waits (event loop) until a reading satisfies `pred`; false after timeoutMs.
    template <typename Pred>
    bool waitFor(Pred pred, int timeoutMs)
    {
        QElapsedTimer t;
        t.start();
        while (t.elapsed() < timeoutMs && m_process->state() != QProcess::NotRunning) {
            m_process->waitForReadyRead(50);
            const std::optional<double> v = poll();
            if (v && pred(*v))
                return true;
        }
        return false;
    }

private:
    QProcess *m_process;
    QByteArray m_pending;
};

} // namespace

class TestDriveDeskSim : public QObject
{
    Q_OBJECT
private:
    // Starts the simulator and returns its first line (where to connect).
    QString start(QProcess &p, const QStringList &args)
    {
        p.setProgram(simPath());
        p.setArguments(args);
        p.start();
        if (!p.waitForStarted(5000))
            return {};
        for (int i = 0; i < 50 && !p.canReadLine(); ++i)
            p.waitForReadyRead(100);
        return QString::fromUtf8(p.readLine()).trimmed();
    }

    int terminate(QProcess &p)
    {
        ::kill(static_cast<pid_t>(p.processId()), SIGTERM);
        if (!p.waitForFinished(5000)) {
            p.kill();
            return -1;
        }
        return p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    }

private slots:
    void helpDocumentsTheSurface()
    {
        QProcess p;
        p.start(simPath(), {QStringLiteral("--help")});
        QVERIFY(p.waitForFinished(5000));
        QCOMPARE(p.exitCode(), 0);
        const QString help = QString::fromUtf8(p.readAllStandardOutput());
        for (const char *opt : {"--family", "--address", "--pty", "--link", "--can", "--baud", "--bitrate", "--framing",
                                "--latency-ms", "--drop", "--corrupt", "--seed", "--state", "--resonance-hz"})
            QVERIFY2(help.contains(QLatin1String(opt)), opt);
    }

    void badUsageExitsTwo_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("no family") << QStringList{QStringLiteral("--pty")};
        QTest::newRow("unknown family") << QStringList{QStringLiteral("--family"), QStringLiteral("vesc"),
                                                       QStringLiteral("--pty")};
        QTest::newRow("pty and can") << QStringList{QStringLiteral("--family"), QStringLiteral("servo-modbus"),
                                                    QStringLiteral("--pty"), QStringLiteral("--can"),
                                                    QStringLiteral("virtualcan:can0")};
        QTest::newRow("bad address") << QStringList{QStringLiteral("--family"), QStringLiteral("servo-modbus"),
                                                    QStringLiteral("--pty"), QStringLiteral("--address"),
                                                    QStringLiteral("300")};
        QTest::newRow("bad drop") << QStringList{QStringLiteral("--family"), QStringLiteral("servo-modbus"),
                                                 QStringLiteral("--pty"), QStringLiteral("--drop"),
                                                 QStringLiteral("1.5")};
        QTest::newRow("resonance 0 Hz") << QStringList{QStringLiteral("--family"), QStringLiteral("servo-modbus"),
                                                       QStringLiteral("--pty"), QStringLiteral("--resonance-hz"),
                                                       QStringLiteral("0")};
        QTest::newRow("resonance not a number")
            << QStringList{QStringLiteral("--family"), QStringLiteral("servo-modbus"), QStringLiteral("--pty"),
                           QStringLiteral("--resonance-hz"), QStringLiteral("eighty")};
        QTest::newRow("can family on pty")
            << QStringList{QStringLiteral("--family"), QStringLiteral("servo-can"), QStringLiteral("--pty")};
        QTest::newRow("framing on servo")
            << QStringList{QStringLiteral("--family"), QStringLiteral("servo-modbus"), QStringLiteral("--pty"),
                           QStringLiteral("--framing"), QStringLiteral("rtu")};
    }
    void badUsageExitsTwo()
    {
        QFETCH(QStringList, args);
        QProcess p;
        p.start(simPath(), args);
        QVERIFY(p.waitForFinished(5000));
        QCOMPARE(p.exitCode(), 2);
        QVERIFY(!p.readAllStandardError().isEmpty());
        QVERIFY(p.readAllStandardOutput().isEmpty()); // no "pty:" line: nothing was started
    }

    void servoModbusOnPtyWithLinkAndState()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString link = dir.filePath(QStringLiteral("rs485"));
        const QString state = dir.filePath(QStringLiteral("state.json"));
        const QStringList args{QStringLiteral("--family"),
                               QStringLiteral("servo-modbus"),
                               QStringLiteral("--address"),
                               QStringLiteral("3"),
                               QStringLiteral("--pty"),
                               QStringLiteral("--link"),
                               link,
                               QStringLiteral("--baud"),
                               QStringLiteral("115200"),
                               QStringLiteral("--state"),
                               state};
        {
            QProcess sim;
            const QString where = start(sim, args);
            QVERIFY2(where.startsWith(QLatin1String("pty: /dev/pts/")), qPrintable(where));
            QVERIFY(QFileInfo(link).isSymLink());

            DriveConnection c;
            ConnectionSettings s;
            s.family = Family::ServoModbus;
            s.port = link;
            s.baud = 115200;
            Error e;
            QVERIFY2(c.open(s, &e), qPrintable(e.message));
            Drive *d = c.drive(3);
            QVERIFY(d);
            DriveReply *r = (await(d->readParameters({51})));
            QVERIFY2(r->ok(), qPrintable(r->error().message));
            QCOMPARE(r->parameters().value(51), 3);
            r = (await(d->writeParameters({{10, 1234}})));
            QVERIFY2(r->ok(), qPrintable(r->error().message));
            c.close();
            QCOMPARE(terminate(sim), 0);
            QVERIFY(!QFileInfo::exists(link)); // the link goes with the simulator
            QVERIFY(QFileInfo::exists(state));
        }
        // A new simulator with the same state file remembers the write.
        QProcess sim;
        const QString where = start(sim, args);
        QVERIFY(where.startsWith(QLatin1String("pty: ")));
        DriveConnection c;
        ConnectionSettings s;
        s.family = Family::ServoModbus;
        s.port = link;
        s.baud = 115200;
        QVERIFY(c.open(s));
        DriveReply *r = (await(c.drive(3)->readParameters({10})));
        QVERIFY2(r->ok(), qPrintable(r->error().message));
        QCOMPARE(r->parameters().value(10), 1234);
        c.close();
        QCOMPARE(terminate(sim), 0);
    }

    void servoCanOnPrivateVirtualCan()
    {
        QProcess sim;
        const QString where = start(sim,
                                    {QStringLiteral("--family"), QStringLiteral("servo-can"),
                                     QStringLiteral("--address"), QStringLiteral("7"), QStringLiteral("--can"),
                                     QStringLiteral("virtualcan:auto")});
        QVERIFY2(where.startsWith(QLatin1String("can: virtualcan:tcp://127.0.0.1:")),
                 qPrintable(where + sim.errorString()));
        DriveConnection c;
        ConnectionSettings s;
        s.family = Family::ServoCan;
        s.can = where.mid(5);
        Error e;
        QVERIFY2(c.open(s, &e), qPrintable(e.message));
        Discovery *scan = c.createDiscovery({}); // the backend owns it
        QSignalSpy done(scan, &Discovery::finished);
        scan->start();
        QVERIFY(done.wait(5000));
        QCOMPARE(scan->results().size(), 1);
        QCOMPARE(scan->results().first().address, 7);
        DriveReply *r = (await(c.drive(7)->readParameters({75})));
        QVERIFY2(r->ok(), qPrintable(r->error().message));
        QCOMPARE(r->parameters().value(75), 7);
        c.close();
        QCOMPARE(terminate(sim), 0);
    }

    // Issue 26, item 7: the keep-alive belongs to the program that commands the motion. A
    // jogging drivedesk-cli is killed (SIGKILL: no stop, no clean-up) while another
    // drivedesk-cli monitors the same drive; the monitor must not keep the orphaned jog alive,
    // so the drive's own 2 s watchdog stops the axis. (Before the fix every program on the bus
    // sent the keep-alive to every drive it heard, and the axis ran on while the monitor ran.)
    void orphanedJogStopsByTheDriveWatchdogWhileAnotherProgramMonitors()
    {
        QProcess sim;
        test::dieWithParent(sim);
        const QString where = start(sim,
                                    {QStringLiteral("--family"), QStringLiteral("servo-can"),
                                     QStringLiteral("--address"), QStringLiteral("1"), QStringLiteral("--can"),
                                     QStringLiteral("virtualcan:auto")});
        QVERIFY2(where.startsWith(QLatin1String("can: virtualcan:")), qPrintable(where + sim.errorString()));
        const QStringList link{
            QStringLiteral("--family"),  QStringLiteral("servo-can"), QStringLiteral("--can"), where.mid(5),
            QStringLiteral("--address"), QStringLiteral("1"),         QStringLiteral("--json")};

        std::unique_ptr<QProcess> monitor(
            test::startCli(link
                           + QStringList{QStringLiteral("monitor"), QStringLiteral("speed"), QStringLiteral("--rate"),
                                         QStringLiteral("20"), QStringLiteral("--duration"), QStringLiteral("120")}));
        SpeedLines speed(monitor.get());
        QVERIFY2(speed.waitFor([](double) { return true; }, 20000),
                 monitor->readAllStandardError().constData()); // the monitor reads

        std::unique_ptr<QProcess> jog(test::startCli(
            link + QStringList{QStringLiteral("jog"), QStringLiteral("300"), QStringLiteral("--enable")}));
        QByteArray seen;
        QVERIFY2(test::waitForOutput(jog.get(), "Ctrl-C", 20000, &seen), seen.constData());
        QVERIFY2(speed.waitFor([](double v) { return qAbs(v - 300) < 3; }, 20000), "the jog does not run");
        // Well into the jog, the monitor reading on: still at 300 r/min.
        QVERIFY(!speed.waitFor([](double v) { return qAbs(v - 300) >= 3; }, 600));

        QElapsedTimer sinceKill;
        ::kill(static_cast<pid_t>(jog->processId()), SIGKILL);
        sinceKill.start();
        QVERIFY(jog->waitForFinished(5000));
        QCOMPARE(jog->exitStatus(), QProcess::CrashExit);

        // Nothing sends a stop: only the drive's watchdog can stop the axis, 2 s after the
        // last keep-alive the killed program sent (generous margin: ASan, 2 busy cores).
        const bool stopped = speed.waitFor([](double v) { return qAbs(v) < 1; }, 2000 + 8000);
        const qint64 stoppedAfter = sinceKill.elapsed();
        qInfo("orphaned jog: at rest %lld ms after its program was killed", static_cast<long long>(stoppedAfter));
        QVERIFY2(stopped, "the orphaned jog runs on: something keeps the drive's watchdog from acting");
        QVERIFY2(stoppedAfter >= 1500, "stopped before the 2 s watchdog could act");
        QCOMPARE(monitor->state(), QProcess::Running); // the monitor read all along

        ::kill(static_cast<pid_t>(monitor->processId()), SIGINT);
        QVERIFY(monitor->waitForFinished(10000));
        QCOMPARE(monitor->exitCode(), 0);
        QCOMPARE(terminate(sim), 0);
    }
};

QTEST_GUILESS_MAIN(TestDriveDeskSim)
#include "tst_drivedesksim.moc"
