// The demo: File → Demo bench starts the simulated bench on its own thread, connects to
// every link and finds one drive of each family; STOP (F12) really stops a moving drive.
#include "core/drive/drive.h"
#include "core/drive/drivehub.h"
#include "core/trend/trendrecorder.h"
#include "sim/bench/demobench.h"
#include "tests/support/requiretool.h"
#include "ui/bus/bustreewidget.h"
#include "ui/bus/connectioncontroller.h"
#include "ui/bus/drivedirectory.h"
#include "ui/panels/trend/trendpanel.h"
#include "ui/shell/demolauncher.h"
#include "ui/shell/mainwindow.h"
#include "ui/shell/stopaction.h"
#include "ui/workspace/driveworkspace.h"

#include <QApplication>
#include <QCanBus>
#include <QLoggingCategory>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>

using namespace dd;

class TestDemoBench : public QObject
{
    Q_OBJECT

    QTemporaryDir m_settingsDir;

    // Waits with a real event loop until `cond` holds.
    template <typename Cond>
    static bool waitFor(QObject *sender, const char *signal, Cond cond, int timeoutMs)
    {
        QSignalSpy spy(sender, signal);
        QDeadlineTimer deadline(timeoutMs);
        while (!cond() && !deadline.hasExpired())
            spy.wait(int(qMax<qint64>(1, qMin<qint64>(100, deadline.remainingTime()))));
        return cond();
    }

    static int driveCount(DriveDirectory *dir)
    {
        int n = 0;
        for (int id : dir->connections())
            n += int(dir->drives(id).size());
        return n;
    }

