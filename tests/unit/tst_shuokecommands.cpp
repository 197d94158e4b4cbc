#include <QtTest>

#include "core/protocol/shuoke/shuokecommands.h"

#include <set>

using namespace dd::shuoke;

namespace {

quint16 mask(std::initializer_list<int> lengths)
{
    quint16 m = 0;
    for (int n : lengths)
        m = static_cast<quint16>(m | (1u << n));
    return m;
}

std::set<int> codesWith(CommandFlag flag)
{
    std::set<int> out;
    for (const CommandInfo &c : commandTable())
        if (c.flags.testFlag(flag))
            out.insert(c.code);
    return out;
}

std::set<int> codesWithPlc(PlcAccess access)
{
    std::set<int> out;
    for (const CommandInfo &c : commandTable())
        if (c.plcAccess == access)
            out.insert(c.code);
    return out;
}

} // namespace

class TestShuokeCommands : public QObject
{
    Q_OBJECT
private slots:
    void tableIsSortedAndComplete()
    {
        const QList<CommandInfo> &table = commandTable();
        std::set<int> expected;
        for (int c = 0x20; c <= 0x4F; ++c)
            expected.insert(c);
        for (int c = 0x55; c <= 0x62; ++c)
            expected.insert(c);
        expected.insert(0x65);
        expected.insert(0x66);
        std::set<int> got;
        for (qsizetype i = 0; i < table.size(); ++i) {
            got.insert(table[i].code);
            if (i > 0)
                QVERIFY(table[i - 1].code < table[i].code);
            QVERIFY(table[i].name && *table[i].name);
            QCOMPARE(table[i].replyCommands[0], table[i].code);
            QVERIFY(table[i].requestLengths != 0);
            QVERIFY(table[i].replyLengths != 0);
        }
        QCOMPARE(got, expected);
        QVERIFY(!commandInfo(0x1F));
        QVERIFY(!commandInfo(0x50));
        QVERIFY(!commandInfo(0x63));
        QVERIFY(!commandInfo(0x67));
        QVERIFY(!commandInfo(0xA5));
        QCOMPARE(commandInfo(0x3B)->code, quint8(0x3B));
        QCOMPARE(commandName(0x36), QStringLiteral("Query speed"));
        QCOMPARE(commandName(0x50), QStringLiteral("command 0x50"));
    }

    // Request and reply data lengths of the command table in docs/protocols/shuoke.md, row by row.
    void lengths_data()
    {
        QTest::addColumn<int>("code");
        QTest::addColumn<int>("request");
        QTest::addColumn<int>("reply");
        auto row = [](int code, std::initializer_list<int> r, std::initializer_list<int> a) {
            QTest::addRow("0x%02x", code) << code << int(mask(r)) << int(mask(a));
        };
        row(0x20, {0}, {0});
        row(0x21, {0}, {0});
        row(0x22, {1}, {1});
        row(0x23, {0}, {1});
        row(0x24, {1}, {1});
        for (int set : {0x25, 0x27, 0x29, 0x2B, 0x2D, 0x2F}) {
            row(set, {4}, {0});
            row(set + 1, {0}, {4});
        }
        for (int move : {0x31, 0x32, 0x33, 0x34, 0x35})
            row(move, {4}, {0});
        row(0x36, {0}, {4});
        row(0x37, {0}, {4});
        row(0x38, {0}, {0});
        row(0x39, {0}, {4});
        row(0x3A, {0}, {0});
        row(0x3B, {0}, {5});
        row(0x3C, {0}, {0});
        row(0x3D, {0}, {0});
        row(0x3E, {1}, {0});
        row(0x3F, {2}, {0});
        row(0x40, {1, 2, 3, 4, 5, 6, 7}, {0});
        row(0x41, {1}, {0, 1, 2, 3, 4, 5, 6, 7});
        row(0x42, {0}, {5});
        row(0x43, {0}, {5});
        row(0x44, {4}, {0});
        row(0x45, {0}, {0});
        row(0x46, {0}, {0});
        row(0x47, {0}, {0});
        for (int setting : {0x48, 0x49, 0x4A, 0x4B})
            row(setting, {1}, {1});
        row(0x4C, {5}, {5});
        row(0x4D, {5}, {5});
        row(0x4E, {1, 4}, {0});
        row(0x4F, {1, 4}, {0});
        for (int move : {0x55, 0x56, 0x57})
            row(move, {4}, {0});
        row(0x58, {0}, {4});
        row(0x59, {0, 4}, {0});
        row(0x5A, {0}, {4});
        row(0x5B, {0, 4}, {0});
        for (int flag : {0x5C, 0x5D, 0x5E})
            row(flag, {1}, {0});
        row(0x5F, {4}, {0});
        row(0x60, {0}, {4});
        row(0x61, {4}, {0});
        row(0x62, {0}, {4});
        row(0x65, {4}, {0});
        row(0x66, {4}, {0});
    }
    void lengths()
    {
        QFETCH(int, code);
        QFETCH(int, request);
        QFETCH(int, reply);
        const CommandInfo *c = commandInfo(static_cast<quint8>(code));
        QVERIFY(c);
        QCOMPARE(int(c->requestLengths), request);
        QCOMPARE(int(c->replyLengths), reply);
    }

