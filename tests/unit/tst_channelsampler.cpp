// ChannelSampler: fixed rate; a link slower than the rate skips ticks and gets up to two
// reads pipelined (never more); samples in the order the reads went out; first error stops.
#include "core/drive/drive.h"
#include "core/trend/channelsampler.h"

#include <QSignalSpy>
#include <QTimer>
#include <QtTest>

using namespace dd;

namespace {

// A drive whose reads take latencyMs (or latencies[n - 1] for read n). With `serial` they
// are served one at a time in the order asked, as a half-duplex link does: a read waits
// until the one before it is answered, then takes its latency.
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
        ++outstanding;
        maxOutstanding = std::max(maxOutstanding, outstanding);
        if (serial) {
            m_queue.append({r, n});
            if (m_queue.size() == 1) {
                if (reads > 1)
                    ++idleGaps; // the link had nothing to do since the previous answer
                serveHead();
            }
            return r;
        }
        QTimer::singleShot(latencyOf(n), r, [this, r, n] { answer(r, n); });
        return r;
    }
    int reads = 0;
    int failAt = -1;
    int latencyMs = 0;
    QList<int> latencies;
    bool serial = false;
    int outstanding = 0;
    int maxOutstanding = 0;
    int idleGaps = 0; // serial: a read found the link idle (all earlier reads answered)
    QStringList asked;

private:
    int latencyOf(int n) const { return n <= latencies.size() ? latencies.at(n - 1) : latencyMs; }
    void answer(DriveReply *r, int n)
    {
        --outstanding;
        const Error e = n == failAt ? Error{ErrorCode::Timeout, QStringLiteral("no reply")} : Error{};
        r->setSample(QStringLiteral("speed"), n * 10.0);
        r->finish(e);
    }
    void serveHead()
    {
        const QPair<QPointer<DriveReply>, int> head = m_queue.first();
        QTimer::singleShot(latencyOf(head.second), Qt::PreciseTimer, this, [this] {
            const QPair<QPointer<DriveReply>, int> done = m_queue.takeFirst();
            if (done.first)
                answer(done.first, done.second);
            else
                --outstanding;
            if (!m_queue.isEmpty())
                serveHead();
        });
    }
    QList<QPair<QPointer<DriveReply>, int>> m_queue;
};

using SamplerSamples = QMap<QString, double>;

// Runs a real event loop for `ms` (QTest::qWait sleeps between event passes).
void spin(int ms)
{
    QEventLoop loop;
    QTimer::singleShot(ms, Qt::PreciseTimer, &loop, &QEventLoop::quit);
    loop.exec();
}

} // namespace

class TestChannelSampler : public QObject
{
    Q_OBJECT

private slots:
    void samplesAtTheRate();
    void slowLinkSkipsTicks();
    void behindTheRateReadsBackToBack();
    void slowLinkGetsTwoReadsPipelined();
    void continuousKeepsTheLinkBusyWhateverTheRate();
    void overtakingReplyWaitsForTheEarlierRead();
    void stopIgnoresRepliesOnTheirWay();
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
    QCOMPARE(drive.reads, 1); // the first read goes out at once
    QTRY_VERIFY_WITH_TIMEOUT(spy.count() >= 5, 2000);
    s.stop();
    QCOMPARE(drive.asked, QStringList{QStringLiteral("speed")});
    double last = -1;
    for (const QList<QVariant> &args : spy) {
        const double t = args.at(0).toDouble();
        QVERIFY(t > last);
        last = t;
        QVERIFY(args.at(1).value<SamplerSamples>().contains(QStringLiteral("speed")));
    }
    // The following ones every 20 ms (never sooner).
    QVERIFY(spy.at(4).at(0).toDouble() >= 0.06);
    const int n = drive.reads;
    QTest::qWait(60);
    QCOMPARE(drive.reads, n); // stopped means stopped
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
    QVERIFY(drive.reads <= spy.count() + 2); // never more than two reads outstanding
    QCOMPARE(drive.maxOutstanding, 2);
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
    QCOMPARE(readsWhenSampled, 2); // the second read was already out
}

