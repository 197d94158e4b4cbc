#include <QtTest>

#include "core/protocol/modbus/crc16.h"
#include "core/protocol/modbus/modbusrtu.h"
#include "tests/support/hex.h"

using namespace dd;
using namespace dd::modbusrtu;

Q_DECLARE_METATYPE(dd::modbusrtu::DecodeError)
Q_DECLARE_METATYPE(dd::modbusrtu::Request)

namespace {

using dd::test::hex;
// A frame with a correct CRC over arbitrary (possibly malformed) content.
QByteArray crcd(const char *h)
{
    return withCrc16(QByteArray::fromHex(h));
}

Request readReq(quint8 addr, quint16 start, quint16 count)
{
    Request r;
    r.address = addr;
    r.function = ReadHoldingRegisters;
    r.start = start;
    r.count = count;
    return r;
}

Request writeMultiReq(quint8 addr, quint16 start, QList<quint16> values)
{
    Request r;
    r.address = addr;
    r.function = WriteMultipleRegisters;
    r.start = start;
    r.count = static_cast<quint16>(values.size());
    r.values = std::move(values);
    return r;
}

Request writeSingleReq(quint8 addr, quint16 reg, quint16 value)
{
    Request r;
    r.address = addr;
    r.function = WriteSingleRegister;
    r.start = reg;
    r.count = 1;
    r.values = {value};
    return r;
}

} // namespace

class TestModbusRtu : public QObject
{
    Q_OBJECT
private slots:
    // ---- encoders: well-known Modbus vectors ----
    void encodeRequests()
    {
        QCOMPARE(encodeReadHoldingRequest(0x01, 0x0000, 10).toHex(' '), hex("01 03 00 00 00 0A C5 CD").toHex(' '));
        // Modbus application protocol spec examples (server 0x11).
        QCOMPARE(encodeReadHoldingRequest(0x11, 0x006B, 3).toHex(' '), hex("11 03 00 6B 00 03 76 87").toHex(' '));
        QCOMPARE(encodeWriteSingleRequest(0x11, 0x0001, 0x0003).toHex(' '), hex("11 06 00 01 00 03 9A 9B").toHex(' '));
        QCOMPARE(encodeWriteSingleRequest(0x01, 0x0001, 0x0003).toHex(' '), hex("01 06 00 01 00 03 98 0B").toHex(' '));
        QCOMPARE(encodeWriteMultipleRequest(0x11, 0x0001, {0x000A, 0x0102}).toHex(' '),
                 hex("11 10 00 01 00 02 04 00 0A 01 02 C6 F0").toHex(' '));
        QCOMPARE(encodeRequest(writeMultiReq(0x11, 0x0001, {0x000A, 0x0102})).toHex(' '),
                 hex("11 10 00 01 00 02 04 00 0A 01 02 C6 F0").toHex(' '));
        QCOMPARE(encodeRequest(readReq(0x11, 0x006B, 3)).toHex(' '), hex("11 03 00 6B 00 03 76 87").toHex(' '));
        QCOMPARE(encodeRequest(writeSingleReq(0x11, 1, 3)).toHex(' '), hex("11 06 00 01 00 03 9A 9B").toHex(' '));
    }
    void encodeReplies()
    {
        QCOMPARE(encodeReadHoldingReply(0x11, {0xAE41, 0x5652, 0x4340}).toHex(' '),
                 hex("11 03 06 AE 41 56 52 43 40 49 AD").toHex(' '));
        QCOMPARE(encodeWriteSingleReply(0x11, 0x0001, 0x0003).toHex(' '), hex("11 06 00 01 00 03 9A 9B").toHex(' '));
        QCOMPARE(encodeWriteMultipleReply(0x11, 0x0001, 2).toHex(' '), hex("11 10 00 01 00 02 12 98").toHex(' '));
        QCOMPARE(encodeExceptionReply(0x01, 0x03, IllegalDataAddress).toHex(' '), hex("01 83 02 C0 F1").toHex(' '));
        QCOMPARE(encodeExceptionReply(0x01, 0x03, ServerDeviceFailure).toHex(' '), hex("01 83 04 40 F3").toHex(' '));
        // An exception flag already set is not doubled.
        QCOMPARE(encodeExceptionReply(0x01, 0x83, 0x04).toHex(' '), hex("01 83 04 40 F3").toHex(' '));
    }
    void encodersRefuseWhatModbusForbids()
    {
        QVERIFY(encodeReadHoldingRequest(1, 0, 0).isEmpty());
        QVERIFY(encodeReadHoldingRequest(1, 0, 126).isEmpty());
        QCOMPARE(encodeReadHoldingRequest(1, 0, 125).size(), 8);
        QVERIFY(encodeWriteMultipleRequest(1, 0, {}).isEmpty());
        QVERIFY(encodeWriteMultipleRequest(1, 0, QList<quint16>(124, 0)).isEmpty());
        QCOMPARE(encodeWriteMultipleRequest(1, 0, QList<quint16>(123, 0)).size(), 9 + 246);
        QVERIFY(encodeReadHoldingReply(1, {}).isEmpty());
        QVERIFY(encodeReadHoldingReply(1, QList<quint16>(126, 0)).isEmpty());
        QCOMPARE(encodeReadHoldingReply(1, QList<quint16>(125, 0)).size(), 5 + 250);
        Request bad = writeMultiReq(1, 0, {1, 2});
        bad.count = 3;
        QVERIFY(encodeRequest(bad).isEmpty());
        Request unknown = readReq(1, 0, 1);
        unknown.function = 0x04;
        QVERIFY(encodeRequest(unknown).isEmpty());
    }
    void expectedSizes()
    {
        QCOMPARE(expectedReplySize(readReq(1, 0, 20)), 45);
        QCOMPARE(expectedReplySize(writeMultiReq(1, 0, {1, 2, 3})), 8);
        QCOMPARE(expectedReplySize(writeSingleReq(1, 0, 1)), 8);
        Request unknown;
        unknown.function = 0x2B;
        QCOMPARE(expectedReplySize(unknown), 0);
    }