    void namedCodes()
    {
        // Spot checks of the name enum against the seed's numbering.
        QCOMPARE(int(CmdHandshake), 0x20);
        QCOMPARE(int(CmdSetStartSpeed), 0x25);
        QCOMPARE(int(CmdQueryStatus), 0x3B);
        QCOMPARE(int(CmdSetPlcBase), 0x3F);
        QCOMPARE(int(CmdCanBitrate), 0x4B);
        QCOMPARE(int(CmdClosedLoopMove), 0x55);
        QCOMPARE(int(CmdEncoderDirection), 0x5C);
        QCOMPARE(int(CmdNoEncoderMaxPulses), 0x66);
        for (const int c : {CmdGetGearDenominator, CmdEncoderAbTolerance, CmdCanToSerialEcho, CmdFactoryReset})
            QVERIFY(commandInfo(static_cast<quint8>(c)));
    }

    void maxLengths()
    {
        QCOMPARE(commandInfo(0x3B)->maxReplyLength(), 5);
        QCOMPARE(commandInfo(0x3B)->maxRequestLength(), 0);
        QCOMPARE(commandInfo(0x59)->maxRequestLength(), 4);
        QCOMPARE(commandInfo(0x40)->maxRequestLength(), 7);
        QVERIFY(commandInfo(0x59)->allowsRequestLength(0));
        QVERIFY(!commandInfo(0x59)->allowsRequestLength(2));
        QVERIFY(!commandInfo(0x59)->allowsRequestLength(-1));
        QVERIFY(!commandInfo(0x59)->allowsRequestLength(99));
    }

    void flags()
    {
        QCOMPARE(codesWith(BroadcastAllowed), (std::set<int>{0x21, 0x3C, 0x3D}));
        QCOMPARE(codesWith(WriteOnly), (std::set<int>{0x3F, 0x48, 0x49, 0x4A, 0x4B, 0x5C, 0x5D, 0x5E, 0x65, 0x66}));
        QCOMPARE(codesWith(SerialOnly), (std::set<int>{0x40, 0x41, 0x4C}));
        QCOMPARE(codesWith(CanOnly), (std::set<int>{0x4D}));
        QCOMPARE(codesWith(NoCrcCheck), (std::set<int>{0x20}));
        QCOMPARE(codesWith(M4505SOnly), (std::set<int>{0x44, 0x45, 0x46, 0x47, 0x48, 0x49}));
        std::set<int> closedLoop;
        for (int c = 0x55; c <= 0x62; ++c)
            closedLoop.insert(c);
        closedLoop.insert(0x65);
        closedLoop.insert(0x66);
        QCOMPARE(codesWith(ClosedLoop), closedLoop);
        QCOMPARE(codesWith(M6505Only), closedLoop);
        QCOMPARE(codesWith(NotM4505),
                 (std::set<int>{0x2F, 0x30, 0x35, 0x3E, 0x40, 0x41, 0x42, 0x43, 0x4A, 0x4B, 0x4C, 0x4D, 0x4E, 0x4F}));
    }

