// WriteVerification: how a parameter write ended and what a batch of writes finishes with,
// the same for every family (servo-modbus, servo-can, shuoke).
#include "core/drive/writeverification.h"

#include <QtTest>

using namespace dd;

namespace {

using Check = WriteVerification::Check;

Check check(int index, qint64 requested)
{
    Check c;
    c.index = index;
    c.requested = requested;
    c.label = QStringLiteral("PA%1").arg(index);
    return c;
}

const Error kTimeout{ErrorCode::Timeout, QStringLiteral("No reply within 100 ms.")};
const Error kRefused{ErrorCode::DriveException, QStringLiteral("The drive refused it."), 3};

} // namespace

class TestWriteVerification : public QObject
{
    Q_OBJECT

private slots:
    void verified();
    void verifiedDespiteALostAnswer();
    void mismatch();
    void mismatchNamesTheAttempts();
    void refusedWithoutReadBack();
    void unansweredAndReadBackOther();
    void unknownWhenNothingAnswered();
    void unacknowledgedWriteWithoutReadBackIsUnknown();
    void readBackFailed();
    void writeOnly();
    void writeOnlyRefused();
    void summaryNone();
    void summaryCountsMismatches();
    void summaryFailureBeatsAnEarlierMismatch();
    void summaryKeepsTheCauseOfTheFirstFailure();
    void resultsInOrder();
};

void TestWriteVerification::verified()
{
    Check c = check(5, 100);
    c.readBack = 100;
    Error cause{ErrorCode::Timeout, QStringLiteral("x")};
    const ParameterWriteResult r = WriteVerification::classify(c, &cause);
    QCOMPARE(r.outcome, WriteOutcome::Verified);
    QCOMPARE(r.index, 5);
    QCOMPARE(r.requested, qint64(100));
    QCOMPARE(r.readBack, qint64(100));
    QVERIFY(r.written);
    QVERIFY(r.verified);
    QVERIFY(r.readable);
    QVERIFY(!r.readBackFailed);
    QVERIFY(r.error.isEmpty());
    QVERIFY(!cause.isError());
}

void TestWriteVerification::verifiedDespiteALostAnswer()
{
    // The answer to the write was lost, but the drive holds the value: it took it.
    Check c = check(5, -7);
    c.writeError = kTimeout;
    c.readBack = -7;
    const ParameterWriteResult r = WriteVerification::classify(c);
    QCOMPARE(r.outcome, WriteOutcome::Verified);
    QVERIFY(r.written);
    QVERIFY(r.verified);
    QVERIFY(r.error.isEmpty());
}

void TestWriteVerification::mismatch()
{
    Check c = check(7, 300);
    c.readBack = 250;
    Error cause;
    const ParameterWriteResult r = WriteVerification::classify(c, &cause);
    QCOMPARE(r.outcome, WriteOutcome::Mismatch);
    QVERIFY(r.written);
    QVERIFY(!r.verified);
    QVERIFY(!r.readBackFailed);
    QCOMPARE(r.readBack, qint64(250));
    QCOMPARE(r.error, QStringLiteral("Wrote 300, but the drive reads back 250."));
    QVERIFY(!cause.isError());
}

void TestWriteVerification::mismatchNamesTheAttempts()
{
    Check c = check(30, 99);
    c.acknowledged = false;
    c.attempts = 7;
    c.readBack = 12;
    const ParameterWriteResult r = WriteVerification::classify(c);
    QCOMPARE(r.outcome, WriteOutcome::Mismatch);
    QVERIFY(r.written);
    QCOMPARE(r.error, QStringLiteral("Wrote 99, but the drive reads back 12. Written 7 time(s)."));
}

void TestWriteVerification::refusedWithoutReadBack()
{
    Check c = check(9, 1);
    c.writeError = kRefused;
    Error cause;
    const ParameterWriteResult r = WriteVerification::classify(c, &cause);
    QCOMPARE(r.outcome, WriteOutcome::NotWritten);
    QVERIFY(!r.written);
    QVERIFY(!r.verified);
    QVERIFY(!r.readBackFailed);
    QCOMPARE(r.error, kRefused.message);
    QCOMPARE(cause.code, ErrorCode::DriveException);
    QCOMPARE(cause.driveCode, 3);
}

void TestWriteVerification::unansweredAndReadBackOther()
{
    // No answer to the write, and the drive holds another value: it did not take it.
    Check c = check(9, 1);
    c.writeError = kTimeout;
    c.readBack = 4;
    const ParameterWriteResult r = WriteVerification::classify(c);
    QCOMPARE(r.outcome, WriteOutcome::NotWritten);
    QVERIFY(!r.written);
    QVERIFY(!r.readBackFailed);
    QCOMPARE(r.readBack, qint64(4));
    QCOMPARE(r.error, kTimeout.message + QStringLiteral(" The drive did not take the value: it reads back 4."));
}

void TestWriteVerification::unknownWhenNothingAnswered()
{
    Check c = check(9, 1);
    c.writeError = kTimeout;
    c.readError = {ErrorCode::ChecksumError, QStringLiteral("Bad CRC.")};
    Error cause;
    const ParameterWriteResult r = WriteVerification::classify(c, &cause);
    QCOMPARE(r.outcome, WriteOutcome::Unknown);
    QVERIFY(!r.written);
    QVERIFY(!r.verified);
    QVERIFY(r.readBackFailed);
    QVERIFY2(r.error.contains(QStringLiteral("could not be read back")), qPrintable(r.error));
    QVERIFY2(r.error.contains(kTimeout.message), qPrintable(r.error));
    QCOMPARE(cause.code, ErrorCode::Timeout); // the write's failure is the cause
}