    // ---- request decoder (drive side) ----
    void decodeValidRequests()
    {
        DecodeError why = DecodeError::TooShort;
        auto d = decodeRequest(hex("11 03 00 6B 00 03 76 87"), UseStandardLimit, &why);
        QVERIFY2(d.ok(), qPrintable(d.error));
        QCOMPARE(why, DecodeError::None);
        QCOMPARE(*d.value, readReq(0x11, 0x006B, 3));

        d = decodeRequest(hex("11 06 00 01 00 03 9A 9B"));
        QVERIFY(d.ok());
        QCOMPARE(*d.value, writeSingleReq(0x11, 1, 3));

        d = decodeRequest(hex("11 10 00 01 00 02 04 00 0A 01 02 C6 F0"));
        QVERIFY(d.ok());
        QCOMPARE(*d.value, writeMultiReq(0x11, 1, {0x000A, 0x0102}));

        // Broadcast decodes too; whether to answer is the caller's business.
        d = decodeRequest(encodeWriteSingleRequest(0x00, 0x0000, 1));
        QVERIFY(d.ok());
        QCOMPARE(d.value->address, quint8(0));
    }
    void decodeRequestRejects_data()
    {
        QTest::addColumn<QByteArray>("adu");
        QTest::addColumn<int>("limit");
        QTest::addColumn<DecodeError>("reason");
        QTest::newRow("empty") << QByteArray() << 0 << DecodeError::TooShort;
        QTest::newRow("3 bytes") << hex("01 03 00") << 0 << DecodeError::TooShort;
        QTest::newRow("bad crc") << hex("01 03 00 00 00 0A C5 CE") << 0 << DecodeError::BadCrc;
        QTest::newRow("crc bytes swapped") << hex("01 03 00 00 00 0A CD C5") << 0 << DecodeError::BadCrc;
        QTest::newRow("truncated") << hex("01 03 00 00 00 0A C5") << 0 << DecodeError::BadCrc;
        QTest::newRow("fc 0x04") << crcd("01 04 00 00 00 01") << 0 << DecodeError::UnknownFunction;
        QTest::newRow("fc 0x83") << crcd("01 83 04") << 0 << DecodeError::UnknownFunction;
        QTest::newRow("0x03 too long") << crcd("01 03 00 00 00 01 00") << 0 << DecodeError::WrongLength;
        QTest::newRow("0x03 too short") << crcd("01 03 00 00 00") << 0 << DecodeError::WrongLength;
        QTest::newRow("0x06 too long") << crcd("01 06 00 00 00 01 00") << 0 << DecodeError::WrongLength;
        QTest::newRow("0x10 too short") << crcd("01 10 00 64 00 01") << 0 << DecodeError::WrongLength;
        QTest::newRow("0x10 bc vs length")
            << crcd("01 10 00 64 00 02 04 00 01 00") << 0 << DecodeError::ByteCountMismatch;
        QTest::newRow("0x10 bc vs count") << crcd("01 10 00 64 00 02 02 00 01") << 0 << DecodeError::ByteCountMismatch;
        QTest::newRow("0x03 count 0") << crcd("01 03 00 64 00 00") << 0 << DecodeError::CountOutOfRange;
        QTest::newRow("0x03 count 126") << crcd("01 03 00 00 00 7E") << 0 << DecodeError::CountOutOfRange;
        QTest::newRow("0x03 count 21, drive limit 20")
            << crcd("01 03 00 64 00 15") << 20 << DecodeError::CountOutOfRange;
        QTest::newRow("0x10 count 0") << crcd("01 10 00 64 00 00 00") << 0 << DecodeError::CountOutOfRange;
        QByteArray w21 = QByteArray::fromHex("0110006400152A") + QByteArray(42, '\0');
        QTest::newRow("0x10 count 21, drive limit 20") << withCrc16(w21) << 20 << DecodeError::CountOutOfRange;
        QByteArray w124 = QByteArray::fromHex("01100000007CF8") + QByteArray(248, '\0');
        QTest::newRow("0x10 count 124") << withCrc16(w124) << 0 << DecodeError::CountOutOfRange;
    }
    void decodeRequestRejects()
    {
        QFETCH(QByteArray, adu);
        QFETCH(int, limit);
        QFETCH(DecodeError, reason);
        DecodeError why = DecodeError::None;
        const auto d = decodeRequest(adu, limit, &why);
        QVERIFY(!d.ok());
        QCOMPARE(why, reason);
        QVERIFY2(d.error.startsWith(decodeErrorName(reason)), qPrintable(d.error));
    }
    void decodeRequestLimits()
    {
        QVERIFY(decodeRequest(crcd("01 03 00 64 00 14"), 20).ok());
        QVERIFY(decodeRequest(crcd("01 03 00 00 00 7D")).ok()); // 125, the Modbus limit
        QVERIFY(decodeRequest(crcd("01 03 00 64 00 15")).ok()); // 21 is fine for Modbus
        QByteArray w20 = QByteArray::fromHex("01100064001428") + QByteArray(40, '\0');
        QVERIFY(decodeRequest(withCrc16(w20), 20).ok());
        QVERIFY(decodeRequest(encodeWriteMultipleRequest(1, 0, QList<quint16>(123, 7))).ok());
    }

