// drivedesk-sim as integrators use it: the executable, its first line, its exit codes,
// --link, --state, SIGTERM — with DriveDesk's own client stack on the other side.
#include <QtTest>

#include "core/drive/drive.h"
#include "core/drive/driveconnection.h"
#include "core/drive/drivereply.h"

#include <QProcess>
#include <QTemporaryDir>
#include <csignal>

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
};

QTEST_GUILESS_MAIN(TestDriveDeskSim)
#include "tst_drivedesksim.moc"
