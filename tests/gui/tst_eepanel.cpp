// The EEPROM tab against a simulated servo-modbus drive: EE-Set with progress until the
// drive reports completion (legacy format, polled), a destructive operation that asks
// first (cancel: nothing sent; yes: done), a drive without EE operations, and which tabs a
// drive gets.
#include "tests/gui/journaldatahome.h"
#include "tests/gui/simdrivefixture.h"
#include "ui/panels/ee/eepanel.h"
#include "ui/workspace/drivepanel.h"
#include "ui/workspace/drivepanels.h"

#include <QApplication>
#include <QLabel>
#include <QLoggingCategory>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>
#include <QTimer>

using namespace dd;

class TestEePanel : public QObject
{
    Q_OBJECT

    // Answers the next modal message box with `button`; its text goes to *text.
    static void answerMessageBox(QMessageBox::StandardButton button, QString *text)
    {
        auto *timer = new QTimer;
        timer->setInterval(10);
        QObject::connect(timer, &QTimer::timeout, timer, [timer, button, text] {
            auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
            if (!box)
                return;
            *text = box->text();
            timer->stop();
            timer->deleteLater();
            box->button(button)->click();
        });
        timer->start();
    }

private slots:
    void initTestCase()
    {
        QLoggingCategory::setFilterRules(QStringLiteral("drivedesk.*.debug=false"));
        QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
        qRegisterMetaType<dd::EeOperation>();
    }

    void saveShowsProgressUntilTheDriveIsDone()
    {
        test::JournalDataHome data;
        SimDriveFixture fx;
        QVERIFY(fx.start([](SimServoModbusDrive *d) {
            d->setFirmware(7000); // the legacy format: started, then polled until done
            d->setEeBusyUs(400000);
            d->setParameter(10, 321);
        }));
        EePanel panel(fx.context());
        panel.setDriveInfo(fx.info);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        auto *reason = panel.findChild<QLabel *>(QStringLiteral("eeUnavailableReason"));
        QVERIFY(!reason->isVisible());
        QVERIFY(panel.button(EeOperation::Save)->isEnabled());
        QCOMPARE(panel.button(EeOperation::Save)->text(), QStringLiteral("EE-Set"));
        QVERIFY(fx.drive()->eepromParameter(10) != 321);

        QSignalSpy finished(&panel, &EePanel::operationFinished);
        fx.traffic.clear();
        QTest::mouseClick(panel.button(EeOperation::Save), Qt::LeftButton); // no question for EE-Set
        QVERIFY(panel.isBusy());
        auto *progress = panel.findChild<QProgressBar *>(QStringLiteral("eeProgress"));
        QVERIFY(progress->isVisible());
        QVERIFY(!panel.button(EeOperation::Save)->isEnabled());
        QVERIFY(!panel.button(EeOperation::FactoryDefaults)->isEnabled());
        QVERIFY2(panel.message().contains(QLatin1String("EE-Set running")), qPrintable(panel.message()));
        // Still running after the first reply: the drive reports "busy" until it is done.
        QVERIFY(QTest::qWaitFor([&] { return fx.drive()->eeRunning(); }, 2000));
        QVERIFY(panel.isBusy());
        QVERIFY(progress->isVisible());

        QVERIFY(finished.wait(5000));
        QCOMPARE(finished.last().at(0).value<EeOperation>(), EeOperation::Save);
        QVERIFY(finished.last().at(1).toBool());
        QVERIFY(!panel.isBusy());
        QVERIFY(!progress->isVisible());
        QVERIFY2(panel.message().contains(QLatin1String("EE-Set done")), qPrintable(panel.message()));
        QVERIFY(panel.button(EeOperation::Save)->isEnabled());
        QCOMPARE(fx.drive()->eeOperationsCompleted(), 1);
        QCOMPARE(fx.drive()->eepromParameter(10), quint16(321));
        QVERIFY(fx.sentWithFunction(0x06) >= 2); // started and polled
        // The EE-Set is in this drive's verification journal (issue 27: it was not).
        const VerificationJournal::Entry journal = data.read(&fx.hub, fx.connectionId, fx.address, fx.info.identity);
        QCOMPARE(journal.ee.operation, QStringLiteral("EE-Set"));
        QVERIFY(journal.ee.ok);
        QVERIFY(journal.ee.message.isEmpty());
    }