    // ---- reply decoder (host side) ----
    void decodeValidReplies()
    {
        DecodeError why = DecodeError::TooShort;
        auto d = decodeReply(hex("11 03 06 AE 41 56 52 43 40 49 AD"), readReq(0x11, 0x006B, 3), &why);
        QVERIFY2(d.ok(), qPrintable(d.error));
        QCOMPARE(why, DecodeError::None);
        QCOMPARE(d.value->values, (QList<quint16>{0xAE41, 0x5652, 0x4340}));
        QCOMPARE(d.value->count, quint16(3));
        QVERIFY(!d.value->isException);

        d = decodeReply(hex("11 10 00 01 00 02 12 98"), writeMultiReq(0x11, 1, {0x000A, 0x0102}));
        QVERIFY(d.ok());
        QCOMPARE(d.value->start, quint16(1));
        QCOMPARE(d.value->count, quint16(2));

        d = decodeReply(hex("11 06 00 01 00 03 9A 9B"), writeSingleReq(0x11, 1, 3));
        QVERIFY(d.ok());
        QCOMPARE(d.value->values, QList<quint16>{3});
    }
    void writeSingleReplyValueIsReturnedNotCompared()
    {
        // The servo-modbus legacy EE reply reports progress in the value (0 = running).
        const auto d = decodeReply(encodeWriteSingleReply(5, 0x0000, 0x0000), writeSingleReq(5, 0x0000, 1));
        QVERIFY2(d.ok(), qPrintable(d.error));
        QCOMPARE(d.value->values, QList<quint16>{0});
    }
    void exceptionRecognisedWhateverItsAddress()
    {
        // The seed: the drive fixes the address byte of an error reply to 0x01.
        DecodeError why = DecodeError::TooShort;
        auto d = decodeReply(hex("01 83 04 40 F3"), readReq(5, 0x64, 20), &why);
        QVERIFY2(d.ok(), qPrintable(d.error));
        QCOMPARE(why, DecodeError::None);
        QVERIFY(d.value->isException);
        QCOMPARE(d.value->exceptionCode, quint8(0x04));
        QCOMPARE(d.value->function, quint8(0x03));
        QCOMPARE(d.value->address, quint8(0x01));

        d = decodeReply(hex("01 90 04 4D C3"), writeMultiReq(5, 0x64, {1}));
        QVERIFY(d.ok());
        QVERIFY(d.value->isException);
        QCOMPARE(d.value->function, quint8(0x10));

        d = decodeReply(hex("01 86 04 43 A3"), writeSingleReq(7, 0, 1));
        QVERIFY(d.ok());
        QVERIFY(d.value->isException);
        QCOMPARE(d.value->function, quint8(0x06));

        // Its own address works as well.
        d = decodeReply(encodeExceptionReply(5, 0x03, IllegalDataValue), readReq(5, 0, 1));
        QVERIFY(d.ok());
        QCOMPARE(d.value->exceptionCode, quint8(IllegalDataValue));
    }
    void decodeReplyRejects_data()
    {
        QTest::addColumn<QByteArray>("adu");
        QTest::addColumn<Request>("request");
        QTest::addColumn<DecodeError>("reason");
        const Request read3 = readReq(0x11, 0x006B, 3);
        const Request write2 = writeMultiReq(0x11, 1, {0x000A, 0x0102});
        const Request single = writeSingleReq(0x11, 1, 3);
        QTest::newRow("4 bytes") << hex("01 83 04 40") << read3 << DecodeError::TooShort;
        QTest::newRow("bad crc") << hex("11 03 06 AE 41 56 52 43 40 49 AE") << read3 << DecodeError::BadCrc;
        QTest::newRow("exception bad crc") << hex("01 83 04 40 F4") << read3 << DecodeError::BadCrc;
        QTest::newRow("other address") << encodeReadHoldingReply(0x12, {1, 2, 3}) << read3
                                       << DecodeError::AddressMismatch;
        QTest::newRow("other function") << encodeWriteMultipleReply(0x11, 0x6B, 3) << read3
                                        << DecodeError::FunctionMismatch;
        QTest::newRow("exception of other function") << hex("01 90 04 4D C3") << read3 << DecodeError::FunctionMismatch;
        QTest::newRow("exception too long") << crcd("01 83 04 00") << read3 << DecodeError::WrongLength;
        QTest::newRow("0x03 bc vs length") << crcd("11 03 06 00 01 00 02") << read3 << DecodeError::ByteCountMismatch;
        QTest::newRow("0x03 odd bc") << crcd("11 03 05 00 01 00 02 00") << read3 << DecodeError::ByteCountMismatch;
        QTest::newRow("0x03 fewer registers")
            << encodeReadHoldingReply(0x11, {1, 2}) << read3 << DecodeError::CountMismatch;
        QTest::newRow("0x03 more registers")
            << encodeReadHoldingReply(0x11, {1, 2, 3, 4}) << read3 << DecodeError::CountMismatch;
        QTest::newRow("0x10 too long") << crcd("11 10 00 01 00 02 00") << write2 << DecodeError::WrongLength;
        QTest::newRow("0x10 start echo") << encodeWriteMultipleReply(0x11, 2, 2) << write2 << DecodeError::EchoMismatch;
        QTest::newRow("0x10 count echo") << encodeWriteMultipleReply(0x11, 1, 1) << write2 << DecodeError::EchoMismatch;
        QTest::newRow("0x06 register echo")
            << encodeWriteSingleReply(0x11, 2, 3) << single << DecodeError::EchoMismatch;
        QTest::newRow("0x06 too short") << crcd("11 06 00 01 00") << single << DecodeError::WrongLength;
        QTest::newRow("to broadcast") << encodeWriteSingleReply(0x00, 1, 3) << writeSingleReq(0, 1, 3)
                                      << DecodeError::AddressMismatch;
        QTest::newRow("exception to broadcast")
            << hex("01 86 04 43 A3") << writeSingleReq(0, 0, 1) << DecodeError::AddressMismatch;
    }
    void decodeReplyRejects()
    {
        QFETCH(QByteArray, adu);
        QFETCH(Request, request);
        QFETCH(DecodeError, reason);
        DecodeError why = DecodeError::None;
        const auto d = decodeReply(adu, request, &why);
        QVERIFY(!d.ok());
        QCOMPARE(why, reason);
        QVERIFY2(d.error.startsWith(decodeErrorName(reason)), qPrintable(d.error));
    }

