// The frame monitor: batched inserts into a bounded ring, pause that keeps recording, the
// filter (text, direction, link), saving, and the dock in the main window receiving the
// traffic of simulated drives with decoded meanings.
#include "core/drive/drive.h"
#include "core/drive/drivehub.h"
#include "core/drive/drivereply.h"
#include "core/protocol/servocan/servocan.h"
#include "tests/gui/simbenchthread.h"
#include "tests/support/requiretool.h"
#include "ui/framemonitor/framemonitordock.h"
#include "ui/framemonitor/framemonitorfilter.h"
#include "ui/framemonitor/framemonitormodel.h"
#include "ui/shell/mainwindow.h"

#include <QAction>
#include <QCanBus>
#include <QComboBox>
#include <QFile>
#include <QLineEdit>
#include <QLoggingCategory>
#include <QMenu>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>
#include <QTreeView>

using namespace dd;

namespace {
ConnectionSettings servoCan(const QString &can = QStringLiteral("virtualcan:can0"))
{
    ConnectionSettings s;
    s.family = Family::ServoCan;
    s.can = can;
    return s;
}

TrafficRecord heartbeat(int position, const QString &link = QStringLiteral("virtualcan:can0"))
{
    TrafficRecord r;
    r.direction = TrafficRecord::Direction::Rx;
    r.link = link;
    r.isCan = true;
    r.canId = 0x65;
    r.bytes = servocan::heartbeat(1, 0x88, position).data;
    r.wallclockMs = QDateTime::currentMSecsSinceEpoch();
    return r;
}

TrafficRecord keepAlive(const QString &link = QStringLiteral("virtualcan:can0"))
{
    TrafficRecord r = heartbeat(0, link);
    r.direction = TrafficRecord::Direction::Tx;
    r.bytes = servocan::keepAlive(1).data;
    return r;
}

bool waitForFlush(FrameMonitorModel &model)
{
    QSignalSpy spy(&model, &FrameMonitorModel::countsChanged);
    return spy.wait(2000);
}
} // namespace

class TestFrameMonitor : public QObject
{
    Q_OBJECT

