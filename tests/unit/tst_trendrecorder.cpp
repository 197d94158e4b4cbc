#include <QtTest>

#include "core/trend/csvwriter.h"
#include "core/trend/trendrecorder.h"

#include <QSignalSpy>

using namespace dd;

class TestTrendRecorder : public QObject
{
    Q_OBJECT
private:
    static TrendChannel ch(const char *id, const char *unit = "")
    {
        return {QString::fromLatin1(id), QString::fromLatin1(id).toUpper(), QString::fromUtf8(unit), 0};
    }

private slots:
    void gapsMarkEveryChannelOnce()
    {
        TrendRecorder rec;
        rec.setChannels(
            {{QStringLiteral("a"), {}, {}, 0}, {QStringLiteral("b"), {}, {}, 0}, {QStringLiteral("c"), {}, {}, 0}});
        rec.append(QStringLiteral("a"), 100, 1);
        rec.append(QStringLiteral("b"), 300, 2); // later than the gap's time
        const quint64 rev = rec.revision();
        QCOMPARE(rec.appendGap(200), 2); // c has nothing to break
        QVERIFY(rec.revision() != rev);
        QCOMPARE(rec.buffer(QStringLiteral("a"))->gapTimes(0, 1000), (std::vector<qint64>{200}));
        QCOMPARE(rec.buffer(QStringLiteral("b"))->gapTimes(0, 1000), (std::vector<qint64>{300}));
        QCOMPARE(rec.appendGap(400), 0); // already broken: one mark per outage
        QVERIFY(!rec.lineValueAt(QStringLiteral("a"), 150));
        rec.append(QStringLiteral("a"), 500, 3);
        QCOMPARE(*rec.lineValueAt(QStringLiteral("a"), 500), 3.0);
        // The CSV writes the gap as a row of "nan".
        const QByteArray csv = CsvWriter::toCsv(rec.snapshotAll({QStringLiteral("a"), QStringLiteral("b")}));
        QVERIFY2(csv.contains("0.000100,nan,\n"), csv.constData());
        QVERIFY2(csv.contains("0.000200,,2\n0.000200,,nan\n"), csv.constData());
    }

    void appendsToKnownChannelsOnly()
    {
        TrendRecorder rec;
        rec.setChannels({ch("speed", "r/min"), ch("torque", "%")});
        QCOMPARE(rec.channelIds(), (QStringList{QStringLiteral("speed"), QStringLiteral("torque")}));
        QVERIFY(rec.isEmpty());
        QVERIFY(!rec.hasOrigin());
        const quint64 r0 = rec.revision();
        QVERIFY(rec.append(QStringLiteral("speed"), 100, 1.0));
        QVERIFY(rec.revision() != r0);
        QVERIFY(!rec.append(QStringLiteral("nope"), 200, 1.0));
        QVERIFY(!rec.append(QStringLiteral("speed"), 50, 1.0)); // older than the newest
        QCOMPARE(rec.rejectedCount(), 2u);
        QCOMPARE(
            rec.appendSamples(
                300, {{QStringLiteral("speed"), 2.0}, {QStringLiteral("torque"), 3.0}, {QStringLiteral("other"), 4.0}}),
            2);
        QVERIFY(rec.hasOrigin());
        QCOMPARE(rec.originUs(), 100);
        QCOMPARE(rec.firstTimeUs(), 100);
        QCOMPARE(rec.lastTimeUs(), 300);
        QCOMPARE(rec.buffer(QStringLiteral("speed"))->size(), 2);
        QCOMPARE(rec.buffer(QStringLiteral("torque"))->size(), 1);
        QVERIFY(rec.buffer(QStringLiteral("nope")) == nullptr);
        QCOMPARE(rec.channel(QStringLiteral("speed")).unit, QStringLiteral("r/min"));
    }

    void pauseKeepsRecording()
    {
        TrendRecorder rec;
        rec.setChannels({ch("speed")});
        QSignalSpy paused(&rec, &TrendRecorder::pausedChanged);
        rec.append(QStringLiteral("speed"), 1000, 1);
        rec.append(QStringLiteral("speed"), 2000, 2);
        rec.setPaused(true);
        QVERIFY(rec.isPaused());
        QCOMPARE(paused.count(), 1);
        QCOMPARE(rec.pausedAtUs(), 2000);
        QVERIFY(rec.append(QStringLiteral("speed"), 3000, 3));
        QVERIFY(rec.append(QStringLiteral("speed"), 4000, 4));
        QCOMPARE(rec.buffer(QStringLiteral("speed"))->size(), 4);
        QCOMPARE(rec.lastTimeUs(), 4000);
        QCOMPARE(rec.pausedAtUs(), 2000); // the frozen view end does not move
        rec.setPaused(true);              // no change, no signal
        QCOMPARE(paused.count(), 1);
        rec.setPaused(false);
        QCOMPARE(paused.count(), 2);
        QCOMPARE(paused.last().at(0).toBool(), false);
    }

