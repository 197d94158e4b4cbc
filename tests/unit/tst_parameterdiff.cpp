#include <QtTest>

#include "core/params/parameterdictionary.h"
#include "core/params/parameterdiff.h"

using namespace dd;

Q_DECLARE_METATYPE(dd::DiffStatus)

namespace {

const ParameterDictionary &shuoke()
{
    return ParameterDictionary::bundled(Family::Shuoke);
}

// File and drive sets of a shuoke drive covering every status.
struct Sets
{
    ParameterSet file;
    ParameterSet drive;
};

Sets shuokeSets()
{
    Sets s;
    s.file.set(0x25, 500);
    s.drive.set(0x25, 500); // start-speed: Same
    s.file.set(0x27, 20000);
    s.drive.set(0x27, 15000); // max-speed: Different
    s.file.set(0x2B, 800);
    s.drive.setUnknown(0x2B);                      // acceleration: OnlyInFile (drive read failed)
    s.file.set(0x29, 100);                         // stop-speed: OnlyInFile (not read)
    s.drive.set(0x2D, 900);                        // deceleration: OnlyOnDrive
    s.file.set(0x5C, 1, ValueSource::LastWritten); // encoder-direction: NotReadable
    s.file.set(0x65, 200, ValueSource::LastWritten);
    s.drive.set(0x65, 200, ValueSource::LastWritten); // NotReadable even when equal
    s.drive.set(0x5D, 0, ValueSource::LastWritten);   // motion-direction: OnlyOnDrive
    s.file.set(0x24, 7);
    s.drive.set(0x24, 6);                           // baud-code: Different, communication
    s.file.set(0x4B, 12, ValueSource::LastWritten); // CAN bitrate: NotReadable, communication
    s.file.set(300, 1);                             // not in the dictionary: ignored
    return s;
}

QList<int> indicesOf(const QVector<DiffEntry> &entries)
{
    QList<int> out;
    for (const DiffEntry &e : entries)
        out.append(e.index);
    return out;
}

} // namespace

class TestParameterDiff : public QObject
{
    Q_OBJECT
private slots:
    void statuses_data()
    {
        QTest::addColumn<int>("index");
        QTest::addColumn<DiffStatus>("status");
        QTest::addColumn<qint64>("fileValue");  // -1: none
        QTest::addColumn<qint64>("driveValue"); // -1: none
        QTest::newRow("same") << 0x25 << DiffStatus::Same << qint64(500) << qint64(500);
        QTest::newRow("different") << 0x27 << DiffStatus::Different << qint64(20000) << qint64(15000);
        QTest::newRow("drive unknown") << 0x2B << DiffStatus::OnlyInFile << qint64(800) << qint64(-1);
        QTest::newRow("drive absent") << 0x29 << DiffStatus::OnlyInFile << qint64(100) << qint64(-1);
        QTest::newRow("only on drive") << 0x2D << DiffStatus::OnlyOnDrive << qint64(-1) << qint64(900);
        QTest::newRow("write-only") << 0x5C << DiffStatus::NotReadable << qint64(1) << qint64(-1);
        QTest::newRow("write-only both") << 0x65 << DiffStatus::NotReadable << qint64(200) << qint64(200);
        QTest::newRow("write-only drive") << 0x5D << DiffStatus::OnlyOnDrive << qint64(-1) << qint64(0);
        QTest::newRow("communication") << 0x24 << DiffStatus::Different << qint64(7) << qint64(6);
    }
    void statuses()
    {
        QFETCH(int, index);
        QFETCH(DiffStatus, status);
        QFETCH(qint64, fileValue);
        QFETCH(qint64, driveValue);
        const Sets s = shuokeSets();
        const ParameterDiff diff = ParameterDiff::compute(shuoke(), s.file, s.drive);
        const DiffEntry *e = diff.entry(index);
        QVERIFY(e);
        QCOMPARE(diffStatusId(e->status), diffStatusId(status));
        QCOMPARE(e->fileValue.value_or(-1), fileValue);
        QCOMPARE(e->driveValue.value_or(-1), driveValue);
        QCOMPARE(e->key, shuoke().byIndex(index)->key);
        QCOMPARE(e->access, shuoke().byIndex(index)->access);
    }

    void entriesAndCounts()
    {
        const Sets s = shuokeSets();
        const ParameterDiff diff = ParameterDiff::compute(shuoke(), s.file, s.drive);
        QCOMPARE(indicesOf(diff.entries()), (QList<int>{0x24, 0x25, 0x27, 0x29, 0x2B, 0x2D, 0x4B, 0x5C, 0x5D, 0x65}));
        QVERIFY(!diff.entry(300));  // not in the dictionary
        QVERIFY(!diff.entry(0x2F)); // known on neither side
        QCOMPARE(diff.count(DiffStatus::Same), 1);
        QCOMPARE(diff.count(DiffStatus::Different), 2);
        QCOMPARE(diff.count(DiffStatus::OnlyInFile), 2);
        QCOMPARE(diff.count(DiffStatus::OnlyOnDrive), 2);
        QCOMPARE(diff.count(DiffStatus::NotReadable), 3);
        QVERIFY(diff.hasDifferences());
        QVERIFY(diff.entry(0x24)->communication);
        QVERIFY(!diff.entry(0x25)->communication);
    }