    QTemporaryDir m_settingsDir;

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
        QCoreApplication::setApplicationName(QStringLiteral("tst_framemonitor"));
        QSettings().setValue(QStringLiteral("language"), QStringLiteral("en"));
    }

    void insertsInBatchesIntoABoundedRing()
    {
        FrameMonitorModel model;
        model.setCapacity(1000);
        model.describeConnection(1, servoCan());
        QSignalSpy inserted(&model, &QAbstractItemModel::rowsInserted);
        QSignalSpy reset(&model, &QAbstractItemModel::modelReset);
        for (int i = 0; i < 300; ++i)
            model.addRecord(1, heartbeat(i));
        QCOMPARE(model.rowCount(), 0); // nothing per frame
        QVERIFY(waitForFlush(model));
        QCOMPARE(model.rowCount(), 300);
        QCOMPARE(inserted.count(), 1); // one batch
        QCOMPARE(model.row(299).meaning, QStringLiteral("#1 heartbeat: idle, position 299"));

        // 5000 more than fit: the newest 1000 stay, in order; still a single update.
        for (int i = 300; i < 5300; ++i)
            model.addRecord(1, heartbeat(i));
        QVERIFY(waitForFlush(model));
        QCOMPARE(model.rowCount(), 1000);
        QCOMPARE(inserted.count() + reset.count(), 2);
        QCOMPARE(model.droppedCount(), quint64(4300));
        QCOMPARE(model.row(0).meaning, QStringLiteral("#1 heartbeat: idle, position 4300"));
        QCOMPARE(model.row(999).meaning, QStringLiteral("#1 heartbeat: idle, position 5299"));

        // A small batch into the full ring: the oldest go, the new ones are appended.
        QSignalSpy removed(&model, &QAbstractItemModel::rowsRemoved);
        for (int i = 0; i < 10; ++i)
            model.addRecord(1, keepAlive());
        QVERIFY(waitForFlush(model));
        QCOMPARE(model.rowCount(), 1000);
        QCOMPARE(removed.count(), 1);
        QCOMPARE(removed.at(0).at(2).toInt(), 9); // rows 0..9
        QCOMPARE(model.row(989).meaning, QStringLiteral("#1 heartbeat: idle, position 5299"));
        QCOMPARE(model.row(999).meaning, QStringLiteral("#1 keep-alive"));
        QCOMPARE(model.data(model.index(999, FrameMonitorModel::DirectionColumn)).toString(), QStringLiteral("TX"));
        QCOMPARE(model.data(model.index(999, FrameMonitorModel::DataColumn)).toString(),
                 QStringLiteral("065#01 08 00 00 00 00 00 FF"));

        model.clear();
        QCOMPARE(model.rowCount(), 0);
        QCOMPARE(model.droppedCount(), quint64(0));
    }

    void pauseHoldsTheViewButKeepsRecording()
    {
        FrameMonitorModel model;
        model.describeConnection(1, servoCan());
        model.addRecord(1, heartbeat(1));
        QVERIFY(waitForFlush(model));
        QCOMPARE(model.rowCount(), 1);
        model.setPaused(true);
        for (int i = 2; i <= 20; ++i)
            model.addRecord(1, heartbeat(i));
        model.flush();
        QCOMPARE(model.rowCount(), 1);
        QCOMPARE(model.heldCount(), 19);
        model.setPaused(false);
        QCOMPARE(model.rowCount(), 20);
        QCOMPARE(model.heldCount(), 0);
        QCOMPARE(model.row(19).meaning, QStringLiteral("#1 heartbeat: idle, position 20"));
    }

    void unknownConnectionIsNotGuessed()
    {
        FrameMonitorModel model; // no hub, nothing said about connection 7
        model.addRecord(7, heartbeat(1));
        model.flush();
        QCOMPARE(model.row(0).meaning, QStringLiteral("?"));
        TrafficRecord drop = heartbeat(1);
        drop.direction = TrafficRecord::Direction::Discarded;
        drop.note = QStringLiteral("late reply");
        model.addRecord(7, drop);
        model.flush();
        QCOMPARE(model.data(model.index(1, FrameMonitorModel::MeaningColumn)).toString(),
                 QStringLiteral("discarded [late reply]"));
    }

    void filterByTextDirectionAndLink()
    {
        FrameMonitorModel model;
        model.describeConnection(1, servoCan());
        model.describeConnection(2, servoCan(QStringLiteral("virtualcan:can1")));
        for (int i = 0; i < 5; ++i) {
            model.addRecord(1, heartbeat(i));
            model.addRecord(1, keepAlive());
        }
        model.addRecord(2, heartbeat(777, QStringLiteral("virtualcan:can1")));
        model.flush();
        QCOMPARE(model.rowCount(), 11);
        FrameMonitorFilter filter;
        filter.setFrameModel(&model);
        QCOMPARE(filter.rowCount(), 11);
        filter.setText(QStringLiteral("KEEP-alive")); // meaning, any case
        QCOMPARE(filter.rowCount(), 5);
        filter.setText(QStringLiteral("01 10 88")); // hex with spaces
        QCOMPARE(filter.rowCount(), 6);
        filter.setText(QStringLiteral("011088")); // hex without
        QCOMPARE(filter.rowCount(), 6);
        filter.setText(QStringLiteral("position 777"));
        QCOMPARE(filter.rowCount(), 1);
        filter.setText(QString());
        filter.setDirections(FrameMonitorFilter::Tx);
        QCOMPARE(filter.rowCount(), 5);
        filter.setDirections(FrameMonitorFilter::Rx);
        QCOMPARE(filter.rowCount(), 6);
        filter.setLink(QStringLiteral("virtualcan:can1"));
        QCOMPARE(filter.rowCount(), 1);
        QCOMPARE(filter.data(filter.index(0, FrameMonitorModel::MeaningColumn)).toString(),
                 QStringLiteral("#1 heartbeat: idle, position 777"));
        filter.setDirections(FrameMonitorFilter::Tx);
        QCOMPARE(filter.rowCount(), 0);
        // New frames pass through the filter as they come.
        filter.setDirections(FrameMonitorFilter::AllDirections);
        filter.setLink(QString());
        filter.setText(QStringLiteral("keep-alive"));
        model.addRecord(1, keepAlive());
        model.flush();
        QCOMPARE(filter.rowCount(), 6);
    }

    void shuokeRtuTrafficIsDescribed()
    {
        SimBenchThread sim;
        SimBenchOptions o;
        o.family = Family::Shuoke; // RTU on a pty
        QVERIFY(!sim.start(o));
        DriveHub hub;
        FrameMonitorModel model;
        model.setHub(&hub);
        int id = 0;
        hub.openConnection(sim.clientSettings(), [&](int newId, const Error &) { id = newId; });
        QVERIFY(waitUntil([&] { return id > 0; }, 5000));
        int finished = 0;
        hub.run(
            id, 1, [](Drive &d) { return d.jog(-500); }, [&](const DriveResult &) { ++finished; });
        hub.run(
            id, 1, [](Drive &d) { return d.stop(false); }, [&](const DriveResult &) { ++finished; });
        QVERIFY(waitUntil([&] { return finished == 2 && model.rowCount() >= 4; }, 5000));
        QStringList meanings;
        for (int i = 0; i < model.rowCount(); ++i)
            meanings << model.row(i).record.directionText() + QLatin1Char(' ') + model.row(i).meaning;
        QVERIFY2(meanings.contains(QStringLiteral("TX #1 Run at constant speed (signed) -500")),
                 qPrintable(meanings.join('\n')));
        QVERIFY2(meanings.contains(QStringLiteral("RX #1 Run at constant speed (signed): OK")),
                 qPrintable(meanings.join('\n')));
        QVERIFY2(meanings.contains(QStringLiteral("TX #1 Decelerate to stop")), qPrintable(meanings.join('\n')));
        QVERIFY(!meanings.join('\n').contains(QLatin1String("?")));
        // No line repeats its own meaning in the link's note.
        for (int i = 0; i < model.rowCount(); ++i) {
            const QString shown = model.index(i, FrameMonitorModel::MeaningColumn).data().toString();
            const QString note = model.row(i).record.note;
            if (!note.isEmpty() && model.row(i).meaning.contains(note, Qt::CaseInsensitive))
                QCOMPARE(shown, model.row(i).meaning);
        }
    }

    void dockInMainWindowShowsLiveTraffic()
    {
        DD_REQUIRE_TOOL(QCanBus::instance()->plugins().contains(QLatin1String("virtualcan")),
                        "Qt's virtualcan plugin is not installed");
        SimBenchThread sim;
        SimBenchOptions o;
        o.family = Family::ServoCan;
        o.can = QStringLiteral("virtualcan:auto");
        QVERIFY(!sim.start(o));
        QVERIFY(waitUntil([&] { return sim.call([&] { return sim.bench()->canBus()->isConnected(); }); }, 5000));

        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        auto *dock = w.findChild<FrameMonitorDock *>(QStringLiteral("frameMonitorDock"));
        QVERIFY(dock);
        QVERIFY(!dock->isVisible()); // View → Frame monitor
        QVERIFY(w.viewMenu()->actions().contains(dock->toggleViewAction()));
        QCOMPARE(dock->toggleViewAction()->text(), QStringLiteral("Frame monitor"));
        dock->toggleViewAction()->trigger();
        QVERIFY(dock->isVisible());
        QCOMPARE(dock->filter()->directions(), FrameMonitorFilter::Directions(FrameMonitorFilter::AllDirections));

        int id = 0;
        w.hub()->openConnection(sim.clientSettings(), [&](int newId, const Error &) { id = newId; });
        QVERIFY(waitUntil([&] { return id > 0; }, 5000));
        FrameMonitorModel *model = dock->model();
        auto has = [model](const QString &meaning, const char *dir) {
            for (int i = 0; i < model->rowCount(); ++i)
                if (model->row(i).meaning == meaning && model->row(i).record.directionText() == QLatin1String(dir))
                    return true;
            return false;
        };
        // Heartbeats from the drive; no keep-alive from DriveDesk to a drive at rest (it goes
        // only with a motion this program commands: the motion lease).
        QVERIFY(waitUntil([&] { return has(QStringLiteral("#1 heartbeat: idle, position 0"), "RX"); }, 5000));
        QVERIFY(!has(QStringLiteral("#1 keep-alive"), "TX"));
        // A read and its answer, described as a pair.
        bool done = false;
        w.hub()->run(
            id, 1, [](Drive &d) { return d.readParameters({75}); }, [&](const DriveResult &) { done = true; });
        QVERIFY(waitUntil([&] { return done && has(QStringLiteral("#1 P75 = 1"), "RX"); }, 5000));
        QVERIFY(has(QStringLiteral("#1 read P75"), "TX"));

        // The filter widgets drive the proxy.
        auto *text = dock->findChild<QLineEdit *>(QStringLiteral("frameFilterText"));
        QTest::keyClicks(text, QStringLiteral("P75"));
        QCOMPARE(dock->filter()->text(), QStringLiteral("P75"));
        QVERIFY(dock->filter()->rowCount() >= 2);
        for (int i = 0; i < dock->filter()->rowCount(); ++i)
            QVERIFY(dock->filter()
                        ->index(i, FrameMonitorModel::MeaningColumn)
                        .data()
                        .toString()
                        .contains(QLatin1String("P75")));
        auto *direction = dock->findChild<QComboBox *>(QStringLiteral("frameFilterDirection"));
        direction->setCurrentIndex(3); // RX only
        QCOMPARE(dock->filter()->directions(), FrameMonitorFilter::Directions(FrameMonitorFilter::Rx));
        QVERIFY(dock->filter()->rowCount() >= 1);
        for (int i = 0; i < dock->filter()->rowCount(); ++i)
            QCOMPARE(dock->filter()->index(i, FrameMonitorModel::DirectionColumn).data().toString(),
                     QStringLiteral("RX"));
        auto *link = dock->findChild<QComboBox *>(QStringLiteral("frameFilterLink"));
        QCOMPARE(link->count(), 2); // All links + this one
        QCOMPARE(link->itemText(1), sim.clientSettings().can);

        // Save: what is shown.
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("frames.csv"));
        const int shown = dock->filter()->rowCount();
        QVERIFY(!dock->saveTo(path));
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = f.readAll().trimmed().split('\n');
        QCOMPARE(lines.size(), shown + 1);
        QVERIFY(lines.last().contains(",RX,065,"));
        QVERIFY(lines.last().contains("P75 = 1"));

        // Pause: the view holds still while frames keep coming.
        QToolButton *pause = dock->findChild<QToolButton *>(QStringLiteral("framePause"));
        pause->click();
        QVERIFY(dock->isPaused());
        const int rows = model->rowCount();
        QVERIFY(waitUntil([&] { return model->heldCount() > 3; }, 3000));
        QCOMPARE(model->rowCount(), rows);
        pause->click();
        QVERIFY(model->rowCount() > rows);
    }
};

QTEST_MAIN(TestFrameMonitor)
#include "tst_framemonitor.moc"
