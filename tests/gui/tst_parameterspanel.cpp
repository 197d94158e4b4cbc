// The Parameters tab against a simulated servo-modbus drive: edit in the table and write
// (the simulated drive's value changes, the row is verified), refused values (nothing is
// sent), undo/redo, search; the table model alone for write-only parameters (shuoke
// dictionary) and names in the UI language.
#include "core/drive/drive.h"
#include "core/drive/drivereply.h"
#include "core/params/parameterdictionary.h"
#include "tests/gui/journaldatahome.h"
#include "tests/gui/simdrivefixture.h"
#include "ui/panels/backup/backuppanel.h"
#include "ui/panels/ee/eepanel.h"
#include "ui/panels/parameters/parametercontextmenu.h"
#include "ui/panels/parameters/parameterspanel.h"
#include "ui/panels/parameters/parametertablemodel.h"
#include "ui/shell/languagemanager.h"

#include <QApplication>
#include <QClipboard>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QLoggingCategory>
#include <QPushButton>
#include <QSignalSpy>
#include <QSortFilterProxyModel>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using namespace dd;

class TestParametersPanel : public QObject
{
    Q_OBJECT

    static QModelIndex valueIndex(ParametersPanel &panel, int parameter, int column = ParameterTableModel::Value)
    {
        const QModelIndex source = panel.model()->index(panel.model()->rowOf(parameter), column);
        return panel.proxy()->mapFromSource(source);
    }

    static QString cell(ParametersPanel &panel, int parameter, int column)
    {
        return valueIndex(panel, parameter, column).data().toString();
    }

    // Opens the Value editor of `parameter`, types `text` and presses Enter.
    static QLineEdit *typeValue(ParametersPanel &panel, int parameter, const QString &text)
    {
        const QString name = QStringLiteral("parameterValueEditor");
        // A closed editor is deleted later: wait until the previous one is gone.
        if (!QTest::qWaitFor([&] { return !panel.view()->findChild<QLineEdit *>(name); }, 2000))
            return nullptr;
        const QModelIndex index = valueIndex(panel, parameter);
        panel.view()->setCurrentIndex(index);
        panel.view()->edit(index);
        auto *editor = panel.view()->findChild<QLineEdit *>(name);
        if (!editor)
            return nullptr;
        editor->selectAll();
        QTest::keyClicks(editor, text);
        QTest::keyClick(editor, Qt::Key_Return);
        return editor;
    }

    static bool readAll(ParametersPanel &panel)
    {
        QSignalSpy done(&panel, &ParametersPanel::operationFinished);
        panel.readAll();
        return done.wait(10000) && done.last().at(0).toBool();
    }

    static std::shared_ptr<const ParameterDictionary> bundled(Family f)
    {
        return {&ParameterDictionary::bundled(f), [](const ParameterDictionary *) {}};
    }

private slots:
    void initTestCase()
    {
        QLoggingCategory::setFilterRules(QStringLiteral("drivedesk.*.debug=false"));
        QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
    }

