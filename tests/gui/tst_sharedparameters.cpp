// One set of parameter values per drive, shared by its tabs: a restore, an EE operation or a
// write in the Parameters tab shows in every view of the drive (issue #10 item 2); undo after
// a write brings the old value back as a pending, marked edit (item 8); servo-modbus values
// written since the last EE-Set are marked as not saved to EEPROM.
#include "core/params/parameterdictionary.h"
#include "tests/gui/simdrivefixture.h"
#include "ui/panels/backup/backupdifftable.h"
#include "ui/panels/backup/backuppanel.h"
#include "ui/panels/backup/restorereportdialog.h"
#include "ui/panels/ee/eepanel.h"
#include "ui/panels/parameters/parameterspanel.h"
#include "ui/panels/parameters/parametertablemodel.h"
#include "ui/workspace/driveparameters.h"

#include <QAbstractButton>
#include <QApplication>
#include <QLoggingCategory>
#include <QMessageBox>
#include <QSignalSpy>
#include <QSortFilterProxyModel>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

using namespace dd;

class TestSharedParameters : public QObject
{
    Q_OBJECT

    static bool readAll(ParametersPanel &panel)
    {
        QSignalSpy done(&panel, &ParametersPanel::operationFinished);
        panel.readAll();
        return done.wait(10000) && done.last().at(0).toBool();
    }

    static QString cell(ParametersPanel &panel, int parameter, int column)
    {
        return panel.model()->index(panel.model()->rowOf(parameter), column).data().toString();
    }

    // Answers the next modal question with Yes (polls for it: it opens inside exec()).
    static void acceptNextQuestion()
    {
        auto *timer = new QTimer;
        timer->setInterval(10);
        QObject::connect(timer, &QTimer::timeout, timer, [timer] {
            auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
            if (!box)
                return;
            timer->stop();
            timer->deleteLater();
            box->button(QMessageBox::Yes)->click();
        });
        timer->start();
    }

private slots:
    void initTestCase()
    {
        QLoggingCategory::setFilterRules(QStringLiteral("drivedesk.*.debug=false"));
        QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
    }

    void restoreUpdatesTheParametersTab()
    {
        QTemporaryDir dir;
        SimDriveFixture fx;
        QVERIFY(fx.start([](SimServoModbusDrive *d) { d->setParameter(10, 100); }));
        DriveParameters shared(true);
        DriveContext ctx = fx.context();
        ctx.parameters = &shared;
        ParametersPanel params(ctx);
        params.setDriveInfo(fx.info);
        BackupPanel backup(ctx);
        backup.setDriveInfo(fx.info);
        backup.show();
        QVERIFY(QTest::qWaitForWindowExposed(&backup));

        const QString path = dir.filePath(QStringLiteral("b.json"));
        QSignalSpy saved(&backup, &BackupPanel::backupSaved);
        backup.saveBackup(path);
        QVERIFY(saved.wait(10000));

        fx.drive()->setParameter(10, 200);
        QVERIFY(readAll(params));
        QCOMPARE(cell(params, 10, ParameterTableModel::Value), QStringLiteral("200"));

        QSignalSpy compared(&backup, &BackupPanel::compared);
        QVERIFY(backup.openFile(path));
        QVERIFY(compared.wait(10000));
        QCOMPARE(backup.diffTable()->checkedIndices(), QList<int>({10}));
        QSignalSpy restored(&backup, &BackupPanel::restored);
        backup.applySelected();
        QVERIFY(restored.wait(10000));
        QCOMPARE(fx.drive()->parameter(10), quint16(100));
        // The Parameters tab follows at once: both columns show the restored value, and
        // there is nothing to write back.
        QCOMPARE(cell(params, 10, ParameterTableModel::Value), QStringLiteral("100"));
        QCOMPARE(cell(params, 10, ParameterTableModel::DriveValue), QStringLiteral("100"));
        QVERIFY(params.model()->changedIndices().isEmpty());
        if (backup.reportDialog())
            backup.reportDialog()->close();
    }

