// The pieces behind the main window, fed by hand (no drives needed): the bus tree follows
// the DriveDirectory, the workspace makes one set of tabs per drive and keeps the tab, the
// status bar counts frames, errors and retries, and the small helpers.
#include "core/drive/drivehub.h"
#include "ui/bus/bustreewidget.h"
#include "ui/bus/drivedirectory.h"
#include "ui/bus/etaestimator.h"
#include "ui/bus/scanprogresswidget.h"
#include "ui/common/displaytext.h"
#include "ui/panels/overview/overviewpanel.h"
#include "ui/shell/statusbarwidget.h"
#include "ui/workspace/drivepanel.h"
#include "ui/workspace/driveworkspace.h"

#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTest>

using namespace dd;

namespace {
DiscoveredDrive discovered(Family f, int address, const QString &firmware)
{
    DiscoveredDrive d;
    d.family = f;
    d.address = address;
    d.firmware = firmware;
    return d;
}

ConnectionSettings serial(const QString &port, Family f)
{
    ConnectionSettings s;
    s.port = port;
    s.family = f;
    s.baud = 19200;
    return s;
}
} // namespace

class TestGuiParts : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void busTreeFollowsDirectory()
    {
        DriveHub hub;
        DriveDirectory dir(&hub);
        BusTreeWidget tree(&dir);
        dir.addConnection(7, serial(QStringLiteral("/dev/ttyUSB0"), Family::ServoModbus));
        QTreeWidgetItem *c = tree.connectionItem(7);
        QVERIFY(c);
        QVERIFY(c->text(BusTreeWidget::NameColumn).contains(QLatin1String("/dev/ttyUSB0")));
        QVERIFY(c->text(BusTreeWidget::NameColumn).contains(QLatin1String("servo-modbus")));

        dir.addDrive(7, discovered(Family::ServoModbus, 5, QStringLiteral("V2.1")));
        dir.addDrive(7, discovered(Family::ServoModbus, 2, QStringLiteral("V2.0")));
        QCOMPARE(c->childCount(), 2);
        QCOMPARE(c->child(0)->data(0, BusTreeWidget::AddressRole).toInt(), 2); // address order
        QTreeWidgetItem *d = tree.driveItem(7, 5);
        QVERIFY(d);
        QCOMPARE(d->text(BusTreeWidget::FirmwareColumn), QStringLiteral("V2.1"));
        QVERIFY2(d->text(BusTreeWidget::NameColumn).startsWith(QLatin1String("#5 ")), // address first
                 qPrintable(d->text(BusTreeWidget::NameColumn)));
        QVERIFY(c->text(BusTreeWidget::NameColumn).contains(QLatin1String("2 drive(s)")));

        // Narrow: position and firmware stay in view (no sideways scrolling); the name is
        // elided in the middle, its tool tip has the whole link.
        tree.resize(360, 300);
        tree.show();
        QVERIFY(QTest::qWaitForWindowExposed(&tree));
        QCOMPARE(tree.textElideMode(), Qt::ElideMiddle);
        QVERIFY(tree.header()->length() <= tree.viewport()->width());
        QVERIFY(tree.header()->sectionViewportPosition(BusTreeWidget::FirmwareColumn)
                    + tree.header()->sectionSize(BusTreeWidget::FirmwareColumn)
                <= tree.viewport()->width());
        QVERIFY(c->toolTip(BusTreeWidget::NameColumn).contains(QLatin1String("/dev/ttyUSB0")));

        // Live state from the hub's signal.
        DriveStatus s;
        s.online = true;
        s.running = true;
        s.enabled = true;
        s.positionValid = true;
        s.position = 12345;
        s.updatedMs = 1;
        emit hub.statusChanged(7, 5, s);
        QTRY_COMPARE(d->text(BusTreeWidget::StateColumn), QStringLiteral("Enabled · moving")); // in words
        QCOMPARE(d->text(BusTreeWidget::PositionColumn), QLocale().toString(12345));
        QVERIFY(d->icon(BusTreeWidget::StateColumn).isNull());

        // Alarm badge.
        emit hub.alarmChanged(7, 5, 21);
        QTRY_VERIFY(d->text(BusTreeWidget::StateColumn).contains(QLatin1String("Alarm 21")));
        QVERIFY(!d->icon(BusTreeWidget::StateColumn).isNull());
        emit hub.alarmChanged(7, 5, 0);
        QTRY_VERIFY(d->icon(BusTreeWidget::StateColumn).isNull());

        // Selection.
        QSignalSpy selected(&tree, &BusTreeWidget::driveSelected);
        tree.selectDrive(7, 2);
        QCOMPARE(selected.count(), 1);
        QCOMPARE(selected.last().at(0).toInt(), 7);
        QCOMPARE(selected.last().at(1).toInt(), 2);
        tree.setCurrentItem(c);
        QCOMPARE(selected.last().at(0).toInt(), 0);

        // Link lost, then removed.
        emit hub.linkLost(7, Error{ErrorCode::LinkClosed, QStringLiteral("unplugged")});
        QTRY_VERIFY(c->text(BusTreeWidget::NameColumn).contains(QLatin1String("link lost")));
        dir.removeConnection(7);
        QVERIFY(!tree.connectionItem(7));
    }

    void workspaceMakesTabsPerDriveAndKeepsTheTab()
    {
        DriveHub hub;
        DriveDirectory dir(&hub);
        DriveWorkspace ws(&dir);
        dir.addConnection(1, serial(QStringLiteral("/dev/ttyS0"), Family::Shuoke));
        dir.addDrive(1, discovered(Family::Shuoke, 1, QString()));
        dir.addDrive(1, discovered(Family::Shuoke, 2, QString()));

        QVERIFY(!ws.tabsFor(1, 1));
        ws.showDrive(1, 1);
        QTabWidget *t1 = ws.tabsFor(1, 1);
        QVERIFY(t1);
        QCOMPARE(ws.currentWidget(), t1);
        QVERIFY(t1->count() >= 1);
        auto *overview = qobject_cast<OverviewPanel *>(t1->widget(0));
        QVERIFY(overview);
        QCOMPARE(overview->context().connectionId, 1);
        QCOMPARE(overview->context().address, 1);
        QCOMPARE(overview->context().family, Family::Shuoke);
        QCOMPARE(t1->tabText(0), QStringLiteral("Overview"));
        QVERIFY(overview->isActive());

        ws.showDrive(1, 2);
        QTabWidget *t2 = ws.tabsFor(1, 2);
        QVERIFY(t2 && t2 != t1);
        QVERIFY(!overview->isActive()); // only the shown drive's panel polls
        ws.showDrive(1, 1);
        QCOMPARE(ws.tabsFor(1, 1), t1); // the same panels: their state is kept
        QVERIFY(overview->isActive());

        // Status reaches the panels of that drive.
        DriveStatus s;
        s.online = true;
        s.updatedMs = 1;
        s.alarmCode = 4;
        emit hub.statusChanged(1, 1, s);
        QTRY_COMPARE(overview->driveInfo().status.alarmCode, 4);

        // Closing the connection removes its tabs and shows the hint.
        dir.removeConnection(1);
        QVERIFY(!ws.tabsFor(1, 1));
        QCOMPARE(ws.currentDrive().connectionId, 0);
        QVERIFY(qobject_cast<QLabel *>(ws.currentWidget()));
    }

    void statusBarCountsFramesErrorsRetries()
    {
        DriveHub hub;
        DriveDirectory dir(&hub);
        StatusBarWidget bar(&hub, &dir);
        TrafficRecord tx;
        tx.direction = TrafficRecord::Direction::Tx;
        TrafficRecord retry = tx;
        retry.note = QStringLiteral("read 0x64 (retry 1)");
        TrafficRecord drop;
        drop.direction = TrafficRecord::Direction::Discarded;
        for (int i = 0; i < 10; ++i)
            emit hub.trafficRecorded(1, tx);
        emit hub.trafficRecorded(1, retry);
        emit hub.trafficRecorded(1, drop);
        QCOMPARE(bar.retryCount(), quint64(1));
        QCOMPARE(bar.errorCount(), quint64(1));
        bar.countError(Error{ErrorCode::Timeout, QStringLiteral("No reply")});
        bar.countError(Error{ErrorCode::Cancelled, QStringLiteral("cancelled")}); // not an error
        QCOMPARE(bar.errorCount(), quint64(2));
        QCOMPARE(bar.currentMessage(), QStringLiteral("No reply"));
        auto *errors = bar.findChild<QLabel *>(QStringLiteral("errorCount"));
        QCOMPARE(errors->text(), QStringLiteral("Errors: 2"));
        // Frames per second over the first window (a coarse one-second timer, which may fire
        // early, and more so on a loaded machine): 12 frames, within a generous window.
        auto *fps = bar.findChild<QLabel *>(QStringLiteral("framesPerSecond"));
        QTRY_VERIFY_WITH_TIMEOUT(bar.framesPerSecond() > 0, 3000);
        QVERIFY(fps->text().contains(QLatin1String("frames/s")));
        QVERIFY2(bar.framesPerSecond() >= 6 && bar.framesPerSecond() <= 12 / 0.75,
                 qPrintable(QString::number(bar.framesPerSecond())));
        bar.resetCounters();
        QCOMPARE(bar.errorCount(), quint64(0));

        auto *link = bar.findChild<QLabel *>(QStringLiteral("linkState"));
        QCOMPARE(link->text(), QStringLiteral("Not connected"));
        dir.addConnection(3, serial(QStringLiteral("/dev/ttyUSB3"), Family::ServoModbus));
        QCOMPARE(link->text(), QStringLiteral("Connected: /dev/ttyUSB3"));
        emit hub.linkLost(3, Error{ErrorCode::LinkClosed, QStringLiteral("gone")});
        QTRY_COMPARE(link->text(), QStringLiteral("Link lost: /dev/ttyUSB3"));
    }

    void etaEstimator()
    {
        EtaEstimator eta;
        eta.start();
        QCOMPARE(eta.remainingMs(), qint64(-1));
        eta.setElapsedForTest(2000);
        eta.update(10, 50);
        QCOMPARE(eta.remainingMs(), qint64(8000)); // 200 ms a step, 40 steps left
        eta.update(50, 50);
        QCOMPARE(eta.remainingMs(), qint64(0));
        QCOMPARE(EtaEstimator::format(8000), QStringLiteral("about 8 s"));
        QCOMPARE(EtaEstimator::format(150000), QStringLiteral("about 3 min"));
        QVERIFY(EtaEstimator::format(-1).isEmpty());
    }

    void scanProgressShowsEtaAndCancels()
    {
        ScanProgressWidget w;
        QVERIFY(w.isHidden());
        w.begin(QStringLiteral("Scanning"));
        QVERIFY(!w.isHidden());
        w.setProgress(5, 32);
        w.setFound(1);
        QVERIFY(w.etaText().contains(QLatin1String("1 drive(s) found")));
        QVERIFY(w.etaText().contains(QLatin1String("about")));
        QSignalSpy cancel(&w, &ScanProgressWidget::cancelRequested);
        QTest::mouseClick(w.findChild<QPushButton *>(QStringLiteral("cancelScan")), Qt::LeftButton);
        QCOMPARE(cancel.count(), 1);
        w.finish();
        QVERIFY(w.isHidden());
    }

    void displayText()
    {
        DriveStatus s;
        QCOMPARE(DisplayText::motionState(s), QStringLiteral("Unknown"));
        s.updatedMs = 1;
        QCOMPARE(DisplayText::motionState(s), QStringLiteral("Offline"));
        s.online = true;
        s.running = true;
        s.enabled = true;
        s.alarmCode = 3;
        QCOMPARE(DisplayText::summary(s), QStringLiteral("Alarm 3 · Enabled · moving"));
        s.alarmCode = 0;
        s.running = false;
        s.enabled = false;
        QCOMPARE(DisplayText::summary(s), QStringLiteral("Disabled · at rest"));
        QCOMPARE(DisplayText::position(s), QStringLiteral("—"));
        QCOMPARE(DisplayText::driveName(Family::ServoCan, 4), QStringLiteral("Servo (CAN) #4"));
    }
};

QTEST_MAIN(TestGuiParts)
#include "tst_guiparts.moc"
