#include <QtTest>

#include "core/protocol/modbus/crc16.h"
#include "core/protocol/shuoke/shuokecommands.h"
#include "core/protocol/shuoke/shuokeplc.h"
#include "tests/support/hex.h"
#include "tests/support/shuokeframestring.h"

using namespace dd::shuoke;
using dd::Decoded;

namespace {

using dd::test::hex;
QByteArray request(const Frame &f, quint16 base = 0)
{
    const Decoded<QByteArray> e = encodePlcRequest(f, PlcOptions{base});
    return e.ok() ? *e.value : QByteArray("encode failed: ") + e.error.toLatin1();
}

} // namespace

class TestShuokePlc : public QObject
{
    Q_OBJECT
private slots:
    // The seed's PLC chapter (mapping base 0; its CRCs are "0xnn": computed independently).
    void seedRequests_data()
    {
        QTest::addColumn<Frame>("frame");
        QTest::addColumn<QByteArray>("adu");
        QTest::addColumn<QByteArray>("replyAdu");
        QTest::addColumn<Frame>("reply");
        QTest::newRow("change address -> 2: 02 00 00 00")
            << Frame::make(1, 0x22, hex("02")) << hex("011000220002040200000071d6") << hex("011000220002e1c2")
            << Frame::make(1, 0x22);
        QTest::newRow("change address, reply from the new address")
            << Frame::make(1, 0x22, hex("02")) << hex("011000220002040200000071d6") << hex("021000220002e1f1")
            << Frame::make(2, 0x22);
        QTest::newRow("set baud 9600: 06 00 00 00")
            << Frame::make(1, 0x24, hex("06")) << hex("0110002400020406000000f0cc") << hex("01100024000201c3")
            << Frame::make(1, 0x24);
        QTest::newRow("set start speed 1000") << Frame::make(1, 0x25, hex("e8030000"))
                                              << hex("011000250002"
                                                     "04e8030000f428")
                                              << hex("0110002500025003") << Frame::make(1, 0x25);
        QTest::newRow("home: dir 00 00 00") << Frame::make(1, 0x3E, hex("01"))
                                            << hex("011000"
                                                   "3e0002040100000070cb")
                                            << QByteArray() << Frame();
        QTest::newRow("clear absolute position: zeros")
            << Frame::make(1, 0x38) << hex("0110003800020400000000f11d") << QByteArray() << Frame();
        QTest::newRow("emergency stop, broadcast") << Frame::make(0, 0x3C)
                                                   << hex("001000"
                                                          "3c0002040000000"
                                                          "0f412")
                                                   << QByteArray() << Frame();
        QTest::newRow("encoder direction: 1 register")
            << Frame::make(1, 0x5C, hex("01")) << hex("0110005c0001020100ab5c") << hex("0110005c0001c1db")
            << Frame::make(1, 0x5C);
        QTest::newRow("read example (0x28)") << Frame::make(1, 0x28) << hex("0103002800024403")
                                             << hex("010304a0860100384a") << Frame::make(1, 0x28, hex("a0860100"));
        QTest::newRow("handshake: 0 registers")
            << Frame::make(1, 0x20) << hex("0103002000004400") << hex("01030020f0") << Frame::make(1, 0x20);
        QTest::newRow("query address, broadcast: 0 registers")
            << Frame::make(0, 0x21) << hex("0003002100001411") << hex("01030020f0") << Frame::make(1, 0x21);
        QTest::newRow("get baud: code 00 00 00") << Frame::make(1, 0x23) << hex("01030023000235c1")
                                                 << hex("01030406000000fabb") << Frame::make(1, 0x23, hex("06"));
        QTest::newRow("status: 4 registers, first 5 bytes") << Frame::make(1, 0x3B) << hex("0103003b000435c4")
                                                            << hex("0103080100010001000000"
                                                                   "5436")
                                                            << Frame::make(1, 0x3B, hex("0100010001"));
    }
    void seedRequests()
    {
        QFETCH(Frame, frame);
        QFETCH(QByteArray, adu);
        QFETCH(QByteArray, replyAdu);
        QFETCH(Frame, reply);
        QCOMPARE(request(frame).toHex(' '), adu.toHex(' '));
        QCOMPARE(plcReplySize(frame), frame.command == 0x3B ? 13 : (adu.at(1) == 0x03 ? 5 + 2 * adu.at(5) : 8));
        if (replyAdu.isEmpty())
            return;
        const Decoded<Frame> d = decodePlcReply(replyAdu, frame);
        QVERIFY2(d.ok(), qPrintable(d.error));
        QCOMPARE(*d.value, reply);
    }