    void editAndWriteChangesTheDrive()
    {
        test::JournalDataHome data;
        SimDriveFixture fx;
        QVERIFY(fx.start([](SimServoModbusDrive *d) {
            d->setParameter(10, 10);
            d->setParameter(12, 12);
        }));
        ParametersPanel panel(fx.context());
        panel.setDriveInfo(fx.info);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QVERIFY(readAll(panel));
        QCOMPARE(cell(panel, 10, ParameterTableModel::Value), QStringLiteral("10"));
        QCOMPARE(cell(panel, 10, ParameterTableModel::DriveValue), QStringLiteral("10"));
        QCOMPARE(cell(panel, 51, ParameterTableModel::Name), QStringLiteral("Drive address"));
        QCOMPARE(cell(panel, 51, ParameterTableModel::Range), QStringLiteral("0 … 255"));
        QCOMPARE(cell(panel, 2, ParameterTableModel::Access), QStringLiteral("read-only"));
        QVERIFY(!(valueIndex(panel, 2).flags() & Qt::ItemIsEditable));

        // Edit in the table: the cell shows the new value and the mark; the drive is untouched.
        QVERIFY(typeValue(panel, 10, QStringLiteral("1234")));
        QVERIFY(QTest::qWaitFor([&] { return panel.model()->editedValue(10).has_value(); }, 2000));
        QCOMPARE(cell(panel, 10, ParameterTableModel::Value), QStringLiteral("1234"));
        QCOMPARE(cell(panel, 10, ParameterTableModel::Mark), QString(QChar(0x25CF)));
        QCOMPARE(cell(panel, 10, ParameterTableModel::DriveValue), QStringLiteral("10"));
        QCOMPARE(fx.drive()->parameter(10), quint16(10));
        QVERIFY(panel.findChild<QPushButton *>(QStringLiteral("writeChangedButton"))->isEnabled());

        // A second edit; Write selected writes only the selected row.
        QVERIFY(typeValue(panel, 12, QStringLiteral("-7")));
        QVERIFY(QTest::qWaitFor([&] { return panel.model()->editedValue(12).has_value(); }, 2000));
        panel.view()->clearSelection();
        panel.view()->selectRow(valueIndex(panel, 12).row());
        QSignalSpy done(&panel, &ParametersPanel::operationFinished);
        panel.writeSelected();
        QVERIFY(done.wait(10000));
        QVERIFY(done.last().at(0).toBool());
        QCOMPARE(qint16(fx.drive()->parameter(12)), qint16(-7));
        QCOMPARE(fx.drive()->parameter(10), quint16(10));
        QCOMPARE(panel.model()->writeState(12), ParameterTableModel::WriteState::Verified);
        QCOMPARE(cell(panel, 12, ParameterTableModel::State), QStringLiteral("written, verified"));
        QCOMPARE(cell(panel, 12, ParameterTableModel::Mark), QString(QChar(0x25C7))); // not saved to EEPROM
        QVERIFY(panel.model()->isChanged(10));

        // Write all changed: PA10 reaches the drive and is read back.
        panel.writeAllChanged();
        QVERIFY(done.wait(10000));
        QVERIFY(done.last().at(0).toBool());
        QCOMPARE(fx.drive()->parameter(10), quint16(1234));
        QCOMPARE(cell(panel, 10, ParameterTableModel::DriveValue), QStringLiteral("1234"));
        QCOMPARE(panel.model()->writeState(10), ParameterTableModel::WriteState::Verified);
        QVERIFY(panel.model()->changedIndices().isEmpty());
        QVERIFY(!panel.findChild<QPushButton *>(QStringLiteral("writeChangedButton"))->isEnabled());
        QVERIFY2(panel.message().contains(QLatin1String("1 written and verified")), qPrintable(panel.message()));
        // The write is in this drive's verification journal, for the commissioning record.
        const VerificationJournal::Entry journal = data.read(&fx.hub, fx.connectionId, fx.address, fx.info.identity);
        QCOMPARE(journal.verification.kind, QStringLiteral("write"));
        QCOMPARE(journal.verification.entries.size(), 1);
        QCOMPARE(journal.verification.entries.first().key, QStringLiteral("PA10"));
        QCOMPARE(journal.verification.entries.first().requested, qint64(1234));
    }

