// ChannelSampler: fixed rate, one read in flight (slow links skip ticks), first error stops.
#include "drive/drive.h"
#include "trend/channelsampler.h"

#include <QSignalSpy>
#include <QTimer>
#include <QtTest>

using namespace dd;

namespace {

class ChannelDrive : public Drive
{
public:
    Family family() const override { return Family::ServoCan; }
    Capabilities capabilities() const override { return Capability::Monitor; }
    QList<ChannelInfo> channels() const override
    {
        return {{QStringLiteral("speed"), QStringLiteral("Speed"), QStringLiteral("r/min"), 0}};
    }
    DriveReply *readChannels(const QStringList &ids) override
    {
        ++reads;
        asked = ids;
        DriveReply *r = newReply();
        const int n = reads;
        const Error e = n == failAt ? Error{ErrorCode::Timeout, QStringLiteral("no reply")} : Error{};
        QTimer::singleShot(latencyMs, r, [r, n, e] {
            r->setSample(QStringLiteral("speed"), n * 10.0);
            r->finish(e);
        });
        return r;
    }
    int reads = 0;
    int failAt = -1;
    int latencyMs = 0;
    QStringList asked;
};

} // namespace

class TestChannelSampler : public QObject
{
    Q_OBJECT

private slots:
    void samplesAtTheRate();
    void slowLinkSkipsTicks();
    void behindTheRateReadsBackToBack();
    void firstErrorStops();
};

void TestChannelSampler::samplesAtTheRate()
{
    ChannelDrive drive;
    ChannelSampler s(&drive);
    s.setChannels({QStringLiteral("speed")});
    s.setIntervalMs(20);
    QSignalSpy spy(&s, &ChannelSampler::sampled);
    s.start();
    QCOMPARE(drive.reads, 1);   // the first read goes out at once
    QTRY_VERIFY_WITH_TIMEOUT(spy.count() >= 5, 2000);
    s.stop();
    QCOMPARE(drive.asked, QStringList{QStringLiteral("speed")});
    double last = -1;
    for (const QList<QVariant> &args : spy) {
        const double t = args.at(0).toDouble();
        QVERIFY(t > last);
        last = t;
        using Samples = QMap<QString, double>;
        QVERIFY(args.at(1).value<Samples>().contains(QStringLiteral("speed")));
    }
    // The following ones every 20 ms (never sooner).
    QVERIFY(spy.at(4).at(0).toDouble() >= 0.06);
    const int n = drive.reads;
    QTest::qWait(60);
    QCOMPARE(drive.reads, n);   // stopped means stopped
}

void TestChannelSampler::slowLinkSkipsTicks()
{
    ChannelDrive drive;
    drive.latencyMs = 45;
    ChannelSampler s(&drive);
    s.setIntervalMs(10);
    QSignalSpy spy(&s, &ChannelSampler::sampled);
    s.start();
    QTRY_VERIFY_WITH_TIMEOUT(spy.count() >= 3, 2000);
    s.stop();
    QVERIFY(s.skippedCount() >= 2);
    QVERIFY(drive.reads <= spy.count() + 1);   // never more than one read outstanding
}

void TestChannelSampler::behindTheRateReadsBackToBack()
{
    // Reads take 250 ms, ticks come every 200 ms: the tick at 200 ms is skipped, and the
    // next read must leave when the first one is in (250 ms), not at the tick at 400 ms.
    ChannelDrive drive;
    drive.latencyMs = 250;
    ChannelSampler s(&drive);
    s.setIntervalMs(200);
    int readsWhenSampled = -1;
    connect(&s, &ChannelSampler::sampled, &s, [&] {
        if (readsWhenSampled < 0)
            readsWhenSampled = drive.reads;
    });
    s.start();
    QTRY_VERIFY_WITH_TIMEOUT(readsWhenSampled >= 0, 2000);
    s.stop();
    QVERIFY(s.skippedCount() >= 1);
    QCOMPARE(readsWhenSampled, 2);   // the second read was already out
}

void TestChannelSampler::firstErrorStops()
{
    ChannelDrive drive;
    drive.failAt = 3;
    ChannelSampler s(&drive);
    s.setIntervalMs(5);
    QSignalSpy samples(&s, &ChannelSampler::sampled);
    QSignalSpy failed(&s, &ChannelSampler::failed);
    s.start();
    QVERIFY(failed.wait(2000));
    QCOMPARE(samples.count(), 2);
    QVERIFY(!s.isRunning());
    QCOMPARE(failed.at(0).at(0).value<Error>().code, ErrorCode::Timeout);
    QTest::qWait(30);
    QCOMPARE(drive.reads, 3);
}

QTEST_GUILESS_MAIN(TestChannelSampler)
#include "tst_channelsampler.moc"
