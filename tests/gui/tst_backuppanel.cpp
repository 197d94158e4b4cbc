// The Backup tab against a simulated servo-modbus drive: save a backup, change the drive,
// open the file, see the difference (ticked), restore it with read-back and a report, and
// the drive is back to the file's values. Bad files are refused with the reason and nothing
// is sent.
#include "core/params/backupfile.h"
#include "core/params/parameterdictionary.h"
#include "tests/gui/journaldatahome.h"
#include "tests/gui/simdrivefixture.h"
#include "ui/panels/backup/backupdifftable.h"
#include "ui/panels/backup/backuppanel.h"
#include "ui/panels/backup/restorereportdialog.h"
#include "ui/shell/languagemanager.h"

#include <QApplication>
#include <QCheckBox>
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QLoggingCategory>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

using namespace dd;

class TestBackupPanel : public QObject
{
    Q_OBJECT

    static QString statusOf(BackupDiffTable *t, int parameter)
    {
        const int row = t->rowOf(parameter);
        return row < 0 ? QString() : t->item(row, BackupDiffTable::Status)->data(Qt::UserRole + 1).toString();
    }

private slots:
    void initTestCase()
    {
        QLoggingCategory::setFilterRules(QStringLiteral("drivedesk.*.debug=false"));
        QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
    }

    void saveChangedFromDefaultsOnly()
    {
        // The save option writes a changed-only file, as backup --changed-only does: the
        // read-only values left out, marked as such in the file.
        QTemporaryDir dir;
        SimDriveFixture fx;
        QVERIFY(fx.start([](SimServoModbusDrive *d) { d->setParameter(10, 100); }));
        BackupPanel panel(fx.context());
        panel.setDriveInfo(fx.info);
        auto *changedOnly = panel.findChild<QCheckBox *>(QStringLiteral("saveChangedOnlyCheck"));
        QVERIFY(changedOnly);
        QVERIFY(!changedOnly->isChecked()); // a full backup unless asked
        const QString full = dir.filePath(QStringLiteral("full.json"));
        QSignalSpy saved(&panel, &BackupPanel::backupSaved);
        panel.saveBackup(full);
        QVERIFY(saved.wait(10000));
        changedOnly->setChecked(true);
        const QString changed = dir.filePath(QStringLiteral("changed.json"));
        panel.saveBackup(changed);
        QVERIFY(saved.wait(10000));
        BackupFile a, b;
        QVERIFY(!a.load(full));
        QVERIFY(!b.load(changed));
        QVERIFY(!a.isChangedOnly());
        QVERIFY(b.isChangedOnly());
        QVERIFY(a.values().value(2).has_value()); // PA2, the firmware: read-only
        QVERIFY(!b.values().value(2).has_value());
        QCOMPARE(b.values().value(10), std::optional<qint64>(100));
        QVERIFY(b.values().size() < a.values().size());
    }

