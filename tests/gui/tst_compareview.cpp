// The Compare view (offscreen): live drives, backup files and the defaults side by side on
// a simulated bench of servo-modbus drives 1-3 (SimBench on the test's thread, a DriveHub on
// it): one row per parameter, differences highlighted, "Only differences", search, CSV
// export, another family refused with the reason, a differing firmware said.
#include "core/drive/drivehub.h"
#include "core/params/backupfile.h"
#include "sim/bench/simbench.h"
#include "sim/bus/simserialbus.h"
#include "sim/servomodbus/simservomodbusdrive.h"
#include "ui/bus/drivedirectory.h"
#include "ui/compare/compareview.h"

#include <QCheckBox>
#include <QLineEdit>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

using namespace dd;

class TestCompareView : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void drivesSideBySide();
    void filterSearchAndExport();
    void filesDefaultsAndRefusals();

private:
    SimServoModbusDrive *sim(int address) const
    {
        return static_cast<SimServoModbusDrive *>(m_bench.serialBus()->device(address - 1));
    }
    int visibleRows(const QTableWidget *t) const
    {
        int n = 0;
        for (int r = 0; r < t->rowCount(); ++r)
            n += t->isRowHidden(r) ? 0 : 1;
        return n;
    }
    void addDrives(CompareView &view, const QList<int> &addresses);

    QTemporaryDir m_dir;
    SimBench m_bench;
    DriveHub m_hub;
    DriveDirectory *m_directory = nullptr;
    int m_id = 0;
};

void TestCompareView::initTestCase()
{
    SimBenchOptions o;
    o.family = Family::ServoModbus;
    o.baud = 115200;
    o.addresses = {1, 2, 3};
    if (Error e = m_bench.start(o))
        QSKIP(qPrintable(e.message));
    bool opened = false;
    m_hub.openConnection(m_bench.clientSettings(), [&](int id, const Error &) {
        m_id = id;
        opened = true;
    });
    QVERIFY(QTest::qWaitFor([&] { return opened; }, 5000));
    QVERIFY(m_id > 0);
    m_directory = new DriveDirectory(&m_hub, this);
    m_directory->addConnection(m_id, m_bench.clientSettings());
}

void TestCompareView::addDrives(CompareView &view, const QList<int> &addresses)
{
    QSignalSpy spy(&view, &CompareView::sourcesChanged);
    for (int a : addresses)
        view.addDrive(m_id, a);
    QVERIFY(QTest::qWaitFor([&] { return spy.count() == addresses.size(); }, 10000));
}

void TestCompareView::drivesSideBySide()
{
    sim(2)->setParameter(20, 2020);
    CompareView view(m_directory);
    view.show();
    addDrives(view, {1, 2});
    QTableWidget *t = view.table();
    QCOMPARE(t->columnCount(), 3); // parameter + 2 drives
    QCOMPARE(t->rowCount(), 60);
    QCOMPARE(view.differenceCount(), 2); // PA20 and the address PA51
    // The PA20 row: both values, highlighted.
    int row = -1;
    for (int r = 0; r < t->rowCount(); ++r)
        if (t->item(r, 0)->text().startsWith(QLatin1String("PA20")))
            row = r;
    QVERIFY(row >= 0);
    QCOMPARE(t->item(row, 2)->text(), QStringLiteral("2020"));
    QVERIFY(t->item(row, 1)->text() != QLatin1String("2020"));
    QVERIFY(t->item(row, 1)->font().bold());
    QVERIFY(t->item(row, 1)->background().color().isValid());
    QVERIFY(!t->item(0, 1)->font().bold());
    // The firmware is in the header.
    QVERIFY(t->horizontalHeaderItem(1)->text().contains(QLatin1String("7051")));
    QVERIFY(view.message().contains(QLatin1String("2 parameter")));
    sim(2)->setParameter(20, sim(1)->parameter(20));
}

void TestCompareView::filterSearchAndExport()
{
    sim(3)->setParameter(33, 3333);
    CompareView view(m_directory);
    addDrives(view, {1, 3});
    QTableWidget *t = view.table();
    QCOMPARE(visibleRows(t), 60);
    view.findChild<QCheckBox *>(QStringLiteral("onlyDifferences"))->setChecked(true);
    QCOMPARE(visibleRows(t), 2);
    view.findChild<QLineEdit *>(QStringLiteral("search"))->setText(QStringLiteral("PA33"));
    QCOMPARE(visibleRows(t), 1);
    view.setOnlyDifferences(false);
    view.setSearchText(QStringLiteral("address"));
    QCOMPARE(visibleRows(t), 1); // PA51 Drive address

    const QString csv = m_dir.filePath(QStringLiteral("compare.csv"));
    QVERIFY(!view.exportCsv(csv));
    QFile f(csv);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = f.readAll().trimmed().split('\n');
    QCOMPARE(lines.size(), 61);
    QCOMPARE(lines.at(0), QByteArray("key,name,drive:1,drive:3,differs"));
    bool found = false;
    for (const QByteArray &l : lines)
        if (l.startsWith("PA33,")) {
            found = true;
            QVERIFY(l.endsWith(",3333,yes"));
        }
    QVERIFY(found);
    sim(3)->setParameter(33, sim(1)->parameter(33));
}

void TestCompareView::filesDefaultsAndRefusals()
{
    // A file of drive 1 with another firmware, and drive 1 itself.
    BackupFile file;
    file.setFamily(Family::ServoModbus);
    file.setFirmware(QStringLiteral("7052"));
    ParameterSet v;
    for (int i = 0; i < 60; ++i)
        v.set(i, sim(1)->parameter(i));
    v.set(40, 4000);
    file.setValues(v);
    const QString path = m_dir.filePath(QStringLiteral("axis.json"));
    QVERIFY(!file.save(path));
    CompareView view(m_directory);
    QVERIFY(!view.addFile(path));
    addDrives(view, {1});
    QCOMPARE(view.differenceCount(), 1);
    QVERIFY(view.message().contains(QLatin1String("firmware differs")));

    // Another family: refused, the reason shown, nothing added.
    BackupFile can;
    can.setFamily(Family::ServoCan);
    ParameterSet cv;
    cv.set(10, 1);
    can.setValues(cv);
    const QString canPath = m_dir.filePath(QStringLiteral("can.json"));
    QVERIFY(!can.save(canPath));
    const Error e = view.addFile(canPath);
    QVERIFY(e.isError());
    QVERIFY(view.message().contains(QLatin1String("servo-can")));
    QCOMPARE(view.sources().size(), 2);

    // The servo-modbus dictionary has no defaults: said so, nothing added.
    QVERIFY(view.addDefaults(Family::ServoModbus).isError());
    QCOMPARE(view.sources().size(), 2);
    // shuoke's has: a view of shuoke sources takes them.
    CompareView shuoke(m_directory);
    QVERIFY(!shuoke.addDefaults(Family::Shuoke));
    QVERIFY(shuoke.table()->rowCount() >= 4);
}

QTEST_MAIN(TestCompareView)
#include "tst_compareview.moc"