    void readCommands()
    {
        const std::map<int, int> pairs{{0x24, 0x23}, {0x25, 0x26}, {0x27, 0x28}, {0x29, 0x2A}, {0x2B, 0x2C},
                                       {0x2D, 0x2E}, {0x2F, 0x30}, {0x38, 0x37}, {0x3A, 0x39}, {0x40, 0x41},
                                       {0x59, 0x58}, {0x5B, 0x5A}, {0x5F, 0x60}, {0x61, 0x62}};
        for (const CommandInfo &c : commandTable()) {
            const auto it = pairs.find(c.code);
            QCOMPARE(int(c.readCommand), it == pairs.end() ? 0 : it->second);
            if (c.flags.testFlag(WriteOnly))
                QCOMPARE(int(c.readCommand), 0);
        }
    }

    // The seed's PLC chapter: the write list (section 五 + closed loop) and the read list (六).
    void plcMapping()
    {
        QCOMPARE(
            codesWithPlc(PlcAccess::Write),
            (std::set<int>{0x22, 0x24, 0x25, 0x27, 0x29, 0x2B, 0x2D, 0x2F, 0x31, 0x32, 0x33, 0x34, 0x35, 0x38, 0x3A,
                           0x3C, 0x3D, 0x3E, 0x55, 0x56, 0x57, 0x59, 0x5B, 0x5C, 0x5D, 0x5E, 0x5F, 0x61, 0x65, 0x66}));
        QCOMPARE(codesWithPlc(PlcAccess::Read),
                 (std::set<int>{0x20, 0x21, 0x23, 0x26, 0x28, 0x2A, 0x2C, 0x2E, 0x30, 0x36, 0x37, 0x39, 0x3B, 0x58,
                                0x5A, 0x60, 0x62}));
        for (const CommandInfo &c : commandTable()) {
            int expected = 2;
            if (c.plcAccess == PlcAccess::None)
                expected = 0;
            else if (c.code == 0x3B)
                expected = 4;
            else if (c.code == 0x20 || c.code == 0x21)
                expected = 0;
            else if (c.code >= 0x5C && c.code <= 0x5E)
                expected = 1;
            QCOMPARE(int(c.plcRegisters), expected);
            // Everything a PLC write carries fits its registers; every PLC read reply too.
            if (c.plcAccess == PlcAccess::Write)
                QVERIFY(c.maxRequestLength() <= 2 * c.plcRegisters);
            if (c.plcAccess == PlcAccess::Read)
                QVERIFY(c.maxReplyLength() <= 2 * c.plcRegisters);
        }
    }

    void models()
    {
        QVERIFY(isSupportedBy(0x25, Model::M4505));
        QVERIFY(isSupportedBy(0x25, Model::M6505));
        QVERIFY(!isSupportedBy(0x2F, Model::M4505));
        QVERIFY(isSupportedBy(0x2F, Model::M4505S));
        QVERIFY(isSupportedBy(0x2F, Model::M6505));
        QVERIFY(!isSupportedBy(0x44, Model::M6505));
        QVERIFY(isSupportedBy(0x44, Model::M4505S));
        QVERIFY(!isSupportedBy(0x55, Model::M4505S));
        QVERIFY(isSupportedBy(0x55, Model::M6505));
        QVERIFY(!isSupportedBy(0x4E, Model::M4505, 1));
        QVERIFY(isSupportedBy(0x4E, Model::M6505, 1));
        QVERIFY(!isSupportedBy(0x4E, Model::M6505, 4));
        QVERIFY(isSupportedBy(0x4F, Model::M4505S, 4));
        QVERIFY(isSupportedBy(0x4F, Model::M6505));
        QVERIFY(!isSupportedBy(0x4F, Model::M4505));
        QVERIFY(!isSupportedBy(0x4E, Model::M4505S, 2));
        QVERIFY(!isSupportedBy(0x25, Model::M6505, 3));
        QVERIFY(!isSupportedBy(0x50, Model::M6505));
        QCOMPARE(modelName(Model::M4505S), QStringLiteral("M4505S"));
    }

