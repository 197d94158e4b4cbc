// Shuoke drives in the simulator bench that drivedesk-sim runs (SimBench): every framing
// comes up from options, a client reaches it with SimBench::clientSettings(), and the
// --state file keeps settings and positions across restarts.
#include <QtTest>

#include "core/drive/driveconnection.h"
#include "core/drive/drivereply.h"
#include "core/drive/shuoke/shuokedrive.h"
#include "core/protocol/shuoke/shuokecommands.h"
#include "sim/bench/simbench.h"
#include "tests/support/shuokeserialbench.h"

using namespace dd;
using namespace dd::shuoke;

class TestShuokeSimBench : public QObject
{
    Q_OBJECT

    static DriveReply *await(DriveReply *r)
    {
        ShuokeSerialBench::wait(r, 8000);
        return r;
    }

private slots:
    void framings_data()
    {
        QTest::addColumn<QString>("framing");
        QTest::addColumn<QString>("can");
        QTest::newRow("rtu") << QStringLiteral("rtu") << QString();
        QTest::newRow("ascii") << QStringLiteral("ascii") << QString();
        QTest::newRow("plc") << QStringLiteral("plc") << QString();
        QTest::newRow("can") << QString() << QStringLiteral("virtualcan:auto");
    }
    void framings()
    {
        QFETCH(QString, framing);
        QFETCH(QString, can);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        SimBenchOptions o;
        o.family = Family::Shuoke;
        o.addresses = {4};
        o.framing = framing;
        o.can = can;
        o.stateFile = dir.filePath(QStringLiteral("state.json"));
        {
            SimBench bench;
            const Error e = bench.start(o);
            if (e.code == ErrorCode::NotSupported)
                QSKIP(qPrintable(e.message));
            QVERIFY2(!e, qPrintable(e.message));
            DriveConnection c;
            Error ce;
            QVERIFY2(c.open(bench.clientSettings(), &ce), qPrintable(ce.message));
            auto *drive = qobject_cast<ShuokeDrive *>(c.drive(4));
            QVERIFY(drive);
            QTRY_VERIFY_WITH_TIMEOUT(c.isOpen(), 3000);
            DriveReply *r = await(drive->writeParameters({{CmdSetMaxSpeed, 23456}, {CmdEncoderAbTolerance, 99}}));
            QVERIFY2(r->ok(), qPrintable(r->error().message));
            r = await(drive->moveRelative(700, 0));
            QVERIFY2(r->ok(), qPrintable(r->error().message));
            QTRY_VERIFY_WITH_TIMEOUT(!(await(drive->readStatus())->status().running), 5000);
            c.close();
            bench.stop(); // saves the state
        }
        QVERIFY(QFileInfo::exists(o.stateFile));
        SimBench again;
        QVERIFY(!again.start(o));
        DriveConnection c;
        QVERIFY(c.open(again.clientSettings()));
        auto *drive = qobject_cast<ShuokeDrive *>(c.drive(4));
        QTRY_VERIFY_WITH_TIMEOUT(c.isOpen(), 3000);
        DriveReply *r = await(drive->readParameters({CmdSetMaxSpeed}));
        QVERIFY2(r->ok(), qPrintable(r->error().message));
        QCOMPARE(r->parameters().value(CmdSetMaxSpeed), 23456);
        r = await(drive->readChannels({QStringLiteral("position")}));
        QVERIFY2(r->ok(), qPrintable(r->error().message));
        QCOMPARE(r->samples().value(QStringLiteral("position")), 700.0);
        c.close();
    }

    void badOptions()
    {
        SimBench bench;
        SimBenchOptions o;
        o.family = Family::Shuoke;
        o.baud = 57600; // code 9 is reserved
        QCOMPARE(bench.start(o).code, ErrorCode::InvalidArgument);
        o.baud = 0;
        o.framing = QStringLiteral("can"); // CAN framing on a pty
        QCOMPARE(bench.start(o).code, ErrorCode::InvalidArgument);
        o.framing = QStringLiteral("rtu");
        o.addresses = {248};
        QCOMPARE(bench.start(o).code, ErrorCode::InvalidArgument);
    }
};

QTEST_GUILESS_MAIN(TestShuokeSimBench)
#include "tst_shuokesimbench.moc"