    static int connectionOf(DriveDirectory *dir, Family f)
    {
        for (int id : dir->connections())
            if (dir->connectionSettings(id).family == f)
                return id;
        return 0;
    }

private slots:
    void initTestCase()
    {
        QLoggingCategory::setFilterRules(QStringLiteral("qt.canbus.plugins.virtualcan.info=false\n"
                                                        "drivedesk.*.debug=false"));
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(m_settingsDir.isValid());
        QSettings::setDefaultFormat(QSettings::IniFormat);
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settingsDir.path());
        QCoreApplication::setOrganizationName(QStringLiteral("DriveDeskTest"));
        QCoreApplication::setApplicationName(QStringLiteral("tst_demobench"));
        QSettings().setValue(QStringLiteral("language"), QStringLiteral("en"));
        DD_REQUIRE_TOOL(QCanBus::instance()->plugins().contains(QLatin1String("virtualcan")),
                        "Qt's virtualcan plugin is not installed");
    }

    void benchRunsOnItsOwnThread()
    {
        DemoBench bench;
        QSignalSpy ready(&bench, &DemoBench::ready);
        const Error e = bench.start();
        QVERIFY2(!e, qPrintable(e.message));
        QVERIFY(bench.benchThread());
        QVERIFY(bench.benchThread() != QThread::currentThread());
        QVERIFY(bench.benchThread()->isRunning());
        QVERIFY(ready.wait(5000));
        const QList<ConnectionSettings> links = bench.connections();
        QCOMPARE(links.size(), bench.describe().size());
        QList<Family> families;
        for (const ConnectionSettings &s : links)
            families << s.family;
        QCOMPARE(families.size(), 3); // one bus per family
        QVERIFY(families.contains(Family::ServoModbus));
        QVERIFY(families.contains(Family::ServoCan));
        QVERIFY(families.contains(Family::Shuoke));
        for (const ConnectionSettings &s : links)
            if (s.isCan())
                QVERIFY2(s.can.startsWith(QLatin1String("virtualcan:tcp://127.0.0.1:")), qPrintable(s.can));
        bench.stop();
        QVERIFY(!bench.isRunning());
        QVERIFY(!bench.benchThread());
    }

    void preferredFamilyIsSelected()
    {
        // `drivedesk --drive servo-can`: the first servo-can drive is selected, whichever
        // family's scan finishes first.
        MainWindow w;
        w.setPreferredFamily(Family::ServoCan);
        w.show();
        DriveDirectory *dir = w.directory();
        QVERIFY(w.startDemo());
        QVERIFY(waitFor(
            w.connections(), SIGNAL(finished(QString, bool)),
            [&] { return driveCount(dir) == 3 && !w.connections()->isBusy(); }, 20000));
        const DriveContext current = w.workspace()->currentDrive();
        QCOMPARE(current.connectionId, connectionOf(dir, Family::ServoCan));
        QCOMPARE(current.address, DemoBench::Address);
    }

    void demoFindsEveryDriveAndStopWorks()
    {
        MainWindow w;
        w.show();
        QApplication::setActiveWindow(&w);
        QVERIFY(QTest::qWaitForWindowActive(&w));
        DriveDirectory *dir = w.directory();

        QVERIFY(w.startDemo());
        QVERIFY(w.demo()->isRunning());
        const int expected = 3; // one drive of each family
        QCOMPARE(int(w.demo()->connections().size()), expected);
        QVERIFY(waitFor(
            w.connections(), SIGNAL(finished(QString, bool)),
            [&] { return driveCount(dir) == expected && !w.connections()->isBusy(); }, 20000));
        QCOMPARE(int(dir->connections().size()), expected);
        QVERIFY(connectionOf(dir, Family::Shuoke));
        for (int id : dir->connections()) {
            QCOMPARE(dir->drives(id), QList<int>({DemoBench::Address}));
            QVERIFY(w.busTree()->driveItem(id, DemoBench::Address));
        }
        // The first drive found is selected and shown.
        QVERIFY(w.workspace()->currentDrive().connectionId > 0);

        // Identities arrive (firmware of the simulated servo-modbus drive: 7051).
        const int modbus = connectionOf(dir, Family::ServoModbus);
        QVERIFY(modbus);
        QVERIFY(waitFor(
            dir, SIGNAL(driveChanged(int, int)),
            [&] { return dir->info(modbus, 1).identity.firmware == QLatin1String("7051"); }, 5000));

        // The trend tab samples the drive's channels while it is shown.
        w.busTree()->selectDrive(modbus, 1);
        w.workspace()->setPreferredPanel(QStringLiteral("trend"));
        TrendPanel *trend = nullptr;
        for (DrivePanel *p : w.workspace()->panelsFor(modbus, 1))
            if (auto *t = qobject_cast<TrendPanel *>(p))
                trend = t;
        QVERIFY(trend);
        QVERIFY(trend->isActive());
        QVERIFY(waitFor(
            dir, SIGNAL(driveChanged(int, int)),
            [&] {
                const SampleBuffer *b = trend->recorder()->buffer(QStringLiteral("speed"));
                return b && b->size() >= 3;
            },
            5000));
        // Not shown: no sampling (the link is shared).
        w.workspace()->setPreferredPanel(QStringLiteral("overview"));
        QVERIFY(!trend->isActive());

        // STOP: the servo-can and the shuoke drive in motion stop when F12 is pressed anywhere
        // in the window (servo-modbus has no stop command).
        const int can = connectionOf(dir, Family::ServoCan);
        const int shuoke = connectionOf(dir, Family::Shuoke);
        QVERIFY(can);
        QVERIFY(shuoke);
        int moving = 0;
        for (int id : {can, shuoke})
            w.hub()->run(
                id, 1, [](Drive &d) { return d.moveRelative(100000000, 300); },
                [&moving](const DriveResult &r) { moving += r.ok() ? 1 : 0; });
        QVERIFY(waitFor(
            dir, SIGNAL(statusChanged(int, int, dd::DriveStatus)),
            [&] { return moving == 2 && dir->info(can, 1).status.running && dir->info(shuoke, 1).status.running; },
            5000));
        QVERIFY(dir->info(can, 1).status.enabled);
        QSignalSpy traffic(w.hub(), &DriveHub::trafficRecorded);
        QSignalSpy stop(w.stopAction(), &QAction::triggered);
        QTest::keyClick(w.busTree(), Qt::Key_F12);
        QCOMPARE(stop.count(), 1);
        // The drives say they stand still (servo-can: its heartbeat state; shuoke: its status
        // reply), and the servo-can drive is disabled (STOP sends "stop and disable").
        QVERIFY(waitFor(
            dir, SIGNAL(statusChanged(int, int, dd::DriveStatus)),
            [&] {
                return !dir->info(can, 1).status.running && !dir->info(can, 1).status.enabled
                    && !dir->info(shuoke, 1).status.running;
            },
            2000));
        // The stop frames themselves, written by hand from the seeds (not by the codecs):
        // servo-can station 1, ID 0x65, command 0x28 "stop and disable"; shuoke RTU
        // emergency stop 0x3C, to the drive (address 1) and broadcast (address 0), CRC-16/MODBUS
        // low byte first.
        const QByteArray canStop = QByteArray::fromHex("01280000000000FF");
        const QByteArray shuokeStop = QByteArray::fromHex("013C003100");
        const QByteArray shuokeBroadcastStop = QByteArray::fromHex("003C0060C0");
        bool canStopSent = false;
        bool shuokeStopSent = false;
        QStringList shuokeSent; // for the failure message
        for (const QList<QVariant> &args : std::as_const(traffic)) {
            const TrafficRecord rec = args.at(1).value<TrafficRecord>();
            if (rec.direction != TrafficRecord::Direction::Tx)
                continue;
            if (args.at(0).toInt() == can && rec.isCan && rec.canId == 0x65 && rec.bytes == canStop)
                canStopSent = true;
            if (args.at(0).toInt() == shuoke) {
                shuokeSent << QString::fromLatin1(rec.bytes.toHex(' '));
                if (rec.bytes == shuokeStop || rec.bytes == shuokeBroadcastStop)
                    shuokeStopSent = true;
            }
        }
        QVERIFY2(canStopSent, "no 0x28 stop frame to servo-can station 1");
        QVERIFY2(shuokeStopSent,
                 qPrintable(QStringLiteral("no 0x3C emergency stop to the shuoke drive; sent: ")
                            + shuokeSent.join(QStringLiteral(" | "))));

        // Disconnecting everything empties the tree.
        w.connections()->disconnectAll();
        QCOMPARE(w.busTree()->topLevelItemCount(), 0);
    }
};

QTEST_MAIN(TestDemoBench)
#include "tst_demobench.moc"