    void roundTrips()
    {
        const QList<quint16> values{0x0000, 0xFFFF, 0x8000, 0x7FFF, 0x1234};
        const Request w = writeMultiReq(0x2A, 0x0064, values);
        const auto dq = decodeRequest(encodeRequest(w), 20);
        QVERIFY(dq.ok());
        QCOMPARE(*dq.value, w);
        const auto dr = decodeReply(encodeReadHoldingReply(0x2A, values), readReq(0x2A, 0x64, 5));
        QVERIFY(dr.ok());
        QCOMPARE(dr.value->values, values);
    }
    void randomFramesDecodeOnlyWhatReencodes()
    {
        // Random CRC-valid ADUs: whatever a decoder accepts encodes back to the same bytes.
        QRandomGenerator rng(4242);
        const quint8 functions[] = {0x03, 0x06, 0x10, 0x83, 0x86, 0x90, 0x04};
        int acceptedRequests = 0, acceptedReplies = 0;
        for (int i = 0; i < 20000; ++i) {
            QByteArray body(rng.bounded(1, 40), Qt::Uninitialized);
            for (auto &c : body)
                c = static_cast<char>(rng.bounded(256));
            body[0] = 5;
            if (body.size() > 1)
                body[1] = static_cast<char>(functions[rng.bounded(7)]);
            if (body.size() > 2 && rng.bounded(2))
                body[2] = static_cast<char>((body.size() - 3) & 0xFF); // plausible 0x03 byte count
            if (body.size() > 6 && rng.bounded(2)) {
                body[4] = 0;
                body[5] = static_cast<char>((body.size() - 7) / 2);
                body[6] = static_cast<char>(body.size() - 7); // plausible 0x10 header
            }
            const QByteArray adu = withCrc16(body);
            const auto q = decodeRequest(adu, 20);
            if (q.ok()) {
                ++acceptedRequests;
                QCOMPARE(encodeRequest(*q.value).toHex(' '), adu.toHex(' '));
            }
            const Request read = readReq(5, 0, quint16(rng.bounded(1, 20)));
            const auto r = decodeReply(adu, read);
            if (r.ok()) {
                ++acceptedReplies;
                const QByteArray again = r.value->isException
                    ? encodeExceptionReply(0x05, read.function, r.value->exceptionCode)
                    : encodeReadHoldingReply(5, r.value->values);
                QCOMPARE(again.toHex(' '), adu.toHex(' '));
            }
        }
        QVERIFY(acceptedRequests > 100);
        QVERIFY(acceptedReplies > 10);
    }
    void names()
    {
        QCOMPARE(exceptionCodeName(0x04), QStringLiteral("server device failure"));
        QCOMPARE(exceptionCodeName(0x42), QStringLiteral("exception 0x42"));
        QCOMPARE(decodeErrorName(DecodeError::BadCrc), QStringLiteral("bad-crc"));
        QVERIFY(isKnownFunction(0x03) && isKnownFunction(0x06) && isKnownFunction(0x10));
        QVERIFY(!isKnownFunction(0x04) && !isKnownFunction(0x83));
    }
};

QTEST_APPLESS_MAIN(TestModbusRtu)
#include "tst_modbusrtu.moc"
