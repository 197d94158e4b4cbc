// ParameterTransfer (backup / compare / restore workflow) against an in-memory drive.
#include "core/common/coreresources.h"
#include "core/drive/drive.h"
#include "core/drive/parametertransfer.h"
#include "core/params/backupfile.h"
#include "core/params/parameterdictionary.h"

#include <QSignalSpy>
#include <QTimer>
#include <QtTest>

using namespace dd;

namespace {

// A servo-modbus-like drive whose parameters live in a map. Replies finish from the event
// loop. `stuck` parameters ignore writes (read back the old value); `refuse` parameters
// fail the write with a drive exception and end the batch there, as a real link would.
class FakeDrive : public Drive
{
public:
    explicit FakeDrive(Family family = Family::ServoModbus, QObject *parent = nullptr)
        : Drive(parent)
        , m_family(family)
    {
        DriveIdentity id;
        id.family = family;
        id.address = 1;
        id.firmware = QStringLiteral("7051");
        id.link = QStringLiteral("fake");
        setIdentity(id);
        for (const ParameterInfo &p : ParameterDictionary::bundled(family).parameters())
            if (p.isReadable())
                values.insert(p.index, p.defaultValue.value_or(p.min > 0 ? p.min : 0));
    }

    Family family() const override { return m_family; }
    Capabilities capabilities() const override { return Capability::ReadParameters | Capability::WriteParameters; }
    QList<ChannelInfo> channels() const override { return {}; }

    DriveReply *refreshIdentity() override
    {
        DriveIdentity id = identity();
        id.firmware = firmware;
        setIdentity(id);
        return later({});
    }
    DriveReply *readParameters(const QList<int> &indices) override
    {
        ++reads;
        DriveReply *r = newReply();
        for (int i : indices)
            if (values.contains(i))
                r->setParameter(i, values.value(i));
        if (!lastWritten.isEmpty())
            r->setInfo(QStringLiteral("lastWritten"), lastWritten);
        QTimer::singleShot(0, r, [r] { r->finish(); });
        return r;
    }
    DriveReply *writeParameters(const QList<ParameterWrite> &writes) override
    {
        DriveReply *r = newReply();
        Error error;
        for (const ParameterWrite &w : writes) {
            ParameterWriteResult res;
            res.index = w.index;
            res.requested = w.value;
            if (refuse.contains(w.index)) {
                res.error = QStringLiteral("exception 4");
                r->addWriteResult(res);
                error = {ErrorCode::DriveException, QStringLiteral("exception 4"), 4};
                break;
            }
            ++writesDone;
            if (!stuck.contains(w.index))
                values[w.index] = w.value;
            res.written = true;
            res.readBack = values.value(w.index);
            res.verified = res.readBack == w.value;
            r->addWriteResult(res);
            if (!res.verified && !error)
                error = {ErrorCode::VerifyMismatch, QStringLiteral("mismatch")};
        }
        QTimer::singleShot(0, r, [r, error] { r->finish(error); });
        return r;
    }

    DriveReply *later(const Error &e)
    {
        DriveReply *r = newReply();
        QTimer::singleShot(0, r, [r, e] { r->finish(e); });
        return r;
    }

    Family m_family;
    QMap<int, qint64> values;
    QVariantMap lastWritten; // as a Shuoke drive reports its write-only settings
    QString firmware = QStringLiteral("7051");
    QList<int> stuck;
    QList<int> refuse;
    int reads = 0;
    int writesDone = 0;
};

Error runJob(ParameterTransfer &t, const std::function<void()> &start)
{
    QSignalSpy spy(&t, &ParameterTransfer::finished);
    start();
    if (!spy.wait(5000))
        return {ErrorCode::Timeout, QStringLiteral("the job never finished")};
    if (spy.count() != 1)
        return {ErrorCode::Malformed, QStringLiteral("finished() more than once")};
    return spy.at(0).at(0).value<Error>();
}

} // namespace

class TestParameterTransfer : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase()
    {
        ensureCoreResources();
        qRegisterMetaType<dd::Error>();
    }
    void backupReadsEveryReadableParameter();
    void compareShowsDifferences();
    void restoreWritesOnlyDifferencesAndVerifies();
    void restoreRefusesOtherFirmwareUnlessForced();
    void restoreReportsMismatch();
    void restoreReportsWhatWasNotWritten();
    void unansweredReadBackIsUnconfirmed();
    void dryRunWritesNothing();
    void onlyNarrowsTheSelection();
    void readableIndicesFollowModels();
    void backupKeepsLastWrittenWriteOnlyValues();
};

