// Multi-drive apply (offscreen) on simulated servo-modbus drives 1-4 (SimBench on the test's
// thread, a DriveHub): "Copy parameters from drive 1" plans first (per drive the parameters
// that will change, nothing written), writes only the differences and reads them back,
// leaves the address alone, reports per drive; an enabled drive needs the confirmation;
// stop at the first failure leaves the later drives not attempted.
#include "core/drive/drivehub.h"
#include "sim/bench/simbench.h"
#include "sim/bus/simserialbus.h"
#include "sim/servomodbus/simservomodbusdrive.h"
#include "tests/gui/journaldatahome.h"
#include "ui/bus/bustreewidget.h"
#include "ui/bus/drivedirectory.h"
#include "ui/fleet/fleetapplydialog.h"

#include <QCheckBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QTreeWidget>
#include <QtTest>

using namespace dd;

class TestFleetApply : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void copyPlansThenWritesOnlyDifferences();
    void enabledDriveNeedsConfirmation();
    void stopAtFirstFailure();
    void busTreeOffersTheEntries();

private:
    SimServoModbusDrive *sim(int address) const
    {
        return static_cast<SimServoModbusDrive *>(m_bench.serialBus()->device(address - 1));
    }
    bool waitPlan(FleetApplyDialog &d)
    {
        return d.isPlanned() || QSignalSpy(&d, &FleetApplyDialog::planReady).wait(10000);
    }

    SimBench m_bench;
    DriveHub m_hub;
    DriveDirectory *m_directory = nullptr;
    int m_id = 0;
};

void TestFleetApply::initTestCase()
{
    SimBenchOptions o;
    o.family = Family::ServoModbus;
    o.baud = 115200;
    o.addresses = {1, 2, 3, 4};
    if (Error e = m_bench.start(o))
        QSKIP(qPrintable(e.message));
    bool opened = false;
    m_hub.openConnection(m_bench.clientSettings(), [&](int id, const Error &) {
        m_id = id;
        opened = true;
    });
    QVERIFY(QTest::qWaitFor([&] { return opened; }, 5000));
    m_directory = new DriveDirectory(&m_hub, this);
    m_directory->addConnection(m_id, m_bench.clientSettings());
    for (int a = 1; a <= 4; ++a) {
        DiscoveredDrive d;
        d.family = Family::ServoModbus;
        d.address = a;
        m_directory->addDrive(m_id, d);
    }
}

void TestFleetApply::copyPlansThenWritesOnlyDifferences()
{
    test::JournalDataHome data;
    sim(1)->setParameter(12, 1212);
    sim(1)->setParameter(13, 1313);
    sim(3)->setParameter(13, 1313); // already has one of them
    const quint16 writes2 = sim(2)->parameter(14);
    FleetApplyDialog d(m_directory, m_id, {1, 2, 3});
    d.show();
    d.setSourceDrive(1);
    QVERIFY(waitPlan(d));
    QCOMPARE(d.planned(2), (QList<int>{12, 13}));
    QCOMPARE(d.planned(3), (QList<int>{12}));
    QCOMPARE(d.tree()->topLevelItemCount(), 2); // the source is not a target
    // Nothing written by the plan.
    QVERIFY(sim(2)->parameter(12) != 1212);
    // The plan says the address is left alone.
    bool leftAlone = false;
    QTreeWidgetItem *two = d.tree()->topLevelItem(0);
    for (int i = 0; i < two->childCount(); ++i)
        leftAlone = leftAlone || (two->child(i)->text(0).startsWith(QLatin1String("PA51")));
    QVERIFY(leftAlone);

    QVERIFY(d.applyButton()->isEnabled());
    QSignalSpy applied(&d, &FleetApplyDialog::applied);
    d.applyButton()->click();
    QVERIFY(applied.count() == 1 || applied.wait(10000));
    QCOMPARE(d.state(2), FleetApplyDialog::DriveState::Verified);
    QCOMPARE(d.state(3), FleetApplyDialog::DriveState::Verified);
    QCOMPARE(d.report(2).written(), (QList<int>{12, 13}));
    QCOMPARE(sim(2)->parameter(12), quint16(1212));
    QCOMPARE(sim(3)->parameter(12), quint16(1212));
    QCOMPARE(sim(2)->parameter(51), quint16(2));
    QCOMPARE(sim(3)->parameter(51), quint16(3));
    QCOMPARE(sim(2)->parameter(14), writes2);
    QVERIFY(d.message().contains(QLatin1String("2 verified")));
    // Each target's verification journal holds its own restore (issue 27: none was noted).
    for (int a : {2, 3}) {
        const VerificationJournal::Entry journal = data.read(&m_hub, m_id, a, m_directory->info(m_id, a).identity);
        QCOMPARE(journal.verification.kind, QStringLiteral("restore"));
        QStringList keys;
        for (const RecordVerification::Entry &e : journal.verification.entries)
            keys << e.key;
        QCOMPARE(keys,
                 a == 2 ? QStringList({QStringLiteral("PA12"), QStringLiteral("PA13")})
                        : QStringList({QStringLiteral("PA12")}));
        QVERIFY(journal.verification.passed());
        QVERIFY(journal.verification.sourceFile.isEmpty()); // from drive 1, no file
        QVERIFY(journal.backups.isEmpty());
    }
}

