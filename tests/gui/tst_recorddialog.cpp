// File → Commissioning record… offscreen, against a simulated servo-modbus drive: the drive is
// listed, the header is remembered between sessions, the preview shows pages, and the saved
// PDF (read back with pdftotext) holds the drive, the header and the JSON's SHA-256.
#include "tests/gui/simdrivefixture.h"
#include "tests/support/pdftext.h"
#include "tests/support/recordfixture.h"
#include "ui/bus/drivedirectory.h"
#include "ui/report/recorddialog.h"
#include "ui/report/recordsession.h"

#include <QCryptographicHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLineEdit>
#include <QListWidget>
#include <QLoggingCategory>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using namespace dd;

class TestRecordDialog : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true); // QSettings and the journal stay out of $HOME
        QCoreApplication::setOrganizationName(QStringLiteral("DriveDeskTest"));
        QCoreApplication::setApplicationName(QStringLiteral("tst_recorddialog"));
        QSettings().remove(QStringLiteral("commissioningRecord"));
        QLoggingCategory::setFilterRules(QStringLiteral("drivedesk.*.debug=false"));
        QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
    }

    void chooseFillPreviewSave()
    {
        QTemporaryDir dir;
        SimDriveFixture fx;
        QVERIFY(fx.start([](SimServoModbusDrive *d) { d->setParameter(12, 4321); }));
        DriveDirectory directory(&fx.hub);
        directory.addConnection(fx.connectionId, fx.hub.connectionSettings(fx.connectionId));
        DiscoveredDrive found;
        found.family = Family::ServoModbus;
        found.address = fx.address;
        found.firmware = fx.info.identity.firmware;
        directory.addDrive(fx.connectionId, found);
        QTRY_VERIFY_WITH_TIMEOUT(directory.info(fx.connectionId, fx.address).valid, 10000);
        RecordSession session(&fx.hub, &directory);

        {
            RecordDialog dialog(&directory, &session);
            dialog.show();
            QVERIFY(QTest::qWaitForWindowExposed(&dialog));
            QCOMPARE(dialog.driveList()->count(), 1);
            QVERIFY(dialog.driveList()->item(0)->text().contains(QStringLiteral("at address 1")));
            QCOMPARE(dialog.driveList()->item(0)->checkState(), Qt::Checked);
            dialog.findChild<QLineEdit *>(QStringLiteral("recordMachine"))->setText(QStringLiteral("Press line 3"));
            dialog.findChild<QLineEdit *>(QStringLiteral("recordEngineer"))->setText(QStringLiteral("Li Wei"));
            dialog.findChild<QPlainTextEdit *>(QStringLiteral("recordNotes"))->setPlainText(QStringLiteral("EE saved"));

            QSignalSpy shown(&dialog, &RecordDialog::previewShown);
            dialog.preview();
            QVERIFY(shown.wait(20000));
            QVERIFY(shown.at(0).at(0).toInt() >= 2); // summary and drive pages at least
            QCOMPARE(dialog.previewPages(), shown.at(0).at(0).toInt());

            // A tuning run of this drive is added; a bad run file is not (the message says why).
            TuningRun run = test::fixtureRun(fx.address);
            run.family = QStringLiteral("servo-modbus");
            run.tuning = {{5, QStringLiteral("PA5"), QString(), 123}};
            const QString runPath = dir.filePath(QStringLiteral("axis-step.ddrun"));
            QVERIFY(!run.save(runPath));
            const QString badPath = dir.filePath(QStringLiteral("bad.ddrun"));
            QFile bad(badPath);
            QVERIFY(bad.open(QIODevice::WriteOnly));
            bad.write("not json");
            bad.close();
            QVERIFY(!dialog.addRunFiles({runPath, badPath}));
            QCOMPARE(dialog.runList()->count(), 1);
            QVERIFY(dialog.runList()->item(0)->text().contains(QStringLiteral("axis-step — Velocity step")));
            QVERIFY2(dialog.message().contains(QStringLiteral("bad.ddrun is not valid JSON")),
                     qPrintable(dialog.message()));

            QSignalSpy saved(&dialog, &RecordDialog::recordSaved);
            const QString pdf = dir.filePath(QStringLiteral("record.pdf"));
            dialog.saveTo(pdf);
            QVERIFY(saved.wait(20000));
            const QString jsonPath = saved.at(0).at(1).toString();
            QCOMPARE(jsonPath, dir.filePath(QStringLiteral("record.json")));
            QFile json(jsonPath);
            QVERIFY(json.open(QIODevice::ReadOnly));
            const QString sha = QString::fromLatin1(
                QCryptographicHash::hash(json.readAll(), QCryptographicHash::Sha256).toHex());
            QCOMPARE(saved.at(0).at(2).toString(), sha);
            // The drive's link health: core/link's figures for its address since the session began.
            QVERIFY(json.seek(0));
            const QJsonObject health = QJsonDocument::fromJson(json.readAll())
                                           .object()
                                           .value(QStringLiteral("drives"))
                                           .toArray()
                                           .at(0)
                                           .toObject()
                                           .value(QStringLiteral("linkHealth"))
                                           .toObject();
            QVERIFY(health.value(QStringLiteral("measured")).toBool());
            QVERIFY(health.value(QStringLiteral("requests")).toInt() >= 4);
            QCOMPARE(health.value(QStringLiteral("answered")).toInt(),
                     health.value(QStringLiteral("requests")).toInt());

            QString error;
            const QString text = test::pdfText(pdf, 0, 0, &error);
            QVERIFY2(!text.isEmpty(), qPrintable(error));
            QVERIFY(text.contains(sha));
            QVERIFY(text.contains(QStringLiteral("Press line 3")));
            QVERIFY(text.contains(QStringLiteral("Servo (Modbus) at address 1")));
            QVERIFY(text.contains(fx.info.identity.firmware));
            QVERIFY2(
                QRegularExpression(QStringLiteral("\\b12\\s+PA12\\s+Parameter PA12\\s+4321\\b")).match(text).hasMatch(),
                "PA12 with its value in the appendix");

            QVERIFY(text.contains(QStringLiteral("Tuning runs (1)")));
            QVERIFY(QRegularExpression(QStringLiteral("PA5\\s+Parameter PA5\\s+123")).match(text).hasMatch());

            // A run of a drive that is not in the record: refused with the reason, nothing written.
            run.address = 9;
            const QString otherPath = dir.filePath(QStringLiteral("axis9.ddrun"));
            QVERIFY(!run.save(otherPath));
            QVERIFY(dialog.addRunFiles({otherPath}));
            QSignalSpy refused(&dialog, &RecordDialog::failed);
            dialog.saveTo(dir.filePath(QStringLiteral("other.pdf")));
            QVERIFY(refused.wait(20000));
            QVERIFY2(refused.at(0).at(0).toString().contains(QStringLiteral("axis9.ddrun was taken on servo-modbus at "
                                                                            "address 9, which is not in this record")),
                     qPrintable(refused.at(0).at(0).toString()));
            QVERIFY(!QFile::exists(dir.filePath(QStringLiteral("other.pdf"))));
            dialog.runList()->item(1)->setSelected(true);
            dialog.findChild<QPushButton *>(QStringLiteral("recordRemoveRuns"))->click();
            QCOMPARE(dialog.runList()->count(), 1);

            // No drive chosen: said, nothing read.
            dialog.driveList()->item(0)->setCheckState(Qt::Unchecked);
            QSignalSpy failed(&dialog, &RecordDialog::failed);
            dialog.preview();
            QCOMPARE(failed.size(), 1);
            QVERIFY(failed.at(0).at(0).toString().contains(QStringLiteral("at least one drive")));
            dialog.accept();
        }
        // The header is remembered for the next record.
        RecordDialog again(&directory, &session);
        QCOMPARE(again.findChild<QLineEdit *>(QStringLiteral("recordMachine"))->text(), QStringLiteral("Press line 3"));
        QCOMPARE(again.findChild<QLineEdit *>(QStringLiteral("recordEngineer"))->text(), QStringLiteral("Li Wei"));
        QCOMPARE(again.findChild<QPlainTextEdit *>(QStringLiteral("recordNotes"))->toPlainText(),
                 QStringLiteral("EE saved"));
    }
};

QTEST_MAIN(TestRecordDialog)
#include "tst_recorddialog.moc"