    void destructiveOperationAsksFirst()
    {
        SimDriveFixture fx;
        QVERIFY(fx.start([](SimServoModbusDrive *d) { d->setParameter(10, 555); }));
        const quint16 factory = SimServoModbusDrive::factoryDefaults(fx.drive()->config())[10];
        QVERIFY(factory != 555);
        EePanel panel(fx.context());
        panel.setDriveInfo(fx.info);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));

        // Cancel: nothing is sent.
        fx.traffic.clear();
        QString question;
        answerMessageBox(QMessageBox::Cancel, &question);
        panel.runOperation(EeOperation::FactoryDefaults);
        QVERIFY2(question.contains(QLatin1String("factory defaults")), qPrintable(question));
        QVERIFY(question.contains(QLatin1String("EE-dEF")));
        QVERIFY(!panel.isBusy());
        QVERIFY(panel.message().contains(QLatin1String("cancelled")));
        QVERIFY(fx.sentFrames().isEmpty());
        QCOMPARE(fx.drive()->eeOperationsCompleted(), 0);

        // Yes: the drive goes back to its factory values.
        QSignalSpy started(&panel, &EePanel::operationStarted);
        QSignalSpy finished(&panel, &EePanel::operationFinished);
        answerMessageBox(QMessageBox::Yes, &question);
        panel.runOperation(EeOperation::FactoryDefaults);
        QCOMPARE(started.count(), 1);
        QVERIFY(finished.wait(5000));
        QVERIFY(finished.last().at(1).toBool());
        QCOMPARE(fx.drive()->eeOperationsCompleted(), 1);
        QVERIFY(fx.drive()->lastEeOperation() == servomodbus::EeOp::Defaults);
        QCOMPARE(fx.drive()->parameter(10), factory);
        QVERIFY(panel.message().contains(QLatin1String("the Parameters tab reads them again")));
    }

    void unavailableShowsWhy()
    {
        DriveContext ctx;
        ctx.family = Family::ServoCan;
        EePanel panel(ctx);
        DriveInfo info;
        info.valid = true;
        info.unsupportedReasons.insert(Capability::EeOperations, QStringLiteral("no EEPROM commands here"));
        panel.setDriveInfo(info);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        for (EeOperation op : EePanel::operations())
            QVERIFY(!panel.button(op)->isEnabled());
        auto *reason = panel.findChild<QLabel *>(QStringLiteral("eeUnavailableReason"));
        QVERIFY(reason->isVisible());
        QCOMPARE(reason->text(), QStringLiteral("no EEPROM commands here"));
        panel.runOperation(EeOperation::Save);
        QVERIFY(!panel.isBusy());
    }

    void eachDriveGetsItsTabs()
    {
        QWidget host;
        auto ids = [&host](Family family, Capabilities caps) {
            DriveContext ctx;
            ctx.family = family;
            ctx.capabilities = caps;
            QStringList out;
            const QList<DrivePanel *> panels = createDrivePanels(ctx, &host);
            for (DrivePanel *p : panels)
                out << p->panelId();
            qDeleteAll(panels);
            return out;
        };
        const QStringList modbus = ids(Family::ServoModbus, {});
        QVERIFY(modbus.contains(QLatin1String("parameters")));
        QVERIFY(modbus.contains(QLatin1String("backup")));
        QVERIFY(modbus.contains(QLatin1String("ee")));
        const QStringList can = ids(Family::ServoCan, Capability::ReadParameters | Capability::WriteParameters);
        QVERIFY(can.contains(QLatin1String("parameters")));
        QVERIFY(can.contains(QLatin1String("backup")));
        QVERIFY(!can.contains(QLatin1String("ee")));
    }
};

QTEST_MAIN(TestEePanel)
#include "tst_eepanel.moc"
