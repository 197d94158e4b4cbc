// Shuoke host side without I/O: connection options, the reply matchers the serial
// transport gives SerialLink, and the parameter table against the bundled dictionary.
#include <QtTest>

#include "core/drive/shuoke/shuokeoptions.h"
#include "core/drive/shuoke/shuokeparameter.h"
#include "core/drive/shuoke/shuokeserialtransport.h"
#include "core/link/connectionsettings.h"
#include "core/params/parameterdictionary.h"
#include "core/protocol/modbus/crc16.h"
#include "core/protocol/shuoke/shuokeascii.h"
#include "core/protocol/shuoke/shuokertu.h"

using namespace dd;
using namespace dd::shuoke;

namespace {
QByteArray hostRtu(const Frame &f)
{
    return *encodeRtu(f).value;
}
} // namespace

class TestShuokeHost : public QObject
{
    Q_OBJECT

private slots:
    void optionDefaults()
    {
        ConnectionSettings s;
        s.port = QStringLiteral("/dev/null");
        Error e;
        const ShuokeOptions o = ShuokeOptions::fromSettings(s, &e);
        QVERIFY(!e);
        QCOMPARE(o.framing, ShuokeFraming::Rtu);
        QCOMPARE(o.checksum, AsciiCheck::PlainSum);
        QCOMPARE(o.byteOrder, ByteOrder::LittleEndian);
        QCOMPARE(o.broadcast, quint8(0));
        QVERIFY(!o.model);
        QCOMPARE(o.minGapMs, 50);
        QVERIFY(!o.gapFromReply);
        QCOMPARE(o.plcBase, quint16(0));
        s.port.clear();
        s.can = QStringLiteral("virtualcan:can0");
        QCOMPARE(ShuokeOptions::fromSettings(s, &e).framing, ShuokeFraming::Can);
        QVERIFY(!e);
    }

    void optionValues()
    {
        ConnectionSettings s;
        s.port = QStringLiteral("/dev/null");
        s.framing = QStringLiteral("ASCII");
        s.options = {{QStringLiteral("shuoke.checksum"), QStringLiteral("twos-complement")},
                     {QStringLiteral("shuoke.byteOrder"), QStringLiteral("big")},
                     {QStringLiteral("shuoke.broadcast"), 255},
                     {QStringLiteral("shuoke.model"), QStringLiteral("m4505s")},
                     {QStringLiteral("shuoke.minGapMs"), 80},
                     {QStringLiteral("shuoke.gapFrom"), QStringLiteral("Reply")},
                     {QStringLiteral("shuoke.plcBase"), QStringLiteral("0x100")}};
        Error e;
        const ShuokeOptions o = ShuokeOptions::fromSettings(s, &e);
        QVERIFY2(!e, qPrintable(e.message));
        QCOMPARE(o.framing, ShuokeFraming::Ascii);
        QCOMPARE(o.checksum, AsciiCheck::TwosComplement);
        QCOMPARE(o.byteOrder, ByteOrder::BigEndian);
        QCOMPARE(o.broadcast, quint8(255));
        QCOMPARE(*o.model, Model::M4505S);
        QCOMPARE(o.minGapMs, 80);
        QVERIFY(o.gapFromReply);
        QCOMPARE(o.plcBase, quint16(0x100));
    }

    void gapPacing()
    {
        ShuokeOptions o;
        int gap = -1;
        int spacing = -1;
        o.applyGap(9600, 10, &gap, &spacing); // 3.5 characters = 3.65 ms
        QCOMPARE(gap, 4);
        QCOMPARE(spacing, 50);
        o.applyGap(38400, 10, &gap, &spacing); // 0.91 ms
        QCOMPARE(gap, 1);
        o.applyGap(300, 10, &gap, &spacing); // 116.7 ms
        QCOMPARE(gap, 117);
        o.gapFromReply = true;
        o.applyGap(9600, 10, &gap, &spacing);
        QCOMPARE(gap, 50);
        QCOMPARE(spacing, 0);
    }