void TestParameterTransfer::backupReadsEveryReadableParameter()
{
    FakeDrive drive;
    drive.values[12] = 345;
    ParameterTransfer t(&drive);
    QVERIFY(!runJob(t, [&] { t.backup(); }));
    const BackupFile &f = t.backupFile();
    QCOMPARE(f.family(), std::optional<Family>(Family::ServoModbus));
    QCOMPARE(f.firmware(), QStringLiteral("7051"));
    QCOMPARE(f.address(), 1);
    const QList<int> readable = ParameterTransfer::readableIndices(t.dictionary(), QString());
    QCOMPARE(f.values().size(), readable.size());
    QCOMPARE(f.values().value(12), std::optional<qint64>(345));
    // The result saves and loads back unchanged.
    QByteArray json;
    QVERIFY(!f.toJson(t.dictionary(), &json));
    BackupFile again;
    QVERIFY(!again.loadFromJson(json, QStringLiteral("mem")));
    QCOMPARE(again.values(), f.values());
}

void TestParameterTransfer::compareShowsDifferences()
{
    FakeDrive drive;
    ParameterTransfer t(&drive);
    QVERIFY(!runJob(t, [&] { t.backup(); }));
    BackupFile file = t.backupFile();
    drive.values[12] += 7;
    drive.values[13] += 1;
    QVERIFY(!runJob(t, [&] { t.compare(file); }));
    QCOMPARE(t.diff().count(DiffStatus::Different), 2);
    QCOMPARE(t.diff().entry(12)->status, DiffStatus::Different);
    QCOMPARE(*t.diff().entry(12)->driveValue, *file.values().value(12) + 7);
    QCOMPARE(drive.writesDone, 0);
}

void TestParameterTransfer::restoreWritesOnlyDifferencesAndVerifies()
{
    FakeDrive drive;
    ParameterTransfer t(&drive);
    QVERIFY(!runJob(t, [&] { t.backup(); }));
    const BackupFile file = t.backupFile();
    const QMap<int, qint64> before = drive.values;
    drive.values[12] += 7;
    drive.values[20] -= 3;
    QVERIFY(!runJob(t, [&] { t.restore(file, {}); }));
    QCOMPARE(drive.writesDone, 2);
    QCOMPARE(drive.values, before);
    const RestoreReport &r = t.report();
    QVERIFY(r.isComplete());
    QCOMPARE(r.indices(RestoreReport::Outcome::Verified), (QList<int>{12, 20}));
    QVERIFY(r.notWritten().isEmpty());
}

void TestParameterTransfer::restoreRefusesOtherFirmwareUnlessForced()
{
    FakeDrive drive;
    ParameterTransfer t(&drive);
    QVERIFY(!runJob(t, [&] { t.backup(); }));
    const BackupFile file = t.backupFile();
    drive.firmware = QStringLiteral("7060");
    drive.values[12] += 1;
    const Error refused = runJob(t, [&] { t.restore(file, {}); });
    QCOMPARE(refused.code, ErrorCode::InvalidArgument);
    QVERIFY(refused.message.contains(QLatin1String("7060")));
    QCOMPARE(drive.writesDone, 0);
    RestoreOptions force;
    force.force = true;
    QVERIFY(!runJob(t, [&] { t.restore(file, force); }));
    QCOMPARE(drive.writesDone, 1);
}

void TestParameterTransfer::restoreReportsMismatch()
{
    FakeDrive drive;
    ParameterTransfer t(&drive);
    QVERIFY(!runJob(t, [&] { t.backup(); }));
    const BackupFile file = t.backupFile();
    drive.values[12] += 1;
    drive.values[13] += 1;
    drive.stuck = {13};
    const Error e = runJob(t, [&] { t.restore(file, {}); });
    QCOMPARE(e.code, ErrorCode::VerifyMismatch);
    const RestoreReport &r = t.report();
    QVERIFY(!r.isComplete());
    QCOMPARE(r.outcome(12), RestoreReport::Outcome::Verified);
    QCOMPARE(r.outcome(13), RestoreReport::Outcome::Mismatch);
    QCOMPARE(r.written(), (QList<int>{12, 13}));
}

void TestParameterTransfer::restoreReportsWhatWasNotWritten()
{
    FakeDrive drive;
    ParameterTransfer t(&drive);
    QVERIFY(!runJob(t, [&] { t.backup(); }));
    const BackupFile file = t.backupFile();
    for (int i : {10, 12, 14})
        drive.values[i] += 1;
    drive.refuse = {12};
    const Error e = runJob(t, [&] { t.restore(file, {}); });
    QCOMPARE(e.code, ErrorCode::DriveException);
    const RestoreReport &r = t.report();
    QCOMPARE(r.outcome(10), RestoreReport::Outcome::Verified);
    QCOMPARE(r.outcome(12), RestoreReport::Outcome::Failed);
    QCOMPARE(r.outcome(14), RestoreReport::Outcome::NotAttempted);
    QCOMPARE(r.written(), (QList<int>{10}));
    QCOMPARE(r.notWritten(), (QList<int>{12, 14}));
}