    void layout()
    {
        const auto l = plcRequestLayout(Frame::make(1, 0x22, hex("02")), PlcOptions{0x100});
        QVERIFY(l.ok());
        QCOMPARE(l.value->function, quint8(PlcWriteRegisters));
        QCOMPARE(l.value->registerAddress, quint16(0x122));
        QCOMPARE(l.value->registerCount, quint16(2));
        QCOMPARE(l.value->values.toHex(' '), QByteArray("02 00 00 00"));
        QCOMPARE(plcBytesToRegisters(l.value->values), (QList<quint16>{0x0200, 0x0000}));
        const auto r = plcRequestLayout(Frame::make(1, 0x3B));
        QCOMPARE(r.value->function, quint8(PlcReadRegisters));
        QCOMPARE(r.value->registerAddress, quint16(0x3B));
        QCOMPARE(r.value->registerCount, quint16(4));
        QVERIFY(r.value->values.isEmpty());
        const auto one = plcRequestLayout(Frame::make(1, 0x5E, hex("01")));
        QCOMPARE(one.value->registerCount, quint16(1));
        QCOMPARE(one.value->values.toHex(), QByteArray("0100"));
    }

    void mappingBase()
    {
        QCOMPARE(request(Frame::make(1, 0x25, hex("e8030000")), 0x100).toHex(' '),
                 hex("0110012500020"
                     "4e8030000f9b8")
                     .toHex(' '));
        QCOMPARE(request(Frame::make(1, 0x26), 0x100).toHex(' '),
                 hex("01030126"
                     "0002243c")
                     .toHex(' '));
        const Decoded<Frame> reply = decodePlcReply(dd::withCrc16(hex("010304e8030000")), Frame::make(1, 0x26),
                                                    PlcOptions{0x100});
        QVERIFY2(reply.ok(), qPrintable(reply.error));
        QCOMPARE(*reply.value, Frame::make(1, 0x26, hex("e8030000")));
        // The drive side finds the command behind the base.
        QCOMPARE(*decodePlcRequest(hex("0103012600022"
                                       "43c"),
                                   PlcOptions{0x100})
                      .value,
                 Frame::make(1, 0x26));
        QVERIFY(!decodePlcRequest(hex("01030126000224"
                                      "3c"),
                                  PlcOptions{0})
                     .ok());
        // base + command beyond 0xFFFF
        QVERIFY(!encodePlcRequest(Frame::make(1, 0x25, hex("e8030000")), PlcOptions{0xFFF0}).ok());
        QVERIFY(encodePlcRequest(Frame::make(1, 0x25, hex("e8030000")), PlcOptions{0xFFDA}).ok());
    }

    void unmapped()
    {
        for (quint8 c : {0x3F, 0x40, 0x41, 0x42, 0x43, 0x44, 0x47, 0x48, 0x4A, 0x4C, 0x4E, 0x4F}) {
            const auto e = encodePlcRequest(Frame::make(1, c, QByteArray(commandInfo(c)->maxRequestLength(), 1)));
            QVERIFY(!e.ok());
            QVERIFY2(e.error.contains(QLatin1String("no PLC mapping")), qPrintable(e.error));
            QCOMPARE(plcReplySize(Frame::make(1, c)), -1);
        }
        QVERIFY(!encodePlcRequest(Frame::make(1, 0x70)).ok());
        QVERIFY(!encodePlcRequest(Frame::make(1, 0x25, hex("e80300"))).ok()); // wrong length
        QVERIFY(!encodePlcRequest(Frame::make(1, 0x36, hex("00"))).ok());
        QVERIFY(!encodePlcRequest(Frame::failureReply(1, 0x36, 1)).ok());
    }