void TestChannelSampler::slowLinkGetsTwoReadsPipelined()
{
    // Asked for 1 ms on a link that takes 5 ms per read: two reads are out (one on the wire,
    // the next waiting behind it), never more, so the link never idles between samples.
    ChannelDrive drive;
    drive.serial = true;
    drive.latencyMs = 5;
    ChannelSampler s(&drive);
    s.setIntervalMs(1);
    QSignalSpy spy(&s, &ChannelSampler::sampled);
    int maxPending = 0;
    connect(&s, &ChannelSampler::sampled, &s, [&] { maxPending = std::max(maxPending, s.pendingReads()); });
    s.start();
    while (spy.count() < 20 && spy.wait(1000)) {
    }
    s.stop();
    QVERIFY(spy.count() >= 20);
    QCOMPARE(drive.maxOutstanding, 2);
    QCOMPARE(maxPending, 2);
    QCOMPARE(drive.idleGaps, 0);
    QVERIFY(s.skippedCount() > 0);
    // In order: read n answers n * 10; times never go backwards.
    double lastT = -1;
    for (int k = 0; k < spy.count(); ++k) {
        QCOMPARE(spy.at(k).at(1).value<SamplerSamples>().value(QStringLiteral("speed")), (k + 1) * 10.0);
        const double t = spy.at(k).at(0).toDouble();
        QVERIFY(t >= lastT);
        lastT = t;
    }
}

void TestChannelSampler::continuousKeepsTheLinkBusyWhateverTheRate()
{
    // A capture asks for as fast as the link allows: reads of 2 ms with ticks every 200 ms
    // would leave the link idle between ticks; continuous keeps two reads out all along.
    ChannelDrive drive;
    drive.serial = true;
    drive.latencyMs = 2;
    ChannelSampler s(&drive);
    s.setIntervalMs(200);
    s.setContinuous(true);
    QSignalSpy spy(&s, &ChannelSampler::sampled);
    s.start();
    while (spy.count() < 20 && spy.wait(1000)) {
    }
    s.stop();
    QVERIFY(spy.count() >= 20);
    QCOMPARE(drive.maxOutstanding, 2);
    QCOMPARE(drive.idleGaps, 0);
    for (int k = 0; k < spy.count(); ++k)
        QCOMPARE(spy.at(k).at(1).value<SamplerSamples>().value(QStringLiteral("speed")), (k + 1) * 10.0);
}

void TestChannelSampler::overtakingReplyWaitsForTheEarlierRead()
{
    // Read 1 takes 200 ms, read 2 (pipelined at the next tick) 5 ms: read 2's sample is
    // held until read 1's is out.
    ChannelDrive drive;
    drive.latencies = {200, 5};
    drive.latencyMs = 200;
    ChannelSampler s(&drive);
    s.setIntervalMs(1);
    QSignalSpy spy(&s, &ChannelSampler::sampled);
    s.start();
    QVERIFY(spy.wait(2000));
    while (spy.count() < 2 && spy.wait(1000)) {
    }
    s.stop();
    QVERIFY(spy.count() >= 2);
    QCOMPARE(spy.at(0).at(1).value<SamplerSamples>().value(QStringLiteral("speed")), 10.0);
    QCOMPARE(spy.at(1).at(1).value<SamplerSamples>().value(QStringLiteral("speed")), 20.0);
    QVERIFY(spy.at(0).at(0).toDouble() >= 0.2);
    QVERIFY(spy.at(1).at(0).toDouble() >= spy.at(0).at(0).toDouble());
}

void TestChannelSampler::stopIgnoresRepliesOnTheirWay()
{
    ChannelDrive drive;
    drive.latencyMs = 30;
    ChannelSampler s(&drive);
    s.setIntervalMs(1);
    QSignalSpy spy(&s, &ChannelSampler::sampled);
    s.start();
    spin(10);
    QCOMPARE(s.pendingReads(), 2);
    s.stop();
    QCOMPARE(s.pendingReads(), 0);
    spin(80);
    QCOMPARE(drive.outstanding, 0); // both were answered ...
    QCOMPARE(spy.count(), 0);       // ... and ignored
    QCOMPARE(drive.reads, 2);
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