void TestParameterTransfer::unansweredReadBackIsUnconfirmed()
{
    RestoreReport r;
    auto result = [&r](int index, bool written, bool verified, bool readBackFailed) {
        DiffEntry e;
        e.index = index;
        r.selected.append(e);
        ParameterWriteResult w;
        w.index = index;
        w.requested = 5;
        w.readBack = verified ? 5 : 0;
        w.written = written;
        w.verified = verified;
        w.readBackFailed = readBackFailed;
        r.results.append(w);
    };
    result(1, true, true, false);   // verified
    result(2, true, false, true);   // the drive took it, the read-back got no answer
    result(3, false, false, true);  // no answer to the write nor to the read-back
    result(4, false, false, false); // refused
    QCOMPARE(r.outcome(1), RestoreReport::Outcome::Verified);
    QCOMPARE(r.outcome(2), RestoreReport::Outcome::Unconfirmed);
    QCOMPARE(r.outcome(3), RestoreReport::Outcome::Unconfirmed);
    QCOMPARE(r.outcome(4), RestoreReport::Outcome::Failed);
    QCOMPARE(r.written(), (QList<int>{1}));
    QCOMPARE(r.notWritten(), (QList<int>{4}));
    QCOMPARE(r.indices(RestoreReport::Outcome::Unconfirmed), (QList<int>{2, 3}));
    QVERIFY(!r.isComplete());
    QCOMPARE(RestoreReport::outcomeId(RestoreReport::Outcome::Unconfirmed), QStringLiteral("unconfirmed"));
}

void TestParameterTransfer::dryRunWritesNothing()
{
    FakeDrive drive;
    ParameterTransfer t(&drive);
    QVERIFY(!runJob(t, [&] { t.backup(); }));
    const BackupFile file = t.backupFile();
    drive.values[12] += 1;
    RestoreOptions dry;
    dry.dryRun = true;
    QVERIFY(!runJob(t, [&] { t.restore(file, dry); }));
    QCOMPARE(drive.writesDone, 0);
    QCOMPARE(t.report().selected.size(), 1);
    QVERIFY(t.report().dryRun);
    QVERIFY(!t.report().isComplete());
}

void TestParameterTransfer::onlyNarrowsTheSelection()
{
    FakeDrive drive;
    ParameterTransfer t(&drive);
    QVERIFY(!runJob(t, [&] { t.backup(); }));
    const BackupFile file = t.backupFile();
    drive.values[12] += 1;
    drive.values[13] += 1;
    RestoreOptions only;
    only.only = {13};
    QVERIFY(!runJob(t, [&] { t.restore(file, only); }));
    QCOMPARE(drive.writesDone, 1);
    QCOMPARE(drive.values[13], *file.values().value(13));
    QVERIFY(drive.values[12] != *file.values().value(12));
}

void TestParameterTransfer::readableIndicesFollowModels()
{
    const ParameterDictionary &shuoke = ParameterDictionary::bundled(Family::Shuoke);
    const QList<int> unknownModel = ParameterTransfer::readableIndices(shuoke, QString());
    for (int i : unknownModel) {
        const ParameterInfo *p = shuoke.byIndex(i);
        QVERIFY(p->isReadable());
        QVERIFY(p->models.isEmpty());
    }
    for (const ParameterInfo &p : shuoke.parameters())
        if (!p.isReadable())
            QVERIFY(!ParameterTransfer::readableIndices(shuoke, QStringLiteral("M6505")).contains(p.index));
}

void TestParameterTransfer::backupKeepsLastWrittenWriteOnlyValues()
{
    const ParameterDictionary &dict = ParameterDictionary::bundled(Family::Shuoke);
    const ParameterInfo *writeOnly = nullptr;
    for (const ParameterInfo &p : dict.parameters())
        if (!p.isReadable() && p.models.isEmpty() && !writeOnly)
            writeOnly = &p;
    QVERIFY(writeOnly);
    FakeDrive drive(Family::Shuoke);
    drive.firmware.clear();
    const qint64 value = writeOnly->max > writeOnly->min ? writeOnly->min + 1 : writeOnly->min;
    drive.lastWritten.insert(QString::number(writeOnly->index), value);
    ParameterTransfer t(&drive);
    QVERIFY(!runJob(t, [&] { t.backup(); }));
    const ParameterValue v = t.backupFile().values().entry(writeOnly->index);
    QCOMPARE(v.source, ValueSource::LastWritten);
    QCOMPARE(v.value, value);
    QByteArray json;
    const Error e = t.backupFile().toJson(dict, &json);
    QVERIFY2(!e, qPrintable(e.message));
}

QTEST_GUILESS_MAIN(TestParameterTransfer)
#include "tst_parametertransfer.moc"