    void exceptionReplies()
    {
        const Decoded<Frame> w = decodePlcReply(hex("0190044dc3"), Frame::make(1, 0x25, hex("e8030000")));
        QVERIFY2(w.ok(), qPrintable(w.error));
        QCOMPARE(*w.value, Frame::failureReply(1, 0x25, 4));
        const Decoded<Frame> r = decodePlcReply(hex("018302c0f1"), Frame::make(1, 0x36));
        QVERIFY2(r.ok(), qPrintable(r.error));
        QCOMPARE(*r.value, Frame::failureReply(1, 0x36, 2));
        // drive side produces the same bytes
        QCOMPARE(encodePlcReply(Frame::failureReply(1, 0x25, 4), Frame::make(1, 0x25, hex("e8030000"))).value->toHex(),
                 QByteArray("0190044dc3"));
        for (quint8 code = 1; code <= 5; ++code) {
            const Frame req = Frame::make(1, 0x37);
            const QByteArray adu = *encodePlcReply(Frame::failureReply(1, 0x37, code), req).value;
            QCOMPARE(adu.size(), 5);
            QCOMPARE(quint8(adu.at(1)), quint8(0x83));
            QCOMPARE(*decodePlcReply(adu, req).value, Frame::failureReply(1, 0x37, code));
        }
    }

    void malformedReplies_data()
    {
        QTest::addColumn<Frame>("request");
        QTest::addColumn<QByteArray>("adu");
        QTest::addColumn<QString>("why");
        const Frame read = Frame::make(1, 0x28);
        const Frame write = Frame::make(1, 0x22, hex("02"));
        QTest::newRow("short") << read << hex("0103") << "too short";
        QTest::newRow("bad crc") << read << hex("010304a0860100384b") << "CRC";
        QTest::newRow("wrong address") << read << dd::withCrc16(hex("020304a0860100")) << "address";
        QTest::newRow("wrong function") << read << dd::withCrc16(hex("010404a0860100")) << "function";
        QTest::newRow("write function to a read") << read << dd::withCrc16(hex("011000280002")) << "function";
        QTest::newRow("byte count 2") << read << dd::withCrc16(hex("010302a086")) << "byte count";
        QTest::newRow("byte count vs size") << read << dd::withCrc16(hex("010304a08601")) << "byte count";
        QTest::newRow("write echo register") << write << dd::withCrc16(hex("011000230002")) << "echoes";
        QTest::newRow("write echo count") << write << dd::withCrc16(hex("011000220001")) << "echoes";
        QTest::newRow("write reply too long") << write << dd::withCrc16(hex("01100022000200")) << "8 expected";
        QTest::newRow("exception too long") << write << dd::withCrc16(hex("01900400")) << "exception";
        QTest::newRow("unmapped request") << Frame::make(1, 0x42) << hex("0103000000") << "no PLC mapping";
    }
    void malformedReplies()
    {
        QFETCH(Frame, request);
        QFETCH(QByteArray, adu);
        QFETCH(QString, why);
        const Decoded<Frame> d = decodePlcReply(adu, request);
        QVERIFY(!d.ok());
        QVERIFY2(d.error.contains(why), qPrintable(d.error));
    }

    void replyData()
    {
        QCOMPARE(plcReplyData(0x23, hex("06000000")).value->toHex(), QByteArray("06"));
        QCOMPARE(plcReplyData(0x3B, hex("0100010001000000")).value->toHex(), QByteArray("0100010001"));
        QCOMPARE(plcReplyData(0x37, plcRegistersToBytes({0x18fc, 0xffff})).value->toHex(), QByteArray("18fcffff"));
        QVERIFY(plcReplyData(0x20, QByteArray()).value->isEmpty());
        QVERIFY(!plcReplyData(0x37, hex("18fc")).ok());
        QVERIFY(!plcReplyData(0x25, hex("00000000")).ok()); // a write
    }

    void registerWords()
    {
        QCOMPARE(plcBytesToRegisters(hex("0200"
                                         "0000")),
                 (QList<quint16>{0x0200, 0x0000}));
        QCOMPARE(plcBytesToRegisters(hex("a0860100")), (QList<quint16>{0xa086, 0x0100}));
        QCOMPARE(plcBytesToRegisters(hex("a08601")), (QList<quint16>{0xa086}));
        QCOMPARE(plcRegistersToBytes({0x1234, 0xabcd}).toHex(), QByteArray("1234abcd"));
        QVERIFY(plcRegistersToBytes({}).isEmpty());
    }