    void backupChangeCompareRestore()
    {
        test::JournalDataHome data;
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        SimDriveFixture fx;
        QVERIFY(fx.start([](SimServoModbusDrive *d) {
            d->setParameter(10, 100);
            d->setParameter(20, quint16(-5));
        }));
        BackupPanel panel(fx.context());
        panel.setDriveInfo(fx.info);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QSignalSpy used(&panel, &DrivePanel::fileUsed);

        // Save.
        const QString path = dir.filePath(QStringLiteral("drive1.json"));
        QSignalSpy saved(&panel, &BackupPanel::backupSaved);
        panel.saveBackup(path);
        QVERIFY(panel.isBusy());
        QVERIFY(saved.wait(10000));
        QCOMPARE(used.count(), 1);
        QCOMPARE(used.first().at(0).toString(), path);
        BackupFile file;
        QVERIFY(!file.load(path));
        QCOMPARE(file.family(), std::optional<Family>(Family::ServoModbus));
        QCOMPARE(file.firmware(), fx.info.identity.firmware);
        QCOMPARE(file.values().value(10), std::optional<qint64>(100));
        QCOMPARE(file.values().value(20), std::optional<qint64>(-5));
        QVERIFY(panel.message().contains(QLatin1String("Saved")));

        // The drive changes (someone tuned it).
        fx.drive()->setParameter(10, 200);
        fx.drive()->setParameter(20, 7);

        // Open: the differences are listed and ticked; nothing is written yet.
        fx.traffic.clear();
        QSignalSpy compared(&panel, &BackupPanel::compared);
        QVERIFY(panel.openFile(path));
        QVERIFY(compared.wait(10000));
        QCOMPARE(used.count(), 2);
        QCOMPARE(fx.sentWithFunction(0x10), 0);
        BackupDiffTable *table = panel.diffTable();
        QCOMPARE(statusOf(table, 10), QStringLiteral("different"));
        QCOMPARE(statusOf(table, 20), QStringLiteral("different"));
        QCOMPARE(table->item(table->rowOf(10), BackupDiffTable::FileValue)->text(), QStringLiteral("100"));
        QCOMPARE(table->item(table->rowOf(10), BackupDiffTable::DriveValue)->text(), QStringLiteral("200"));
        QCOMPARE(table->checkedIndices(), QList<int>({10, 20}));
        QVERIFY(table->isRowHidden(table->rowOf(11))); // identical: hidden
        QVERIFY(!table->isRowHidden(table->rowOf(10)));
        QVERIFY(panel.findChild<QPushButton *>(QStringLiteral("applyBackupButton"))->isEnabled());

        // Restore only PA10 (PA20 unticked): written, verified, reported.
        table->setChecked(20, false);
        QCOMPARE(table->checkedIndices(), QList<int>({10}));
        QSignalSpy restored(&panel, &BackupPanel::restored);
        panel.applySelected();
        QVERIFY(restored.wait(10000));
        QVERIFY(restored.first().at(0).toBool());
        QCOMPARE(fx.drive()->parameter(10), quint16(100));
        QCOMPARE(fx.drive()->parameter(20), quint16(7)); // not ticked, not touched
        QCOMPARE(panel.lastReport().indices(RestoreReport::Outcome::Verified), QList<int>({10}));
        RestoreReportDialog *report = panel.reportDialog();
        QVERIFY(report);
        QVERIFY(report->isVisible());
        QCOMPARE(report->table()->rowCount(), 1);
        QCOMPARE(report->table()->item(0, 3)->data(Qt::UserRole).toString(), QStringLiteral("verified"));
        QVERIFY2(report->summary().contains(QLatin1String("1 written, 1 verified, 0 failed, 0 not attempted")),
                 qPrintable(report->summary()));
        // The save and the restore are in this drive's verification journal.
        const VerificationJournal::Entry journal = data.read(&fx.hub, fx.connectionId, fx.address, fx.info.identity);
        QCOMPARE(journal.verification.kind, QStringLiteral("restore"));
        QCOMPARE(journal.verification.sourceFile, path);
        QCOMPARE(journal.verification.entries.size(), 1);
        QCOMPARE(journal.verification.entries.first().key, QStringLiteral("PA10"));
        QCOMPARE(journal.backups.size(), 2);
        QCOMPARE(journal.backups.at(0).role, QStringLiteral("restore"));
        QCOMPARE(journal.backups.at(1).role, QStringLiteral("backup"));

        // Compared again afterwards: PA10 is the same now, PA20 still differs.
        QVERIFY(compared.wait(10000));
        QCOMPARE(statusOf(table, 10), QStringLiteral("same"));
        QCOMPARE(statusOf(table, 20), QStringLiteral("different"));
        report->close();
    }

    // Issue #26: Apply selected to an enabled or moving drive asks first, as Apply to several
    // drives does; Cancel sends nothing, Yes restores.
    void applyToAnEnergisedDriveAsksFirst()
    {
        QTemporaryDir dir;
        SimDriveFixture fx;
        QVERIFY(fx.start([](SimServoModbusDrive *d) { d->setParameter(10, 100); }));
        BackupPanel panel(fx.context());
        DriveInfo info = fx.info;
        info.status.enabled = true;
        info.status.running = true;
        panel.setDriveInfo(info);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        const QString path = dir.filePath(QStringLiteral("drive1.json"));
        QSignalSpy saved(&panel, &BackupPanel::backupSaved);
        panel.saveBackup(path);
        QVERIFY(saved.wait(10000));
        fx.drive()->setParameter(10, 200);
        QSignalSpy compared(&panel, &BackupPanel::compared);
        QVERIFY(panel.openFile(path));
        QVERIFY(compared.wait(10000));
        QCOMPARE(panel.diffTable()->checkedIndices(), QList<int>({10}));
        fx.traffic.clear();
        QString asked;
        QString question;
        const auto answer = [&](QMessageBox::StandardButton button) {
            QTimer::singleShot(0, &panel, [&, button] {
                QTRY_VERIFY_WITH_TIMEOUT(QApplication::activeModalWidget(), 10000);
                auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
                QVERIFY(box);
                asked = box->objectName();
                question = box->text();
                box->button(button)->click();
            });
        };
        answer(QMessageBox::Cancel);
        panel.applySelected();
        QCOMPARE(asked, QStringLiteral("energisedRestoreConfirmation"));
        QVERIFY2(question.contains(QLatin1String("moving")), qPrintable(question));
        QVERIFY2(panel.message().contains(QLatin1String("nothing was sent")), qPrintable(panel.message()));
        QCOMPARE(fx.sentWithFunction(0x10), 0);
        QCOMPARE(fx.drive()->parameter(10), quint16(200));

        asked.clear();
        answer(QMessageBox::Yes);
        QSignalSpy restored(&panel, &BackupPanel::restored);
        panel.applySelected();
        QCOMPARE(asked, QStringLiteral("energisedRestoreConfirmation"));
        QVERIFY(restored.wait(10000));
        QCOMPARE(fx.drive()->parameter(10), quint16(100));
        if (panel.reportDialog())
            panel.reportDialog()->close();
    }