    void optionErrors_data()
    {
        QTest::addColumn<QString>("key");
        QTest::addColumn<QVariant>("value");
        QTest::newRow("checksum") << "shuoke.checksum" << QVariant(QStringLiteral("crc"));
        QTest::newRow("byteOrder") << "shuoke.byteOrder" << QVariant(QStringLiteral("middle"));
        QTest::newRow("broadcast") << "shuoke.broadcast" << QVariant(7);
        QTest::newRow("model") << "shuoke.model" << QVariant(QStringLiteral("M9000"));
        QTest::newRow("gap") << "shuoke.minGapMs" << QVariant(-1);
        QTest::newRow("gapFrom") << "shuoke.gapFrom" << QVariant(QStringLiteral("both"));
        QTest::newRow("base") << "shuoke.plcBase" << QVariant(QStringLiteral("x"));
    }
    void optionErrors()
    {
        QFETCH(QString, key);
        QFETCH(QVariant, value);
        ConnectionSettings s;
        s.port = QStringLiteral("/dev/null");
        s.options.insert(key, value);
        Error e;
        ShuokeOptions::fromSettings(s, &e);
        QCOMPARE(e.code, ErrorCode::InvalidArgument);
        QVERIFY(e.message.contains(key));
        ConnectionSettings wrong;
        wrong.port = QStringLiteral("/dev/null");
        wrong.framing = QStringLiteral("can");
        ShuokeOptions::fromSettings(wrong, &e);
        QCOMPARE(e.code, ErrorCode::InvalidArgument);
    }

    void rtuMatcher()
    {
        const Frame request = Frame::make(3, CmdGetMaxSpeed);
        const ReplyMatcher m = ShuokeSerialTransport::rtuMatcher(request);
        const QByteArray reply = hostRtu(Frame::make(3, CmdGetMaxSpeed, encodeUInt32(1234)));
        // in pieces
        QCOMPARE(m(reply.left(2)).status, FrameMatch::Status::Incomplete);
        QCOMPARE(m(reply.left(8)).status, FrameMatch::Status::Incomplete);
        FrameMatch r = m(reply + QByteArray::fromHex("aa"));
        QCOMPARE(r.status, FrameMatch::Status::Match);
        QCOMPARE(r.consumed, reply.size());
        QCOMPARE(r.frame, reply);
        // noise, another drive's reply, another command, the echo of the request
        QCOMPARE(m(QByteArray::fromHex("ff") + reply).status, FrameMatch::Status::Garbage);
        QCOMPARE(m(hostRtu(Frame::make(4, CmdGetMaxSpeed, encodeUInt32(1)))).status, FrameMatch::Status::Garbage);
        QCOMPARE(m(hostRtu(Frame::make(3, CmdGetStartSpeed, encodeUInt32(1)))).status, FrameMatch::Status::Garbage);
        r = m(hostRtu(request));
        QCOMPARE(r.status, FrameMatch::Status::Garbage);
        QCOMPARE(r.consumed, 5);
        // a failure reply matches
        const QByteArray failure = hostRtu(Frame::failureReply(3, CmdGetMaxSpeed, FailureOutOfRange));
        QCOMPARE(m(failure).status, FrameMatch::Status::Match);
        // a reply with a bad CRC is corrupt (the link retries at once)
        QByteArray bad = reply;
        bad[4] = static_cast<char>(bad.at(4) ^ 0x10);
        r = m(bad + QByteArray(5, '\0')); // enough bytes for every reading of its length
        QCOMPARE(r.status, FrameMatch::Status::Corrupt);
        QCOMPARE(r.consumed, reply.size());
        // the seed's "len counts the CRC" variant is accepted
        QByteArray withCrcLen = reply.left(reply.size() - 2);
        withCrcLen[2] = 6;
        withCrcLen = withCrc16(withCrcLen);
        QCOMPARE(m(withCrcLen).status, FrameMatch::Status::Match);
    }

    void rtuMatcherBroadcastAndAddressChange()
    {
        const ReplyMatcher any = ShuokeSerialTransport::rtuMatcher(Frame::make(0, CmdQueryAddress));
        QCOMPARE(any(hostRtu(Frame::make(42, CmdQueryAddress))).status, FrameMatch::Status::Match);
        const ReplyMatcher change = ShuokeSerialTransport::rtuMatcher(
            Frame::make(1, CmdChangeAddress, QByteArray(1, '\x09')));
        QCOMPARE(change(hostRtu(Frame::make(1, CmdChangeAddress, QByteArray(1, '\x09')))).status,
                 FrameMatch::Status::Match);
        QCOMPARE(change(hostRtu(Frame::make(9, CmdChangeAddress, QByteArray(1, '\x09')))).status,
                 FrameMatch::Status::Match);
        QCOMPARE(change(hostRtu(Frame::make(5, CmdChangeAddress, QByteArray(1, '\x09')))).status,
                 FrameMatch::Status::Garbage);
        // 0x42 may be answered with 0x41 (the seed's example)
        const ReplyMatcher inputs = ShuokeSerialTransport::rtuMatcher(Frame::make(1, CmdReadInputs));
        QCOMPARE(inputs(hostRtu(Frame::make(1, CmdReadIoSubstitution, QByteArray(5, '\0')))).status,
                 FrameMatch::Status::Match);
    }