    void statusIds()
    {
        QCOMPARE(diffStatusId(DiffStatus::Same), QStringLiteral("same"));
        QCOMPARE(diffStatusId(DiffStatus::Different), QStringLiteral("different"));
        QCOMPARE(diffStatusId(DiffStatus::OnlyInFile), QStringLiteral("only-in-file"));
        QCOMPARE(diffStatusId(DiffStatus::OnlyOnDrive), QStringLiteral("only-on-drive"));
        QCOMPARE(diffStatusId(DiffStatus::NotReadable), QStringLiteral("not-readable"));
    }

    void selectAll()
    {
        const Sets s = shuokeSets();
        const ParameterDiff diff = ParameterDiff::compute(shuoke(), s.file, s.drive);
        QVector<DiffEntry> out;
        QVERIFY(!diff.selectForWrite({}, &out));
        // Different, OnlyInFile and write-only values; not Same, OnlyOnDrive, nor the
        // communication settings baud-code (0x24) and CAN bitrate (0x4B).
        QCOMPARE(indicesOf(out), (QList<int>{0x27, 0x29, 0x2B, 0x5C, 0x65}));
        QCOMPARE(out.at(0).fileValue, std::optional<qint64>(20000));
    }

    void selectOnly_data()
    {
        QTest::addColumn<QList<int>>("only");
        QTest::addColumn<QList<int>>("expected");
        QTest::newRow("one difference") << QList<int>{0x27} << QList<int>{0x27};
        QTest::newRow("same is not written") << QList<int>{0x25, 0x27} << QList<int>{0x27};
        QTest::newRow("communication when named") << QList<int>{0x24} << QList<int>{0x24};
        QTest::newRow("write-only communication when named") << QList<int>{0x4B, 0x5C} << QList<int>{0x4B, 0x5C};
        QTest::newRow("order follows index") << QList<int>{0x65, 0x29} << QList<int>{0x29, 0x65};
        QTest::newRow("only same") << QList<int>{0x25} << QList<int>{};
    }
    void selectOnly()
    {
        QFETCH(QList<int>, only);
        QFETCH(QList<int>, expected);
        const Sets s = shuokeSets();
        const ParameterDiff diff = ParameterDiff::compute(shuoke(), s.file, s.drive);
        QVector<DiffEntry> out;
        const Error e = diff.selectForWrite(only, &out);
        QVERIFY2(!e, qPrintable(e.message));
        QCOMPARE(indicesOf(out), expected);
    }

    void selectOnlyErrors()
    {
        const Sets s = shuokeSets();
        const ParameterDiff diff = ParameterDiff::compute(shuoke(), s.file, s.drive);
        QVector<DiffEntry> out{DiffEntry{}};
        Error e = diff.selectForWrite({0x27, 0x2D}, &out); // deceleration: only on the drive
        QCOMPARE(e.code, ErrorCode::InvalidArgument);
        QVERIFY2(e.message.contains("deceleration"), qPrintable(e.message));
        QCOMPARE(out.size(), 1);               // untouched
        e = diff.selectForWrite({0x2F}, &out); // homing-speed: on neither side
        QCOMPARE(e.code, ErrorCode::InvalidArgument);
        QVERIFY(e.message.contains("47"));
    }

    void readOnlyIsNeverWritten()
    {
        const ParameterDictionary &modbus = ParameterDictionary::bundled(Family::ServoModbus);
        ParameterSet file, drive;
        file.set(2, 7051);
        drive.set(2, 7062); // firmware differs: shown, never written
        file.set(51, 5);
        drive.set(51, 1); // address: communication
        file.set(10, 3);
        drive.set(10, 4);
        const ParameterDiff diff = ParameterDiff::compute(modbus, file, drive);
        QCOMPARE(diff.entry(2)->status, DiffStatus::Different);
        QVector<DiffEntry> out;
        QVERIFY(!diff.selectForWrite({}, &out));
        QCOMPARE(indicesOf(out), QList<int>{10});
        const Error e = diff.selectForWrite({2}, &out);
        QCOMPARE(e.code, ErrorCode::NotSupported);
        QVERIFY(e.message.contains("PA2") && e.message.contains("read-only"));
        QVERIFY(!diff.selectForWrite({51}, &out));
        QCOMPARE(indicesOf(out), QList<int>{51});
    }

    void identicalSetsHaveNoDifferences()
    {
        ParameterSet set;
        set.set(0x25, 10);
        set.set(0x27, 20);
        set.set(0x24, 6);
        const ParameterDiff diff = ParameterDiff::compute(shuoke(), set, set);
        QVERIFY(!diff.hasDifferences());
        QCOMPARE(diff.count(DiffStatus::Same), 3);
        QVector<DiffEntry> out;
        QVERIFY(!diff.selectForWrite({}, &out));
        QVERIFY(out.isEmpty());

        // Only a communication setting differs: a default restore writes nothing.
        ParameterSet other = set;
        other.set(0x24, 7);
        QVERIFY(!ParameterDiff::compute(shuoke(), other, set).hasDifferences());
    }

    void emptySets()
    {
        const ParameterDiff diff = ParameterDiff::compute(shuoke(), ParameterSet(), ParameterSet());
        QVERIFY(diff.entries().isEmpty());
        QVERIFY(!diff.hasDifferences());
    }
};

QTEST_GUILESS_MAIN(TestParameterDiff)
#include "tst_parameterdiff.moc"