    // Issue #10: the message line follows a live language switch (it is made again, not
    // left in the language it was written in).
    void messageFollowsALiveLanguageSwitch()
    {
        QTemporaryDir dir;
        SimDriveFixture fx;
        QVERIFY(fx.start());
        BackupPanel panel(fx.context());
        panel.setDriveInfo(fx.info);
        QSignalSpy saved(&panel, &BackupPanel::backupSaved);
        const QString path = dir.filePath(QStringLiteral("drive1.json"));
        panel.saveBackup(path);
        QVERIFY(saved.wait(10000));
        const QString english = panel.message();
        QVERIFY2(english.startsWith(QLatin1String("Saved")), qPrintable(english));
        LanguageManager language;
        QVERIFY(language.apply(LanguageManager::Language::Chinese));
        QCoreApplication::sendPostedEvents();
        const QString chinese = panel.message();
        QVERIFY2(!chinese.contains(QLatin1String("Saved")) && chinese.contains(QDir::toNativeSeparators(path)),
                 qPrintable(chinese));
        QVERIFY(language.apply(LanguageManager::Language::English));
        QCoreApplication::sendPostedEvents();
        QCOMPARE(panel.message(), english);
    }

    void badFilesAreRefusedAndNothingIsSent()
    {
        QTemporaryDir dir;
        SimDriveFixture fx;
        QVERIFY(fx.start());
        BackupPanel panel(fx.context());
        panel.setDriveInfo(fx.info);
        QSignalSpy used(&panel, &DrivePanel::fileUsed);
        QSignalSpy failed(&panel, &BackupPanel::operationFailed);

        // A backup whose values were edited by hand: the checksum no longer matches.
        BackupFile good;
        good.setFamily(Family::ServoModbus);
        good.setAddress(1);
        ParameterSet values;
        values.set(10, 100);
        good.setValues(values);
        const QString tampered = dir.filePath(QStringLiteral("tampered.json"));
        QVERIFY(!good.save(tampered));
        QFile f(tampered);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QByteArray bytes = f.readAll();
        f.close();
        QVERIFY(bytes.contains("\"value\": 100"));
        bytes.replace("\"value\": 100", "\"value\": 101");
        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write(bytes);
        f.close();

        fx.traffic.clear();
        QVERIFY(panel.openFile(tampered));
        QCOMPARE(failed.count(), 1);
        QVERIFY2(panel.message().contains(QLatin1String("nothing was sent")), qPrintable(panel.message()));
        QVERIFY(panel.findChild<QLabel *>(QStringLiteral("backupFileInfo"))
                    ->text()
                    .contains(QLatin1String("cannot be used")));
        QCOMPARE(panel.diffTable()->rowCount(), 0);
        QVERIFY(!panel.findChild<QPushButton *>(QStringLiteral("applyBackupButton"))->isEnabled());
        QCOMPARE(used.count(), 0);

        // A backup of another family.
        BackupFile other;
        other.setFamily(Family::ServoCan);
        other.setAddress(1);
        ParameterSet canValues;
        canValues.set(4, 1);
        other.setValues(canValues);
        const QString canPath = dir.filePath(QStringLiteral("servo-can.json"));
        QVERIFY(!other.save(canPath));
        QVERIFY(panel.openFile(canPath));
        QCOMPARE(failed.count(), 2);
        QVERIFY2(panel.message().contains(QLatin1String("servo-can")), qPrintable(panel.message()));
        QCOMPARE(panel.diffTable()->rowCount(), 0);

        // Not a backup at all (another kind of DriveDesk JSON): left to other panels.
        const QString dictionary = dir.filePath(QStringLiteral("dictionary.json"));
        QFile d(dictionary);
        QVERIFY(d.open(QIODevice::WriteOnly));
        d.write("{\"format\": \"drivedesk-dictionary\"}");
        d.close();
        QVERIFY(!panel.openFile(dictionary));
        QVERIFY(!BackupPanel::looksLikeBackup(dir.filePath(QStringLiteral("trend.csv"))));

        // Nothing reached the drive in all this.
        panel.applySelected();
        QVERIFY(fx.sentFrames().isEmpty());
    }
};

QTEST_MAIN(TestBackupPanel)
#include "tst_backuppanel.moc"