    void asciiMatcher_data()
    {
        QTest::addColumn<int>("check");
        QTest::newRow("sum") << int(AsciiCheck::PlainSum);
        QTest::newRow("lrc") << int(AsciiCheck::TwosComplement);
    }
    void asciiMatcher()
    {
        QFETCH(int, check);
        AsciiOptions o;
        o.check = AsciiCheck(check);
        const Frame request = Frame::make(2, CmdQueryStatus);
        const ReplyMatcher m = ShuokeSerialTransport::asciiMatcher(request, o);
        const QByteArray line = *encodeAscii(Frame::make(2, CmdQueryStatus, QByteArray::fromHex("0100010001")), o).value;
        QCOMPARE(m(line.left(7)).status, FrameMatch::Status::Incomplete);
        FrameMatch r = m("xx" + line);
        QCOMPARE(r.status, FrameMatch::Status::Garbage);
        QCOMPARE(r.consumed, 2);
        r = m(line);
        QCOMPARE(r.status, FrameMatch::Status::Match);
        QCOMPARE(r.frame, line);
        // a frame cut short by the next one
        QCOMPARE(m(line.left(6) + line).status, FrameMatch::Status::Garbage);
        // the other check byte: corrupt
        AsciiOptions other;
        other.check = o.check == AsciiCheck::PlainSum ? AsciiCheck::TwosComplement : AsciiCheck::PlainSum;
        const QByteArray otherLine =
            *encodeAscii(Frame::make(2, CmdQueryStatus, QByteArray::fromHex("0100010001")), other).value;
        QCOMPARE(m(otherLine).status, FrameMatch::Status::Corrupt);
        // an endless line without LF is dropped
        QCOMPARE(m(":" + QByteArray(60, '0')).status, FrameMatch::Status::Garbage);
    }

    void parametersMatchTheBundledDictionary()
    {
        const ParameterDictionary &dict = ParameterDictionary::bundled(Family::Shuoke);
        QVERIFY(!dict.isEmpty());
        QCOMPARE(dict.size(), ShuokeParameter::all().size());
        for (const ShuokeParameter &p : ShuokeParameter::all()) {
            const ParameterInfo *info = dict.byIndex(p.index());
            QVERIFY2(info, p.key);
            QCOMPARE(info->key, QString::fromLatin1(p.key));
            QCOMPARE(info->isReadable(), p.isReadable());
            QCOMPARE(info->readCommand, p.isReadable() ? int(p.readCommand) : -1);
            QCOMPARE(info->min, p.min);
            QCOMPARE(info->max, p.max);
            const CommandInfo *set = commandInfo(p.setCommand);
            QVERIFY(set);
            QVERIFY(set->allowsRequestLength(p.size));
            QCOMPARE(set->readCommand, p.readCommand);
            QCOMPARE(set->flags.testFlag(WriteOnly), !p.isReadable());
        }
    }

    void parameterValues()
    {
        const ShuokeParameter *speed = ShuokeParameter::byIndex(CmdSetMaxSpeed);
        QCOMPARE(speed->encode(100000, ByteOrder::LittleEndian), QByteArray::fromHex("a0860100"));
        QCOMPARE(speed->encode(100000, ByteOrder::BigEndian), QByteArray::fromHex("000186a0"));
        QCOMPARE(*speed->decode(QByteArray::fromHex("a0860100"), ByteOrder::LittleEndian), 100000);
        QVERIFY(!speed->decode(QByteArray::fromHex("a08601"), ByteOrder::LittleEndian));
        const ShuokeParameter *baud = ShuokeParameter::byIndex(CmdSetBaudCode);
        QCOMPARE(baud->encode(7, ByteOrder::BigEndian), QByteArray(1, '\x07'));
        QVERIFY(!ShuokeParameter::byIndex(CmdGetMaxSpeed));
        QVERIFY(!ShuokeParameter::byIndex(CmdSetGearNumerator)->isSupportedBy(Model::M4505S));
        QVERIFY(ShuokeParameter::byIndex(CmdSkipCrcCheck)->isSupportedBy(Model::M4505S));
        QVERIFY(!ShuokeParameter::byIndex(CmdSkipCrcCheck)->isSupportedBy(Model::M6505));
    }
};

QTEST_APPLESS_MAIN(TestShuokeHost)
#include "tst_shuokehost.moc"