    // Issue #10: the table's context menu — copy, reset to default where the dictionary knows
    // one (a pending, undoable edit), write this row.
    void contextMenuCopiesResetsAndWritesARow()
    {
        SimDriveFixture fx;
        QVERIFY(fx.start([](SimServoModbusDrive *d) { d->setParameter(10, 10); }));
        ParametersPanel panel(fx.context());
        panel.setDriveInfo(fx.info);
        // The bundled servo-modbus dictionary gives no defaults: one that does.
        auto dictionary = std::make_shared<ParameterDictionary>();
        const Error loadError = dictionary->loadFromJson(R"({"format": "drivedesk-dictionary", "formatVersion": 1,
            "family": "servo-modbus", "valueType": "int16", "parameters": [
            {"index": 10, "key": "PA10", "name": {"en": "Speed gain", "zh": "速度增益"}, "description": {"en": "-", "zh": "-"}, "unit": "Hz",
             "min": 0, "max": 3000, "default": 40, "access": "rw", "register": 110},
            {"index": 11, "key": "PA11", "name": {"en": "Eleven", "zh": "十一"}, "description": {"en": "-", "zh": "-"}, "unit": "",
             "min": -100, "max": 100, "access": "rw", "register": 111}]})",
                                                         QStringLiteral("test"));
        QVERIFY2(!loadError, qPrintable(loadError.message));
        panel.model()->setDictionary(dictionary);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QVERIFY(readAll(panel));

        std::unique_ptr<ParameterContextMenu> menu(panel.contextMenuFor(10));
        QVERIFY(!menu->writeAction()->isEnabled()); // nothing edited
        menu->copyAction()->trigger();
        QCOMPARE(QApplication::clipboard()->text(), QStringLiteral("PA10\tSpeed gain\t10\tHz"));
        QVERIFY(menu->resetAction()->isEnabled());
        QVERIFY(menu->resetAction()->text().contains(QLatin1String("40")));
        menu->resetAction()->trigger();
        QCOMPARE(panel.model()->editedValue(10), std::optional<qint64>(40));
        QCOMPARE(fx.drive()->parameter(10), quint16(10)); // a pending edit, nothing sent
        QCOMPARE(panel.undoStack()->count(), 1);

        menu.reset(panel.contextMenuFor(11));
        QVERIFY(!menu->resetAction()->isEnabled()); // the dictionary gives no default
        menu.reset(panel.contextMenuFor(10));
        QVERIFY(menu->writeAction()->isEnabled());
        QSignalSpy done(&panel, &ParametersPanel::operationFinished);
        menu->writeAction()->trigger();
        QVERIFY(done.wait(10000));
        QVERIFY(done.last().at(0).toBool());
        QCOMPARE(fx.drive()->parameter(10), quint16(40));
        QCOMPARE(panel.model()->writeState(10), ParameterTableModel::WriteState::Verified);
    }

    // Issue #10: generic names say where the drive's own dictionary goes; loading one is
    // validated whole (a bad file changes nothing and says why) and relabels the table.
    void loadsTheDrivesDictionary()
    {
        QTemporaryDir dir;
        SimDriveFixture fx;
        QVERIFY(fx.start());
        ParametersPanel panel(fx.context());
        panel.setDriveInfo(fx.info);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        auto *hint = panel.findChild<QLabel *>(QStringLiteral("genericNamesHint"));
        QVERIFY(panel.namesAreGeneric());
        QVERIFY(hint->isVisible());
        QVERIFY(hint->text().contains(QLatin1String("Load dictionary")));
        const QString before = cell(panel, 10, ParameterTableModel::Name);
        QSignalSpy used(&panel, &DrivePanel::fileUsed);

        const auto write = [&](const QString &name, const QByteArray &json) {
            const QString path = dir.filePath(name);
            QFile f(path);
            return f.open(QIODevice::WriteOnly) && f.write(json) == json.size() ? path : QString();
        };
        const QByteArray good = R"({"format": "drivedesk-dictionary", "formatVersion": 1,
            "family": "servo-modbus", "valueType": "int16", "parameters": [
            {"index": 10, "key": "PA10", "name": {"en": "Speed gain", "zh": "速度增益"},
             "description": {"en": "-", "zh": "-"}, "unit": "Hz", "min": 0, "max": 3000, "access": "rw",
             "register": 110}]})";
        QByteArray broken = good;
        broken.replace("\"max\": 3000", "\"max\": \"lots\"");
        QByteArray otherFamily = good;
        otherFamily.replace("\"servo-modbus\"", "\"servo-can\"");
        for (const QString &bad : {write(QStringLiteral("broken.json"), broken),
                                   write(QStringLiteral("can.json"), otherFamily), dir.filePath("missing.json")}) {
            QVERIFY(panel.loadDictionary(bad).isError());
            QVERIFY2(panel.message().startsWith(QLatin1String("Dictionary not loaded:")), qPrintable(panel.message()));
            QCOMPARE(cell(panel, 10, ParameterTableModel::Name), before);
        }
        QCOMPARE(used.count(), 0);

        const QString path = write(QStringLiteral("mine.json"), good);
        QVERIFY(!panel.loadDictionary(path).isError());
        QCOMPARE(cell(panel, 10, ParameterTableModel::Name), QStringLiteral("Speed gain"));
        QCOMPARE(panel.model()->rowCount(), 1);
        QVERIFY(!panel.namesAreGeneric());
        QVERIFY(!hint->isVisible());
        QCOMPARE(used.count(), 1);
        // The drive validates with it too: a value above its maximum is refused there.
        auto max = std::make_shared<qint64>(0);
        bool asked = false;
        fx.hub.run(
            fx.connectionId, fx.address,
            [max](Drive &d) {
                const ParameterInfo *p = d.parameterDictionary().byIndex(10);
                *max = p ? p->max : 0;
                auto *reply = new DriveReply(&d);
                reply->finish();
                return reply;
            },
            [&asked](const DriveResult &) { asked = true; });
        QVERIFY(QTest::qWaitFor([&] { return asked; }, 5000));
        QCOMPARE(*max, qint64(3000));
    }

    void readQueuedBehindAScanIsNotCancelled()
    {
        // The tab may be shown (and read) while the connect dialog's scan still probes the
        // other addresses: the end of the scan must not cancel the read.
        SimDriveFixture fx;
        QVERIFY(fx.start());
        ParametersPanel panel(fx.context());
        panel.setDriveInfo(fx.info);
        bool scanned = false;
        ScanOptions scan;
        scan.from = 1;
        scan.to = 6;
        scan.timeoutMs = 30;
        fx.hub.scan(fx.connectionId, scan, {}, {}, [&](const Error &) { scanned = true; });
        QVERIFY(QTest::qWaitFor([&] { return fx.sentFrames().size() >= 2; }, 2000));
        QSignalSpy done(&panel, &ParametersPanel::operationFinished);
        panel.readAll();
        QVERIFY(done.wait(10000));
        QVERIFY2(done.last().at(0).toBool(), qPrintable(panel.message()));
        QVERIFY(QTest::qWaitFor([&] { return scanned; }, 5000));
    }

    void refusedValuesSendNothing()
    {
        SimDriveFixture fx;
        QVERIFY(fx.start());
        const quint16 address = fx.drive()->parameter(51);
        ParametersPanel panel(fx.context());
        panel.setDriveInfo(fx.info);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QVERIFY(readAll(panel));
        fx.traffic.clear();

        // Out of range: Enter does not commit, the editor stays open and the reason shows.
        QLineEdit *editor = typeValue(panel, 51, QStringLiteral("300"));
        QVERIFY(editor);
        QVERIFY(editor->isVisible());
        QVERIFY2(panel.message().contains(QLatin1String("outside the allowed range 0 to 255. Nothing was sent")),
                 qPrintable(panel.message())); // the reason ends with a full stop
        QVERIFY(panel.message().contains(QLatin1String("Nothing was sent")));
        QVERIFY(editor->toolTip().contains(QLatin1String("0 to 255")));
        QTest::keyClick(editor, Qt::Key_Escape);
        QVERIFY(QTest::qWaitFor(
            [&] { return !panel.view()->findChild<QLineEdit *>(QStringLiteral("parameterValueEditor")); }, 2000));
        QVERIFY(!panel.model()->editedValue(51));
        QCOMPARE(cell(panel, 51, ParameterTableModel::Value), QString::number(address));

        // Malformed.
        editor = typeValue(panel, 51, QStringLiteral("12abc"));
        QVERIFY(editor);
        QVERIFY2(panel.message().contains(QLatin1String("not a whole number")), qPrintable(panel.message()));
        QTest::keyClick(editor, Qt::Key_Escape);
        QVERIFY(!panel.model()->editedValue(51));

        // Straight into the model (a paste, a script): refused with the reason too.
        QSignalSpy refused(panel.model(), &ParameterTableModel::editRefused);
        QVERIFY(!panel.proxy()->setData(valueIndex(panel, 10), QStringLiteral("-40000")));
        QCOMPARE(refused.count(), 1);
        QCOMPARE(refused.first().at(1).value<Error>().code, ErrorCode::OutOfRange);
        QVERIFY(!panel.model()->editedValue(10));
        // Hexadecimal is accepted, within range.
        QVERIFY(panel.proxy()->setData(valueIndex(panel, 51), QStringLiteral("0x20")));
        QCOMPARE(*panel.model()->editedValue(51), qint64(32));
        panel.undoStack()->undo();

        // Nothing to write, nothing sent: a read afterwards is the only traffic, and no
        // write request (0x06 / 0x10) ever left.
        panel.writeAllChanged();
        QVERIFY(panel.message().contains(QLatin1String("Nothing to write")));
        QVERIFY(fx.sentFrames().isEmpty());
        QVERIFY(readAll(panel));
        QVERIFY(!fx.sentFrames().isEmpty());
        QCOMPARE(fx.sentWithFunction(0x10), 0);
        QCOMPARE(fx.sentWithFunction(0x06), 0);
        QCOMPARE(fx.drive()->parameter(51), address);
    }

    void undoRestoresTheOldCell()
    {
        SimDriveFixture fx;
        QVERIFY(fx.start([](SimServoModbusDrive *d) { d->setParameter(10, 10); }));
        ParametersPanel panel(fx.context());
        panel.setDriveInfo(fx.info);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QVERIFY(readAll(panel));
        auto *undo = panel.findChild<QPushButton *>(QStringLiteral("undoButton"));
        auto *redo = panel.findChild<QPushButton *>(QStringLiteral("redoButton"));
        QVERIFY(!undo->isEnabled());

        QVERIFY(typeValue(panel, 10, QStringLiteral("77")));
        QVERIFY(QTest::qWaitFor([&] { return panel.model()->editedValue(10).has_value(); }, 2000));
        QVERIFY(typeValue(panel, 10, QStringLiteral("78")));
        QVERIFY(QTest::qWaitFor([&] { return panel.model()->editedValue(10) == 78; }, 2000));
        QCOMPARE(panel.undoStack()->count(), 2);
        QVERIFY(undo->isEnabled());
        QVERIFY(undo->toolTip().contains(QLatin1String("PA10")));

        QTest::mouseClick(undo, Qt::LeftButton);
        QCOMPARE(cell(panel, 10, ParameterTableModel::Value), QStringLiteral("77"));
        QTest::mouseClick(undo, Qt::LeftButton);
        QCOMPARE(cell(panel, 10, ParameterTableModel::Value), QStringLiteral("10"));
        QCOMPARE(cell(panel, 10, ParameterTableModel::Mark), QString());
        QVERIFY(!panel.model()->isChanged(10));
        QVERIFY(!undo->isEnabled());
        QVERIFY(redo->isEnabled());
        QTest::mouseClick(redo, Qt::LeftButton);
        QCOMPARE(cell(panel, 10, ParameterTableModel::Value), QStringLiteral("77"));
        QVERIFY(panel.model()->isChanged(10));

        // Ctrl+Z in the table does the same.
        panel.view()->setFocus();
        QTest::keyClick(panel.view(), Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(cell(panel, 10, ParameterTableModel::Value), QStringLiteral("10"));
        // Typing the drive's own value is no edit at all.
        QVERIFY(panel.proxy()->setData(valueIndex(panel, 10), QStringLiteral("10")));
        QVERIFY(!panel.model()->isChanged(10));
    }

    void searchFilters()
    {
        ParametersPanel panel(DriveContext{}); // no drive needed: the bundled dictionary
        auto *search = panel.findChild<QLineEdit *>(QStringLiteral("parameterSearch"));
        QVERIFY(search);
        const int all = panel.model()->rowCount();
        QCOMPARE(all, ParameterDictionary::bundled(Family::ServoModbus).size());
        QCOMPARE(panel.proxy()->rowCount(), all);

        QTest::keyClicks(search, QStringLiteral("pa51"));
        QCOMPARE(panel.proxy()->rowCount(), 1);
        QCOMPARE(panel.proxy()->index(0, 0).data(ParameterTableModel::ParameterIndexRole).toInt(), 51);

        search->clear();
        QTest::keyClicks(search, QStringLiteral("address")); // by name
        QCOMPARE(panel.proxy()->rowCount(), 1);
        search->setText(ParameterDictionary::bundled(Family::ServoModbus).byIndex(51)->name.chinese());
        QCOMPARE(panel.proxy()->rowCount(), 1); // by the Chinese name too
        search->setText(QStringLiteral("59"));  // by index
        QCOMPARE(panel.proxy()->rowCount(), 1);
        QCOMPARE(panel.proxy()->index(0, 0).data(ParameterTableModel::ParameterIndexRole).toInt(), 59);
        search->setText(QStringLiteral("no such parameter"));
        QCOMPARE(panel.proxy()->rowCount(), 0);
        search->clear();
        QCOMPARE(panel.proxy()->rowCount(), all);
    }

    void writeOnlyShowsNotReadableAndLastWritten()
    {
        ParameterTableModel model;
        const auto shuoke = bundled(Family::Shuoke);
        const ParameterInfo *skip = shuoke->byKey(QStringLiteral("skip-crc-check"));
        QVERIFY(skip);
        QCOMPARE(skip->access, Access::WriteOnly);
        // Model-specific parameters appear only for their model.
        model.setDictionary(shuoke, QString());
        QCOMPARE(model.rowOf(skip->index), -1);
        model.setDictionary(shuoke, skip->models.value(0));
        const int row = model.rowOf(skip->index);
        QVERIFY(row >= 0);
        QVERIFY(!model.readableIndices().contains(skip->index));
        QCOMPARE(model.index(row, ParameterTableModel::DriveValue).data().toString(), QStringLiteral("not readable"));
        QCOMPARE(model.index(row, ParameterTableModel::Access).data().toString(), QStringLiteral("write-only"));

        QVERIFY(model.setData(model.index(row, ParameterTableModel::Value), QStringLiteral("0")));
        QVERIFY(model.isChanged(skip->index));
        ParameterWriteResult r;
        r.index = skip->index;
        r.requested = 0;
        r.written = true;
        r.readable = false;
        model.applyWriteResults({r}, {skip->index});
        QCOMPARE(model.index(row, ParameterTableModel::DriveValue).data().toString(),
                 QStringLiteral("not readable (last written: 0)"));
        QCOMPARE(model.index(row, ParameterTableModel::Value).data().toString(), QStringLiteral("0"));
        QCOMPARE(model.writeState(skip->index), ParameterTableModel::WriteState::WrittenOnly);
        QVERIFY(!model.isChanged(skip->index));
        // Writing the same value again is still a change: the drive cannot say what it has.
        QVERIFY(model.setData(model.index(row, ParameterTableModel::Value), QStringLiteral("0")));
        QVERIFY(model.isChanged(skip->index));

        // A failed write keeps the edit and says why; one that was never reached says so.
        const int start = shuoke->byKey(QStringLiteral("start-speed"))
            ? shuoke->byKey(QStringLiteral("start-speed"))->index
            : -1;
        QVERIFY(start >= 0);
        const int startRow = model.rowOf(start);
        QVERIFY(model.setData(model.index(startRow, ParameterTableModel::Value),
                              QString::number(shuoke->byIndex(start)->min)));
        ParameterWriteResult failed;
        failed.index = start;
        failed.error = QStringLiteral("timeout");
        model.applyWriteResults({failed}, {start, skip->index});
        QCOMPARE(model.writeState(start), ParameterTableModel::WriteState::Failed);
        QVERIFY(model.isChanged(start));
        QCOMPARE(model.index(startRow, ParameterTableModel::State).data().toString(),
                 QStringLiteral("failed: timeout"));
        QCOMPARE(model.writeState(skip->index), ParameterTableModel::WriteState::NotAttempted);
    }

    void writeOnlyOnAShuokeDrive()
    {
        SimDriveFixture fx;
        QVERIFY(fx.startShuoke());
        const QString model = fx.info.identity.model;
        const ParameterInfo *encoder = ParameterDictionary::bundled(Family::Shuoke)
                                           .byKey(QStringLiteral("encoder-direction"));
        QVERIFY(encoder);
        if (!encoder->models.contains(model))
            QSKIP("the simulated drive's model has no encoder-direction setting");
        ParametersPanel panel(fx.context());
        panel.setDriveInfo(fx.info);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QVERIFY(readAll(panel));
        QCOMPARE(cell(panel, encoder->index, ParameterTableModel::DriveValue), QStringLiteral("not readable"));
        QCOMPARE(cell(panel, encoder->index, ParameterTableModel::Value), QString());

        const qint64 before = fx.shuokeDrive()->setting(quint8(encoder->index));
        const QString wanted = before ? QStringLiteral("0") : QStringLiteral("1");
        QVERIFY(typeValue(panel, encoder->index, wanted));
        QVERIFY(QTest::qWaitFor([&] { return panel.model()->isChanged(encoder->index); }, 2000));
        QSignalSpy done(&panel, &ParametersPanel::operationFinished);
        panel.writeAllChanged();
        QVERIFY(done.wait(10000));
        QVERIFY2(done.last().at(0).toBool(), qPrintable(panel.message()));
        QCOMPARE(fx.shuokeDrive()->setting(quint8(encoder->index)), wanted.toLongLong());
        QCOMPARE(panel.model()->writeState(encoder->index), ParameterTableModel::WriteState::WrittenOnly);
        QCOMPARE(cell(panel, encoder->index, ParameterTableModel::DriveValue),
                 QStringLiteral("not readable (last written: %1)").arg(wanted));
        QCOMPARE(cell(panel, encoder->index, ParameterTableModel::Value), wanted);
        QVERIFY2(panel.message().contains(QLatin1String("write-only")), qPrintable(panel.message()));

        // Another panel on the same connection learns the last written value on Read all.
        ParametersPanel again(fx.context());
        again.setDriveInfo(fx.info);
        QVERIFY(readAll(again));
        QCOMPARE(cell(again, encoder->index, ParameterTableModel::DriveValue),
                 QStringLiteral("not readable (last written: %1)").arg(wanted));
    }

    void namesInTheUiLanguage()
    {
        ParameterTableModel model;
        model.setDictionary(bundled(Family::ServoModbus));
        const ParameterInfo *p = ParameterDictionary::bundled(Family::ServoModbus).byIndex(51);
        const QModelIndex name = model.index(model.rowOf(51), ParameterTableModel::Name);
        QCOMPARE(name.data().toString(), p->name.english());
        QLocale::setDefault(QLocale(QLocale::Chinese, QLocale::China));
        QCOMPARE(name.data().toString(), p->name.chinese());
        QCOMPARE(name.data(Qt::ToolTipRole).toString(), p->description.chinese());
        QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
        QCOMPARE(name.data().toString(), p->name.english());
    }

    void switchesToChineseLive()
    {
        ParametersPanel panel(DriveContext{});
        EePanel ee(DriveContext{});
        BackupPanel backup(DriveContext{});
        panel.show();
        ee.show();
        backup.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        auto *read = panel.findChild<QPushButton *>(QStringLiteral("readAllButton"));
        QCOMPARE(read->text(), QStringLiteral("Read all"));
        const QModelIndex name = panel.proxy()->index(panel.model()->rowOf(51), ParameterTableModel::Name);

        LanguageManager languages;
        QVERIFY(languages.apply(LanguageManager::Language::Chinese));
        QCoreApplication::sendPostedEvents(); // LanguageChange is posted to top-level widgets
        QCOMPARE(read->text(), QStringLiteral("全部读取"));
        QCOMPARE(panel.title(), QStringLiteral("参数"));
        QCOMPARE(panel.model()->headerData(ParameterTableModel::Name, Qt::Horizontal).toString(),
                 QStringLiteral("名称"));
        QCOMPARE(name.data().toString(), ParameterDictionary::bundled(Family::ServoModbus).byIndex(51)->name.chinese());
        QCOMPARE(backup.title(), QStringLiteral("备份"));
        QCOMPARE(backup.findChild<QPushButton *>(QStringLiteral("saveBackupButton"))->text(),
                 QStringLiteral("保存备份…"));
        QVERIFY(
            ee.findChild<QLabel *>(QStringLiteral("eeUnavailableReason"))->text().contains(QStringLiteral("驱动器")));

        QVERIFY(languages.apply(LanguageManager::Language::English));
        QCoreApplication::sendPostedEvents();
        QCOMPARE(read->text(), QStringLiteral("Read all"));
        QCOMPARE(name.data().toString(), QStringLiteral("Drive address"));
    }
};

QTEST_MAIN(TestParametersPanel)
#include "tst_parameterspanel.moc"