void TestFleetApply::enabledDriveNeedsConfirmation()
{
    sim(1)->setParameter(15, 1515);
    DriveStatus s;
    s.online = true;
    s.enabled = true;
    m_directory->updateStatus(m_id, 4, s);
    FleetApplyDialog d(m_directory, m_id, {1, 4});
    d.show();
    d.setSourceDrive(1);
    QVERIFY(waitPlan(d));
    QCOMPARE(d.energisedTargets(), QList<int>{4});
    QVERIFY(d.confirmBox()->isVisible());
    QVERIFY(d.confirmBox()->text().contains(QLatin1String("energised")));
    QVERIFY(!d.applyButton()->isEnabled());
    d.apply(); // refused without the confirmation
    QVERIFY(sim(4)->parameter(15) != 1515);
    d.confirmBox()->setChecked(true);
    QVERIFY(d.applyButton()->isEnabled());
    QSignalSpy applied(&d, &FleetApplyDialog::applied);
    d.applyButton()->click();
    QVERIFY(applied.count() == 1 || applied.wait(10000));
    QCOMPARE(sim(4)->parameter(15), quint16(1515));
    s.enabled = false;
    m_directory->updateStatus(m_id, 4, s);
}

void TestFleetApply::stopAtFirstFailure()
{
    sim(1)->setParameter(16, 1616);
    sim(2)->faults().setSilent(true); // drive 2 will not answer the writes
    FleetApplyDialog d(m_directory, m_id, {2, 3, 4});
    d.show();
    // Drive 2 answers the plan, then goes silent.
    BackupFile file;
    file.setFamily(Family::ServoModbus);
    file.setFirmware(QStringLiteral("7051"));
    ParameterSet v;
    v.set(16, 1616);
    file.setValues(v);
    sim(2)->faults().setSilent(false);
    d.setSourceFile(file, QStringLiteral("axis.json"));
    QVERIFY(waitPlan(d));
    QVERIFY(d.stopAtFirstFailureBox()->isChecked());
    sim(2)->faults().setSilent(true);
    QSignalSpy applied(&d, &FleetApplyDialog::applied);
    d.applyButton()->click();
    QVERIFY(applied.count() == 1 || applied.wait(20000));
    sim(2)->faults().setSilent(false);
    QCOMPARE(d.state(2), FleetApplyDialog::DriveState::Failed);
    QCOMPARE(d.state(3), FleetApplyDialog::DriveState::NotAttempted);
    QCOMPARE(d.state(4), FleetApplyDialog::DriveState::NotAttempted);
    QVERIFY(sim(3)->parameter(16) != 1616);
    QVERIFY(d.tree()->topLevelItem(0)->text(1).contains(QLatin1String("FAILED")));
}

void TestFleetApply::busTreeOffersTheEntries()
{
    BusTreeWidget tree(m_directory);
    tree.show();
    QVERIFY(tree.driveItem(m_id, 2));
    tree.driveItem(m_id, 2)->setSelected(true);
    tree.driveItem(m_id, 3)->setSelected(true);
    QCOMPARE(tree.selectedDrives(m_id), (QList<int>{2, 3}));
}

QTEST_MAIN(TestFleetApply)
#include "tst_fleetapply.moc"