    void replyCommands()
    {
        QCOMPARE(acceptedReplyCommands(Frame::make(1, 0x25, QByteArray(4, 0))), (QList<quint8>{0x25}));
        for (quint8 c : {0x42, 0x43, 0x44, 0x45, 0x46})
            QCOMPARE(acceptedReplyCommands(Frame::make(1, c)), (QList<quint8>{c, 0x41}));
        QCOMPARE(acceptedReplyCommands(Frame::make(1, 0x4E, QByteArray(1, 1))), (QList<quint8>{0x4E, 0x3E}));
        QCOMPARE(acceptedReplyCommands(Frame::make(1, 0x4F, QByteArray(1, 0))), (QList<quint8>{0x4F, 0x3E}));
        QCOMPARE(acceptedReplyCommands(Frame::make(1, 0x4E, QByteArray(4, 0))), (QList<quint8>{0x4E}));
        QCOMPARE(acceptedReplyCommands(Frame::make(1, 0x70)), (QList<quint8>{0x70}));
    }

    void replyMatching()
    {
        const Frame speed = Frame::make(3, 0x36);
        QVERIFY(isReplyTo(Frame::make(3, 0x36, QByteArray(4, 1)), speed));
        QVERIFY(!isReplyTo(Frame::make(4, 0x36, QByteArray(4, 1)), speed));
        QVERIFY(!isReplyTo(Frame::make(3, 0x37, QByteArray(4, 1)), speed));
        QVERIFY(!isReplyTo(Frame::make(3, 0x36, QByteArray(2, 1)), speed));
        QVERIFY(isReplyTo(Frame::failureReply(3, 0x36, FailureChecksum), speed));
        QVERIFY(!isReplyTo(Frame::failureReply(3, 0x37, FailureChecksum), speed));

        const Frame query = Frame::make(kBroadcastZero, 0x21);
        QVERIFY(isReplyTo(Frame::make(17, 0x21), query));
        QVERIFY(isReplyTo(Frame::make(17, 0x21), Frame::make(kBroadcastAllOnes, 0x21)));

        const Frame change = Frame::make(1, 0x22, QByteArray(1, 2));
        QVERIFY(isReplyTo(Frame::make(1, 0x22, QByteArray(1, 2)), change)); // RTU text: old address
        QVERIFY(isReplyTo(Frame::make(2, 0x22, QByteArray(1, 2)), change)); // ASCII/CAN example: new one
        QVERIFY(!isReplyTo(Frame::make(3, 0x22, QByteArray(1, 2)), change));

        QVERIFY(isReplyTo(Frame::make(1, 0x41, QByteArray(5, 0)), Frame::make(1, 0x42)));
        QVERIFY(isReplyTo(Frame::make(1, 0x42, QByteArray(5, 0)), Frame::make(1, 0x42)));
        QVERIFY(isReplyTo(Frame::make(1, 0x41), Frame::make(1, 0x45)));
        QVERIFY(isReplyTo(Frame::make(1, 0x3E), Frame::make(1, 0x4E, QByteArray(1, 1))));
        QVERIFY(!isReplyTo(Frame::make(1, 0x3E), Frame::make(1, 0x4E, QByteArray(4, 1))));
    }