void TestWriteVerification::unacknowledgedWriteWithoutReadBackIsUnknown()
{
    // servo-can: writes are never answered, so a failed read-back leaves it unknown.
    Check c = check(20, 123);
    c.acknowledged = false;
    c.readError = kTimeout;
    Error cause;
    const ParameterWriteResult r = WriteVerification::classify(c, &cause);
    QCOMPARE(r.outcome, WriteOutcome::Unknown);
    QVERIFY(!r.written);
    QVERIFY(r.readBackFailed);
    QCOMPARE(r.error,
             QStringLiteral("The write was not confirmed and could not be read back, so whether the "
                            "drive took the value is unknown: No reply within 100 ms. Read it again."));
    QCOMPARE(cause.code, ErrorCode::Timeout);
}

void TestWriteVerification::readBackFailed()
{
    Check c = check(20, 3);
    c.readError = kRefused;
    Error cause;
    const ParameterWriteResult r = WriteVerification::classify(c, &cause);
    QCOMPARE(r.outcome, WriteOutcome::ReadBackFailed);
    QVERIFY(r.written);
    QVERIFY(!r.verified);
    QVERIFY(r.readBackFailed);
    QCOMPARE(r.error, QStringLiteral("Written, but it could not be read back: The drive refused it."));
    QCOMPARE(cause.code, ErrorCode::DriveException);
}

void TestWriteVerification::writeOnly()
{
    Check c = check(0x48, 1);
    c.readable = false;
    Error cause;
    const ParameterWriteResult r = WriteVerification::classify(c, &cause);
    QCOMPARE(r.outcome, WriteOutcome::WriteOnly);
    QVERIFY(r.written);
    QVERIFY(!r.verified);
    QVERIFY(!r.readable);
    QVERIFY(!r.readBackFailed);
    QVERIFY(r.error.startsWith(QStringLiteral("Not readable")));
    QVERIFY(!cause.isError());
}

void TestWriteVerification::writeOnlyRefused()
{
    Check c = check(0x48, 1);
    c.readable = false;
    c.writeError = kTimeout;
    const ParameterWriteResult r = WriteVerification::classify(c);
    QCOMPARE(r.outcome, WriteOutcome::NotWritten);
    QVERIFY(!r.written);
    QVERIFY(!r.readable);
    QCOMPARE(r.error, kTimeout.message);
}

void TestWriteVerification::summaryNone()
{
    WriteVerification v;
    Check a = check(1, 1);
    a.readBack = 1;
    Check b = check(2, 2);
    b.readable = false;
    v.add(a);
    v.add(b);
    QVERIFY(!v.summary().isError()); // write-only is not an error
    QVERIFY(!WriteVerification().summary().isError());
}

void TestWriteVerification::summaryCountsMismatches()
{
    WriteVerification v;
    for (int i = 1; i <= 3; ++i) {
        Check c = check(i, 10);
        c.readBack = i == 2 ? 10 : 9;
        v.add(c);
    }
    const Error e = v.summary();
    QCOMPARE(e.code, ErrorCode::VerifyMismatch);
    QVERIFY2(e.message.startsWith(QStringLiteral("2 parameter(s) read back with another value than written "
                                                 "(first: PA1: Wrote 10, but the drive reads back 9.)")),
             qPrintable(e.message));
}

void TestWriteVerification::summaryFailureBeatsAnEarlierMismatch()
{
    // A write that failed outright says more than a value the drive limited: the batch
    // finishes with the failure, whatever came first (shuoke and servo-can used to report
    // the first unverified write, servo-can always as VerifyMismatch).
    WriteVerification v;
    Check a = check(1, 10);
    a.readBack = 9;
    Check b = check(2, 20);
    b.acknowledged = false;
    b.readError = kTimeout;
    v.add(a);
    v.add(b);
    const Error e = v.summary();
    QCOMPARE(e.code, ErrorCode::Timeout);
    QVERIFY2(e.message.startsWith(QStringLiteral("PA2: The write was not confirmed")), qPrintable(e.message));
}

void TestWriteVerification::summaryKeepsTheCauseOfTheFirstFailure()
{
    WriteVerification v;
    Check a = check(1, 10);
    a.readBack = 10;
    Check b = check(2, 20);
    b.writeError = kRefused;
    Check c = check(3, 30);
    c.readError = kTimeout;
    v.add(a);
    v.add(b);
    v.add(c);
    const Error e = v.summary();
    QCOMPARE(e.code, ErrorCode::DriveException);
    QCOMPARE(e.driveCode, 3);
    QCOMPARE(e.message, QStringLiteral("PA2: The drive refused it."));
}

void TestWriteVerification::resultsInOrder()
{
    WriteVerification v;
    Check a = check(4, 1);
    a.readBack = 1;
    Check b = check(2, 1);
    b.readBack = 0;
    const ParameterWriteResult ra = v.add(a);
    v.add(b);
    QCOMPARE(ra.outcome, WriteOutcome::Verified);
    const QList<ParameterWriteResult> all = v.results();
    QCOMPARE(all.size(), 2);
    QCOMPARE(all.at(0).index, 4);
    QCOMPARE(all.at(1).index, 2);
    QCOMPARE(all.at(1).outcome, WriteOutcome::Mismatch);
}

QTEST_GUILESS_MAIN(TestWriteVerification)
#include "tst_writeverification.moc"