    // Host request -> drive decode -> drive reply -> host decode, for every mapped command.
    void roundTripEveryMappedCommand()
    {
        int checked = 0;
        for (const quint16 base : {quint16(0), quint16(0x0400)}) {
            for (const CommandInfo &c : commandTable()) {
                if (c.plcAccess == PlcAccess::None)
                    continue;
                for (int n = 0; n <= c.maxRequestLength(); ++n) {
                    if (!c.allowsRequestLength(n))
                        continue;
                    QByteArray data;
                    for (int i = 0; i < n; ++i)
                        data.append(static_cast<char>(0x31 + i + c.code));
                    const Frame req = Frame::make(5, c.code, data);
                    const QByteArray adu = request(req, base);
                    QVERIFY2(dd::hasValidCrc16(adu), adu.constData());
                    QCOMPARE(adu.size(), c.plcAccess == PlcAccess::Read ? 8 : 9 + 2 * c.plcRegisters);

                    // Drive side: the same command comes out, data as the RTU command
                    // carries it (a PLC write always carries the full value: "clear" = 0).
                    const Decoded<Frame> onDrive = decodePlcRequest(adu, PlcOptions{base});
                    QVERIFY2(onDrive.ok(), qPrintable(onDrive.error));
                    QCOMPARE(onDrive.value->address, quint8(5));
                    QCOMPARE(onDrive.value->command, c.code);
                    const int carried = c.plcAccess == PlcAccess::Write ? c.maxRequestLength() : 0;
                    QCOMPARE(onDrive.value->data, data + QByteArray(carried - n, '\0'));

                    QByteArray replyData;
                    if (c.plcAccess == PlcAccess::Read)
                        for (int i = 0; i < c.maxReplyLength(); ++i)
                            replyData.append(static_cast<char>(0x91 + i));
                    const Frame reply = Frame::make(5, c.code, replyData);
                    const Decoded<QByteArray> replyAdu = encodePlcReply(reply, req, PlcOptions{base});
                    QVERIFY2(replyAdu.ok(), qPrintable(replyAdu.error));
                    QCOMPARE(replyAdu.value->size(), plcReplySize(req));
                    const Decoded<Frame> back = decodePlcReply(*replyAdu.value, req, PlcOptions{base});
                    QVERIFY2(back.ok(), qPrintable(back.error));
                    QCOMPARE(*back.value, reply);
                    ++checked;
                }
            }
        }
        QCOMPARE(checked, 2 * (17 + 30 + 2)); // 17 reads, 30 writes, 0x59/0x5B twice
    }

    void malformedRequests_data()
    {
        QTest::addColumn<QByteArray>("adu");
        QTest::addColumn<QString>("why");
        QTest::newRow("short") << hex("010300") << "too short";
        QTest::newRow("bad crc") << hex("0103002800024404") << "CRC";
        QTest::newRow("unmapped register") << dd::withCrc16(hex("010300420002")) << "maps to no command";
        QTest::newRow("register below base") << dd::withCrc16(hex("010300100002")) << "maps to no command";
        QTest::newRow("read of a write command") << dd::withCrc16(hex("010300250002")) << "function";
        QTest::newRow("write of a read command") << dd::withCrc16(hex("0110002800020400000000")) << "function";
        QTest::newRow("wrong count") << dd::withCrc16(hex("010300280001")) << "registers";
        QTest::newRow("byte count") << dd::withCrc16(hex("0110002500020300000000")) << "byte count";
        QTest::newRow("read too long") << dd::withCrc16(hex("01030028000200")) << "8 expected";
    }
    void malformedRequests()
    {
        QFETCH(QByteArray, adu);
        QFETCH(QString, why);
        const Decoded<Frame> d = decodePlcRequest(adu);
        QVERIFY(!d.ok());
        QVERIFY2(d.error.contains(why), qPrintable(d.error));
    }

    void replyTooLongForRegisters()
    {
        QVERIFY(!encodePlcReply(Frame::make(1, 0x23, hex("0600000000")), Frame::make(1, 0x23)).ok());
    }
};

QTEST_APPLESS_MAIN(TestShuokePlc)
#include "tst_shuokeplc.moc"