    void knownLayouts()
    {
        QVERIFY(isKnownLayout(0x36, 4));
        QVERIFY(isKnownLayout(0x36, 0));
        QVERIFY(!isKnownLayout(0x36, 2));
        QVERIFY(isKnownLayout(0x41, 5)); // as the reply to 0x42/0x43
        QVERIFY(isKnownLayout(0x3E, 0));
        QVERIFY(isKnownLayout(0xB6, 1));
        QVERIFY(isKnownLayout(0xF0, 1)); // failure naming an unknown command
        QVERIFY(!isKnownLayout(0xB6, 0));
        QVERIFY(!isKnownLayout(0x70, 0));
        QVERIFY(!isKnownLayout(0x3B, 3));
    }

    void addresses()
    {
        QCOMPARE(broadcastAddress(BroadcastAddress::Zero), quint8(0));
        QCOMPARE(broadcastAddress(BroadcastAddress::AllOnes), quint8(255));
        QVERIFY(isBroadcastAddress(0));
        QVERIFY(isBroadcastAddress(255));
        QVERIFY(!isBroadcastAddress(1));
        QVERIFY(!isUnicastAddress(0));
        QVERIFY(isUnicastAddress(1));
        QVERIFY(isUnicastAddress(247));
        QVERIFY(!isUnicastAddress(248));
    }

    void failureCodes()
    {
        QCOMPARE(QString::fromLatin1(failureCodeText(0x01)), QStringLiteral("Receive timeout or wrong data length"));
        QCOMPARE(QString::fromLatin1(failureCodeText(0x02)), QStringLiteral("Checksum error"));
        QCOMPARE(QString::fromLatin1(failureCodeText(0x03)), QStringLiteral("Unknown command"));
        QCOMPARE(QString::fromLatin1(failureCodeText(0x04)), QStringLiteral("Value out of range"));
        QCOMPARE(QString::fromLatin1(failureCodeText(0x05)), QStringLiteral("Command does not support broadcast"));
        QVERIFY(!failureCodeText(0x00));
        QVERIFY(!failureCodeText(0x06));
        QCOMPARE(failureDescription(0x04), QStringLiteral("Value out of range"));
        QCOMPARE(failureDescription(0x7f), QStringLiteral("unknown failure code 0x7f"));
    }

    void baudCodes()
    {
        const int rates[] = {300, 600, 1200, 2400, 4800, 9600, 19200, 38400, 57600};
        for (int code = 1; code <= 9; ++code) {
            QCOMPARE(baudRateForCode(code), rates[code - 1]);
            QCOMPARE(baudCodeForRate(rates[code - 1]), code);
            QCOMPARE(isUsableBaudCode(code), code != 9);
        }
        QCOMPARE(baudRateForCode(0), 0);
        QCOMPARE(baudRateForCode(10), 0);
        QCOMPARE(baudCodeForRate(115200), 0);
        QCOMPARE(baudCodeForRate(9600), 6);
    }

    void canBitrateCodes()
    {
        const int rates[] = {1000000, 900000, 800000, 750000, 600000, 500000, 400000, 250000, 200000,
                             150000,  125000, 100000, 80000,  50000,  25000,  20000,  10000,  5000};
        for (int code = 1; code <= 18; ++code) {
            QCOMPARE(canBitrateForCode(code), rates[code - 1]);
            QCOMPARE(canBitrateCodeFor(rates[code - 1]), code);
        }
        QCOMPARE(canBitrateForCode(kDefaultCanBitrateCode), 100000);
        QCOMPARE(canBitrateForCode(0), 0);
        QCOMPARE(canBitrateForCode(19), 0);
        QCOMPARE(canBitrateCodeFor(1234), 0);
    }
};

QTEST_APPLESS_MAIN(TestShuokeCommands)
#include "tst_shuokecommands.moc"