    void setChannelsKeepsSurvivorsSamples()
    {
        TrendRecorder rec;
        QSignalSpy changed(&rec, &TrendRecorder::channelsChanged);
        rec.setChannels({ch("a"), ch("b")});
        rec.append(QStringLiteral("a"), 1, 1);
        rec.append(QStringLiteral("b"), 1, 2);
        rec.setChannels({ch("b"), ch("c"), ch("b"), TrendChannel{}});
        QCOMPARE(changed.count(), 2);
        QCOMPARE(rec.channelIds(), (QStringList{QStringLiteral("b"), QStringLiteral("c")}));
        QCOMPARE(rec.buffer(QStringLiteral("b"))->size(), 1);
        QCOMPARE(rec.buffer(QStringLiteral("c"))->size(), 0);
        rec.addChannel(ch("d", "V"));
        rec.addChannel(ch("d", "V")); // same: no signal
        QCOMPARE(changed.count(), 3);
        TrendChannel d2 = ch("d", "mV");
        rec.addChannel(d2);
        QCOMPARE(changed.count(), 4);
        QCOMPARE(rec.channel(QStringLiteral("d")).unit, QStringLiteral("mV"));
        QCOMPARE(rec.channelCount(), 3);
    }

    void clearKeepsChannels()
    {
        TrendRecorder rec;
        QSignalSpy cleared(&rec, &TrendRecorder::cleared);
        rec.setChannels({ch("a")});
        rec.append(QStringLiteral("a"), 500, 1);
        rec.clear();
        QCOMPARE(cleared.count(), 1);
        QVERIFY(rec.isEmpty());
        QCOMPARE(rec.channelCount(), 1);
        QVERIFY(!rec.hasOrigin());
        QVERIFY(rec.append(QStringLiteral("a"), 100, 1)); // earlier than before clear: fine
        QCOMPARE(rec.originUs(), 100);
        QCOMPARE(rec.memoryBytes(), rec.buffer(QStringLiteral("a"))->memoryBytes());
    }

    void boundedPerChannel()
    {
        TrendRecorder rec;
        QCOMPARE(rec.capacityPerChannel(), SampleBuffer::DefaultCapacity);
        rec.setCapacityPerChannel(100);
        rec.setChannels({ch("a"), ch("b")});
        for (int i = 0; i < 250; ++i)
            rec.appendSamples(i, {{QStringLiteral("a"), double(i)}, {QStringLiteral("b"), double(-i)}});
        QCOMPARE(rec.buffer(QStringLiteral("a"))->size(), 100);
        QCOMPARE(rec.droppedCount(), 300u);
        QCOMPARE(rec.firstTimeUs(), 150);
        QCOMPARE(rec.originUs(), 0);                                       // the origin stays: times keep their meaning
        QCOMPARE(rec.memoryBytes(), 2 * (100 * 16 + (100 / 64 + 2) * 32)); // samples + block summaries
    }

    void snapshots()
    {
        TrendRecorder rec;
        rec.setChannels({ch("a"), ch("b"), ch("c")});
        for (int i = 0; i < 10; ++i) {
            rec.append(QStringLiteral("a"), i * 10, i);
            if (i % 2 == 0)
                rec.append(QStringLiteral("b"), i * 10, -i);
        }
        const TrendSnapshot all = rec.snapshotAll();
        QCOMPARE(all.channels.size(), 3);
        QCOMPARE(all.series.at(0).size(), 10);
        QCOMPARE(all.series.at(1).size(), 5);
        QCOMPARE(all.series.at(2).size(), 0);
        QCOMPARE(all.fromUs, 0);
        QCOMPARE(all.toUs, 90);
        QCOMPARE(all.sampleCount(), 15);
        const TrendSnapshot w = rec.snapshot(25, 60, {QStringLiteral("b"), QStringLiteral("x"), QStringLiteral("a")});
        QCOMPARE(w.channels.size(), 2);
        QCOMPARE(w.channels.at(0).id, QStringLiteral("b"));
        QCOMPARE(w.series.at(0), (QList<TrendSample>{{40, -4}, {60, -6}}));
        QCOMPARE(w.series.at(1).size(), 4); // 30, 40, 50, 60
        QCOMPARE(w.originUs, 0);
    }
};

QTEST_GUILESS_MAIN(TestTrendRecorder)
#include "tst_trendrecorder.moc"