    void eeOperationsRereadAndTheUnsavedMark()
    {
        SimDriveFixture fx;
        QVERIFY(fx.start([](SimServoModbusDrive *d) { d->setEeBusyUs(0); }));
        DriveParameters shared(true);
        DriveContext ctx = fx.context();
        ctx.parameters = &shared;
        ParametersPanel params(ctx);
        params.setDriveInfo(fx.info);
        params.show();
        QVERIFY(QTest::qWaitForWindowExposed(&params));
        EePanel ee(ctx);
        ee.setDriveInfo(fx.info);
        QSignalSpy done(&params, &ParametersPanel::operationFinished);
        params.setActive(true); // shown: the first read
        QVERIFY(done.wait(10000));
        const quint16 saved = fx.drive()->eepromParameter(10);

        // A write from the Parameters tab: marked "not saved to EEPROM".
        params.model()->setData(params.model()->index(params.model()->rowOf(10), ParameterTableModel::Value),
                                QStringLiteral("4321"));
        params.writeAllChanged();
        QVERIFY(done.wait(10000));
        QVERIFY(params.model()->isUnsaved(10));
        QCOMPARE(cell(params, 10, ParameterTableModel::Mark), QString(QChar(0x25C7)));

        // EE-rd: the drive reloads its EEPROM; the tab reads again by itself and the mark goes.
        QSignalSpy eeDone(&ee, &EePanel::operationFinished);
        acceptNextQuestion();
        ee.runOperation(EeOperation::Reload);
        QVERIFY(eeDone.wait(10000));
        QVERIFY(eeDone.last().at(1).toBool());
        QVERIFY(done.wait(10000)); // the re-read
        QCOMPARE(cell(params, 10, ParameterTableModel::DriveValue), QString::number(saved));
        QVERIFY(!params.model()->isUnsaved(10));

        // Written again, then EE-Set: saved, no mark.
        params.model()->setData(params.model()->index(params.model()->rowOf(10), ParameterTableModel::Value),
                                QStringLiteral("77"));
        params.writeAllChanged();
        QVERIFY(done.wait(10000));
        QVERIFY(params.model()->isUnsaved(10));
        ee.runOperation(EeOperation::Save);
        QVERIFY(eeDone.wait(10000));
        QVERIFY(!params.model()->isUnsaved(10));
        QCOMPARE(fx.drive()->eepromParameter(10), quint16(77));
    }

    void undoAfterWriteRestoresTheOldValueAsAnEdit()
    {
        SimDriveFixture fx;
        QVERIFY(fx.start([](SimServoModbusDrive *d) { d->setParameter(10, 10); }));
        ParametersPanel params(fx.context());
        params.setDriveInfo(fx.info);
        params.show();
        QVERIFY(QTest::qWaitForWindowExposed(&params));
        QVERIFY(readAll(params));
        params.model()->setData(params.model()->index(params.model()->rowOf(10), ParameterTableModel::Value),
                                QStringLiteral("1234"));
        QSignalSpy done(&params, &ParametersPanel::operationFinished);
        params.writeAllChanged();
        QVERIFY(done.wait(10000));
        QCOMPARE(fx.drive()->parameter(10), quint16(1234));

        // Undo: the old value is back in the editor, marked as an undone write to send.
        QVERIFY(params.undoStack()->canUndo());
        params.undoStack()->undo();
        QCOMPARE(params.model()->editedValue(10), std::optional<qint64>(10));
        QVERIFY(params.model()->isChanged(10));
        QVERIFY(params.model()->isUndoneWrite(10));
        QCOMPARE(cell(params, 10, ParameterTableModel::Value), QStringLiteral("10"));
        QCOMPARE(cell(params, 10, ParameterTableModel::DriveValue), QStringLiteral("1234"));
        QCOMPARE(cell(params, 10, ParameterTableModel::Mark), QString(QChar(0x21B6)));
        QCOMPARE(cell(params, 10, ParameterTableModel::State), QStringLiteral("undone: not yet written back"));
        QCOMPARE(fx.drive()->parameter(10), quint16(1234)); // nothing sent by the undo itself

        // Writing it restores the drive.
        params.writeAllChanged();
        QVERIFY(done.wait(10000));
        QCOMPARE(fx.drive()->parameter(10), quint16(10));
        QVERIFY(!params.model()->isUndoneWrite(10));
    }
};

QTEST_MAIN(TestSharedParameters)
#include "tst_sharedparameters.moc"
