#include <QtTest>

#include "core/protocol/modbus/crc16.h"
#include "core/protocol/modbus/modbusrtu.h"
#include "core/protocol/servomodbus/servomodbus.h"
#include "tests/support/hex.h"

using namespace dd;
using namespace dd::servomodbus;
namespace mbrtu = dd::modbusrtu;

namespace {

using dd::test::hex;

QList<int> range(int first, int last)
{
    QList<int> out;
    for (int i = first; i <= last; ++i)
        out.append(i);
    return out;
}

QString planText(const QList<RegisterRange> &plan)
{
    QStringList parts;
    for (const auto &r : plan)
        parts << QStringLiteral("%1+%2").arg(r.start, 0, 16).arg(r.count);
    return parts.join(QLatin1Char(' '));
}

QString planText(const QList<RegisterWrite> &plan)
{
    QStringList parts;
    for (const auto &w : plan)
        parts << QStringLiteral("%1+%2").arg(w.start, 0, 16).arg(w.values.size());
    return parts.join(QLatin1Char(' '));
}

} // namespace

class TestServoModbusMap : public QObject
{
    Q_OBJECT
private slots:
    // ---- DP monitor table ----
    void monitorTable()
    {
        const QStringList expected = {"DP-SPd",  "DP-PoS", "DP-PoS.", "DP-CPo", "DP-CPo.", "DP-EPo",
                                      "DP-EPo.", "DP-trq", "DP-I",    "DP-LSP", "DP-Cnt",  "DP-Frq",
                                      "DP-CS",   "DP-Ct",  "DP-APo",  "DP-In",  "DP-oUt",  "DP-Cod",
                                      "DP-m",    "DP-Err", "DP-tL",   "DP-IA",  "DP-IC",   "DP-rES"};
        const auto &t = monitorRegisters();
        QCOMPARE(t.size(), int(MonitorRegisterCount));
        for (int i = 0; i < t.size(); ++i) {
            QCOMPARE(t[i].reg, quint16(i));
            QCOMPARE(QString::fromLatin1(t[i].mnemonic), expected[i]);
            QCOMPARE(monitorRegister(quint16(i)), &t[i]);
        }
        QCOMPARE(monitorRegister(0x18), nullptr);
        QCOMPARE(monitorRegister(0x64), nullptr);
        QCOMPARE(QString::fromLatin1(monitorRegister(0x13)->meaning), QStringLiteral("Alarm"));
        QCOMPARE(translated(monitorRegister(0x00)->meaning), QStringLiteral("Speed"));
        // Nobody documents these four: no invented meaning.
        for (quint16 r : {0x09, 0x0A, 0x12, 0x14})
            QVERIFY(qstrlen(monitorRegister(r)->meaning) == 0);
    }
    void monitorPositionPairs()
    {
        QList<std::pair<int, int>> pairs;
        for (const auto &m : monitorRegisters()) {
            if (m.highRegister >= 0)
                pairs.append({m.reg, m.highRegister});
        }
        QCOMPARE(pairs, (QList<std::pair<int, int>>{{0x01, 0x02}, {0x03, 0x04}, {0x05, 0x06}}));
    }

    // ---- PA registers ----
    void parameterRegisters()
    {
        QCOMPARE(parameterRegister(0), quint16(0x64));
        QCOMPARE(parameterRegister(51), quint16(0x97));
        QCOMPARE(parameterRegister(59), quint16(0x9F));
        QCOMPARE(parameterIndex(0x64), 0);
        QCOMPARE(parameterIndex(0x9F), 59);
        QCOMPARE(parameterIndex(0x63), -1);
        QCOMPARE(parameterIndex(0xA0), -1);
        QVERIFY(isParameterIndex(0) && isParameterIndex(59));
        QVERIFY(!isParameterIndex(-1) && !isParameterIndex(60));
    }
    void ranges()
    {
        QVERIFY(isReadableRange(0x00, 20));
        QVERIFY(isReadableRange(0x14, 4));
        QVERIFY(!isReadableRange(0x14, 5));  // past DP-rES
        QVERIFY(!isReadableRange(0x00, 24)); // more than 20
        QVERIFY(!isReadableRange(0x00, 0));
        QVERIFY(isReadableRange(0x64, 20));
        QVERIFY(isReadableRange(0x9F, 1));
        QVERIFY(!isReadableRange(0x9F, 2));
        QVERIFY(!isReadableRange(0x63, 1));
        QVERIFY(!isReadableRange(0x3A, 1));
        QVERIFY(isWritableRange(0x64, 20));
        QVERIFY(isWritableRange(0x8C, 20));
        QVERIFY(!isWritableRange(0x8D, 20));
        QVERIFY(!isWritableRange(0x00, 1)); // monitor values are read-only
        QVERIFY(!isWritableRange(0x64, 21));
    }

    // ---- the seed's frame layouts, address 5 ----
    void seedReadParameters()
    {
        const auto plan = servomodbus::planReads(range(0, 59));
        QCOMPARE(plan.size(), 3);
        QCOMPARE(mbrtu::encodeReadHoldingRequest(5, plan[0].start, plan[0].count).toHex(' '),
                 hex("05 03 00 64 00 14 05 9E").toHex(' '));
        QCOMPARE(mbrtu::encodeReadHoldingRequest(5, plan[1].start, plan[1].count).toHex(' '),
                 hex("05 03 00 78 00 14 C4 58").toHex(' '));
        QCOMPARE(mbrtu::encodeReadHoldingRequest(5, plan[2].start, plan[2].count).toHex(' '),
                 hex("05 03 00 8C 00 14 85 AA").toHex(' '));
        // Reply: byte count = 2 x registers, big-endian register values.
        QList<quint16> values(20, 0);
        values[0] = 1;
        values[1] = 0xFFFE;
        const QByteArray reply = mbrtu::encodeReadHoldingReply(5, values);
        QCOMPARE(reply.left(7).toHex(' '), hex("05 03 28 00 01 FF FE").toHex(' '));
        QCOMPARE(reply.size(), 45);
        const auto d = mbrtu::decodeReply(reply,
                                          mbrtu::decodeRequest(hex("05 03 00 64 00 14 05 9E"), 20).value.value());
        QVERIFY2(d.ok(), qPrintable(d.error));
        QCOMPARE(qint16(d.value->values[1]), qint16(-2));
    }
    void seedReadMonitor()
    {
        QList<quint16> all;
        for (const auto &m : monitorRegisters())
            all.append(m.reg);
        const auto plan = planRegisterReads(all);
        QCOMPARE(planText(plan), QStringLiteral("0+20 14+4"));
        QCOMPARE(mbrtu::encodeReadHoldingRequest(5, plan[0].start, plan[0].count).toHex(' '),
                 hex("05 03 00 00 00 14 44 41").toHex(' '));
        QCOMPARE(mbrtu::encodeReadHoldingRequest(5, plan[1].start, plan[1].count).toHex(' '),
                 hex("05 03 00 14 00 04 05 89").toHex(' '));
    }
    void seedWriteParameters()
    {
        const auto plan = servomodbus::planWrites({{0, 1}, {1, 0xFFFE}});
        QCOMPARE(plan.size(), 1);
        const QByteArray req = mbrtu::encodeWriteMultipleRequest(5, plan[0].start, plan[0].values);
        QCOMPARE(req.toHex(' '), hex("05 10 00 64 00 02 04 00 01 FF FE 70 F4").toHex(' '));
        const auto dq = mbrtu::decodeRequest(req, MaxRegistersPerRequest);
        QVERIFY(dq.ok());
        QVERIFY(validateRequest(*dq.value).isEmpty());
        const QByteArray ack = mbrtu::encodeWriteMultipleReply(5, 0x64, 2);
        QCOMPARE(ack.toHex(' '), hex("05 10 00 64 00 02 01 93").toHex(' '));
        QVERIFY(mbrtu::decodeReply(ack, *dq.value).ok());
    }
    void seedEeLegacy()
    {
        QCOMPARE(encodeEeRequest(5, EeOp::Set, EeFormat::Legacy).toHex(' '), hex("05 06 00 00 00 01 49 8E").toHex(' '));
        QCOMPARE(encodeEeRequest(1, EeOp::Defaults, EeFormat::Legacy).toHex(' '),
                 hex("01 06 00 00 00 05 49 C9").toHex(' '));
        const mbrtu::Request req = eeRequest(5, EeOp::Set, EeFormat::Legacy);
        QVERIFY(validateRequest(req).isEmpty());
        // Reply value 0: still running; == op: finished; else failed.
        auto d = mbrtu::decodeReply(hex("05 06 00 00 00 00 88 4E"), req);
        QVERIFY2(d.ok(), qPrintable(d.error));
        QCOMPARE(interpretLegacyEeReply(d.value->values[0], EeOp::Set), EeProgress::Running);
        d = mbrtu::decodeReply(hex("05 06 00 00 00 01 49 8E"), req);
        QVERIFY(d.ok());
        QCOMPARE(interpretLegacyEeReply(d.value->values[0], EeOp::Set), EeProgress::Finished);
        d = mbrtu::decodeReply(hex("05 06 00 00 00 03 C8 4F"), req);
        QVERIFY(d.ok());
        QCOMPARE(interpretLegacyEeReply(d.value->values[0], EeOp::Set), EeProgress::Failed);
        QCOMPARE(interpretLegacyEeReply(5, EeOp::Defaults), EeProgress::Finished);
        QCOMPARE(interpretLegacyEeReply(0xFFFF, EeOp::Defaults), EeProgress::Failed);
    }
    void seedEeNew()
    {
        QCOMPARE(encodeEeRequest(5, EeOp::Set, EeFormat::New).toHex(' '),
                 hex("05 10 00 3A 00 01 02 00 01 50 0A").toHex(' '));
        QCOMPARE(encodeEeRequest(1, EeOp::Defaults, EeFormat::New).toHex(' '),
                 hex("01 10 00 3A 00 01 02 00 05 63 09").toHex(' '));
        const mbrtu::Request req = eeRequest(5, EeOp::Set, EeFormat::New);
        QVERIFY(validateRequest(req).isEmpty());
        const auto d = mbrtu::decodeReply(hex("05 10 00 3A 00 01 20 40"), req);
        QVERIFY2(d.ok(), qPrintable(d.error));
        QCOMPARE(d.value->start, EeNewRegister);
        QCOMPARE(d.value->count, quint16(1));
    }
    void seedExceptionFromAddress1()
    {
        // Request to address 5; the drive answers an error with address byte 0x01.
        const mbrtu::Request read = mbrtu::decodeRequest(hex("05 03 00 64 00 14 05 9E"), 20).value.value();
        auto d = mbrtu::decodeReply(hex("01 83 04 40 F3"), read);
        QVERIFY2(d.ok(), qPrintable(d.error));
        QVERIFY(d.value->isException);
        QCOMPARE(d.value->exceptionCode, quint8(0x04));
        QCOMPARE(mbrtu::encodeExceptionReply(0x01, mbrtu::ReadHoldingRegisters, 0x04).toHex(' '),
                 hex("01 83 04 40 F3").toHex(' '));

        d = mbrtu::decodeReply(hex("01 90 04 4D C3"), eeRequest(5, EeOp::Set, EeFormat::New));
        QVERIFY(d.ok());
        QVERIFY(d.value->isException);
        d = mbrtu::decodeReply(hex("01 86 04 43 A3"), eeRequest(5, EeOp::Set, EeFormat::Legacy));
        QVERIFY(d.ok());
        QVERIFY(d.value->isException);
    }
    void driveLimitOf20()
    {
        mbrtu::DecodeError why = mbrtu::DecodeError::None;
        QVERIFY(!mbrtu::decodeRequest(mbrtu::encodeReadHoldingRequest(5, 0x64, 21), MaxRegistersPerRequest, &why).ok());
        QCOMPARE(why, mbrtu::DecodeError::CountOutOfRange);
        QVERIFY(mbrtu::decodeRequest(mbrtu::encodeReadHoldingRequest(5, 0x64, 20), MaxRegistersPerRequest).ok());
    }

    // ---- request planning ----
    void planReads_data()
    {
        QTest::addColumn<QList<int>>("indices");
        QTest::addColumn<int>("maxPerRequest");
        QTest::addColumn<QString>("plan"); // start(hex)+count ...
        QTest::newRow("PA0..PA59") << range(0, 59) << 20 << "64+20 78+20 8c+20";
        QTest::newRow("PA59..PA0 with duplicates") << (range(0, 59) + range(10, 20)) << 20 << "64+20 78+20 8c+20";
        QTest::newRow("empty") << QList<int>{} << 20 << "";
        QTest::newRow("single") << QList<int>{51} << 20 << "97+1";
        QTest::newRow("PA0..PA20") << range(0, 20) << 20 << "64+20 78+1";
        QTest::newRow("PA0..PA19") << range(0, 19) << 20 << "64+20";
        // A gap is merged only when that saves a request.
        QTest::newRow("gap saves a request") << QList<int>{0, 10} << 20 << "64+11";
        QTest::newRow("gaps save two") << QList<int>{0, 5, 25} << 20 << "64+6 7d+1";
        QTest::newRow("gap saves nothing") << (range(0, 9) + range(15, 34)) << 20 << "64+10 73+20";
        QTest::newRow("gap needed for 2 requests") << (range(0, 9) + range(11, 31)) << 20 << "64+20 78+12";
        QTest::newRow("all but PA20") << (range(0, 19) + range(21, 59)) << 20 << "64+20 79+20 8d+19";
        QTest::newRow("too far apart") << QList<int>{0, 20} << 20 << "64+1 78+1";
        QTest::newRow("invalid indices left out") << QList<int>{-1, 0, 60, 100} << 20 << "64+1";
        QTest::newRow("max 1") << QList<int>{0, 1, 2} << 1 << "64+1 65+1 66+1";
        QTest::newRow("max 0 means 1") << QList<int>{0, 1} << 0 << "64+1 65+1";
        QTest::newRow("max above the drive's 20") << range(0, 59) << 125 << "64+20 78+20 8c+20";
        QTest::newRow("max 7") << range(0, 19) << 7 << "64+7 6b+7 72+6";
    }
    void planReads()
    {
        QFETCH(QList<int>, indices);
        QFETCH(int, maxPerRequest);
        QFETCH(QString, plan);
        const auto p = servomodbus::planReads(indices, maxPerRequest);
        QCOMPARE(planText(p), plan);
        for (const auto &r : p)
            QVERIFY(isReadableRange(r.start, r.count));
    }
    void planReadsCoversEverythingWanted()
    {
        // Every wanted register is read exactly once, whatever the set.
        QRandomGenerator rng(7);
        for (int round = 0; round < 500; ++round) {
            QList<int> wanted;
            for (int i = 0; i < 60; ++i) {
                if (rng.bounded(100) < 30)
                    wanted.append(i);
            }
            const auto plan = servomodbus::planReads(wanted);
            QList<int> covered;
            for (const auto &r : plan) {
                QVERIFY(r.count >= 1 && r.count <= 20);
                for (int k = 0; k < r.count; ++k)
                    covered.append(parameterIndex(quint16(r.start + k)));
                // Chunks start and end on wanted registers.
                QVERIFY(wanted.contains(parameterIndex(r.start)));
                QVERIFY(wanted.contains(parameterIndex(quint16(r.start + r.count - 1))));
            }
            for (int w : wanted)
                QCOMPARE(covered.count(w), 1);
            // Never more requests than the wanted registers need without any gap reads, and
            // never more than a plain greedy cover.
            int runs = 0;
            for (int i = 0; i < wanted.size();) {
                int j = i;
                while (j + 1 < wanted.size() && wanted[j + 1] == wanted[j] + 1)
                    ++j;
                runs += (j - i + 1 + 19) / 20;
                i = j + 1;
            }
            QVERIFY(plan.size() <= runs);
            int greedy = 0;
            for (int i = 0; i < wanted.size(); ++greedy) {
                const int start = wanted[i];
                while (i < wanted.size() && wanted[i] < start + 20)
                    ++i;
            }
            QCOMPARE(plan.size(), greedy); // greedy is the minimum for fixed-length covers
        }
    }
    void planMonitorAndParameterReads()
    {
        QCOMPARE(planText(planRegisterReads({0x13, 0x00, 0x01, 0x02})), QStringLiteral("0+20"));
        QCOMPARE(planText(planRegisterReads({0x17, 0x64})), QStringLiteral("17+1 64+1"));
        // Registers the drive cannot read are left out (the EE register, the hole).
        QCOMPARE(planText(planRegisterReads({0x3A, 0x30, 0xA0, 0x05})), QStringLiteral("5+1"));
    }
    void planWrites_data()
    {
        QTest::addColumn<QList<int>>("indices");
        QTest::addColumn<int>("maxPerRequest");
        QTest::addColumn<QString>("plan");
        QTest::newRow("PA0..PA59") << range(0, 59) << 20 << "64+20 78+20 8c+20";
        QTest::newRow("PA0..PA24") << range(0, 24) << 20 << "64+20 78+5";
        QTest::newRow("gap is never written") << QList<int>{0, 1, 3} << 20 << "64+2 67+1";
        QTest::newRow("invalid left out") << QList<int>{-5, 59, 60} << 20 << "9f+1";
        QTest::newRow("max 2") << range(0, 4) << 2 << "64+2 66+2 68+1";
        QTest::newRow("empty") << QList<int>{} << 20 << "";
    }
    void planWrites()
    {
        QFETCH(QList<int>, indices);
        QFETCH(int, maxPerRequest);
        QFETCH(QString, plan);
        QMap<int, quint16> values;
        for (int i : indices)
            values.insert(i, quint16(1000 + i));
        const auto p = servomodbus::planWrites(values, maxPerRequest);
        QCOMPARE(planText(p), plan);
        for (const auto &w : p) {
            QVERIFY(isWritableRange(w.start, int(w.values.size())));
            for (int k = 0; k < w.values.size(); ++k)
                QCOMPARE(w.values[k], quint16(1000 + parameterIndex(quint16(w.start + k))));
        }
    }

    // ---- EE operations ----
    void eeOps()
    {
        QCOMPARE(allEeOps().size(), 5);
        const QStringList mnemonics = {"EE-Set", "EE-rd", "EE-bA", "EE-rS", "EE-dEF"};
        for (int i = 0; i < 5; ++i) {
            const EeOp op = allEeOps()[i];
            QCOMPARE(int(op), i + 1);
            QCOMPARE(QString::fromLatin1(eeOpMnemonic(op)), mnemonics[i]);
            QVERIFY(qstrlen(eeOpMeaning(op)) > 0);
            QCOMPARE(eeOpFromCode(quint16(i + 1)), std::optional<EeOp>(op));
        }
        QCOMPARE(QString::fromLatin1(eeOpMeaning(EeOp::Set)), QStringLiteral("Store parameters to EEPROM"));
        QVERIFY(!eeOpFromCode(0));
        QVERIFY(!eeOpFromCode(6));
        QVERIFY(!eeOpNeedsConfirmation(EeOp::Set));
        QVERIFY(!eeOpNeedsConfirmation(EeOp::Backup));
        QVERIFY(eeOpNeedsConfirmation(EeOp::Read));
        QVERIFY(eeOpNeedsConfirmation(EeOp::Restore));
        QVERIFY(eeOpNeedsConfirmation(EeOp::Defaults));
    }
    void eeFormatFromFirmware()
    {
        QCOMPARE(eeFormatForFirmware(0), EeFormat::Legacy);
        QCOMPARE(eeFormatForFirmware(7041), EeFormat::Legacy);
        QCOMPARE(eeFormatForFirmware(7049), EeFormat::Legacy);
        QCOMPARE(eeFormatForFirmware(7050), EeFormat::New);
        QCOMPARE(eeFormatForFirmware(7051), EeFormat::New);
        QCOMPARE(eeFormatForFirmware(7100), EeFormat::New);
        QCOMPARE(chooseEeFormat(EeFormatChoice::Auto, std::nullopt), std::optional<EeFormat>());
        QCOMPARE(chooseEeFormat(EeFormatChoice::Auto, quint16(7051)), std::optional<EeFormat>(EeFormat::New));
        QCOMPARE(chooseEeFormat(EeFormatChoice::Auto, quint16(7031)), std::optional<EeFormat>(EeFormat::Legacy));
        QCOMPARE(chooseEeFormat(EeFormatChoice::Legacy, quint16(7051)), std::optional<EeFormat>(EeFormat::Legacy));
        QCOMPARE(chooseEeFormat(EeFormatChoice::New, std::nullopt), std::optional<EeFormat>(EeFormat::New));
        for (auto c : {EeFormatChoice::Auto, EeFormatChoice::Legacy, EeFormatChoice::New})
            QCOMPARE(eeFormatChoiceFromId(eeFormatChoiceId(c)), std::optional<EeFormatChoice>(c));
        QCOMPARE(eeFormatChoiceId(EeFormatChoice::Legacy), QStringLiteral("legacy"));
        QVERIFY(!eeFormatChoiceFromId(QStringLiteral("Legacy ")));
    }

    // ---- position pairs ----
    void combinePairs_data()
    {
        QTest::addColumn<int>("rule");
        QTest::addColumn<quint16>("low");
        QTest::addColumn<quint16>("high");
        QTest::addColumn<qint64>("value");
        const int bin = int(PositionPairRule::BinaryWords);
        const int d4 = int(PositionPairRule::Decimal10000);
        const int d5 = int(PositionPairRule::Decimal100000);
        QTest::newRow("bin zero") << bin << quint16(0) << quint16(0) << qint64(0);
        QTest::newRow("bin 0x12345678") << bin << quint16(0x5678) << quint16(0x1234) << qint64(0x12345678);
        QTest::newRow("bin low above 32767") << bin << quint16(0xFFFF) << quint16(0) << qint64(65535);
        QTest::newRow("bin -1") << bin << quint16(0xFFFF) << quint16(0xFFFF) << qint64(-1);
        QTest::newRow("bin -65536") << bin << quint16(0) << quint16(0xFFFF) << qint64(-65536);
        QTest::newRow("bin int32 min") << bin << quint16(0) << quint16(0x8000) << qint64(-2147483648LL);
        QTest::newRow("bin int32 max") << bin << quint16(0xFFFF) << quint16(0x7FFF) << qint64(2147483647LL);
        QTest::newRow("dec4 123456") << d4 << quint16(3456) << quint16(12) << qint64(123456);
        QTest::newRow("dec4 -1") << d4 << quint16(9999) << quint16(0xFFFF) << qint64(-1);
        QTest::newRow("dec4 -123456") << d4 << quint16(6544) << quint16(qint16(-13)) << qint64(-123456);
        QTest::newRow("dec5 150000") << d5 << quint16(50000) << quint16(1) << qint64(150000);
        QTest::newRow("dec5 -150000") << d5 << quint16(50000) << quint16(qint16(-2)) << qint64(-150000);
    }
    void combinePairs()
    {
        QFETCH(int, rule);
        QFETCH(quint16, low);
        QFETCH(quint16, high);
        QFETCH(qint64, value);
        const auto r = PositionPairRule(rule);
        QCOMPARE(combinePositionPair(low, high, r), value);
        const auto split = splitPosition(value, r);
        QVERIFY(split.has_value());
        QCOMPARE(split->low, low);
        QCOMPARE(split->high, high);
    }
    void pairDefaultsAndLimits()
    {
        QCOMPARE(combinePositionPair(0x5678, 0x1234), qint64(0x12345678)); // default: binary words
        QVERIFY(!splitPosition(2147483648LL));
        QVERIFY(!splitPosition(-2147483649LL));
        QVERIFY(!splitPosition(70000, PositionPairRule::Decimal100000)); // low part 70000
        QVERIFY(!splitPosition(-5, PositionPairRule::Decimal100000));    // low part 99995
        QVERIFY(splitPosition(327679999, PositionPairRule::Decimal10000).has_value());
        QVERIFY(!splitPosition(327680000, PositionPairRule::Decimal10000)); // high part 32768
        for (auto r : {PositionPairRule::BinaryWords, PositionPairRule::Decimal10000, PositionPairRule::Decimal100000})
            QCOMPARE(positionPairRuleFromId(positionPairRuleId(r)), std::optional<PositionPairRule>(r));
        QCOMPARE(positionPairRuleId(PositionPairRule::BinaryWords), QStringLiteral("binary-words"));
        QVERIFY(!positionPairRuleFromId(QStringLiteral("decimal")));
    }

    // ---- validation of host requests ----
    void validate_data()
    {
        QTest::addColumn<QByteArray>("adu");
        QTest::addColumn<bool>("ok");
        auto rd = [](quint8 a, quint16 s, quint16 c) { return mbrtu::encodeReadHoldingRequest(a, s, c); };
        auto wr = [](quint16 s, int n) { return mbrtu::encodeWriteMultipleRequest(5, s, QList<quint16>(n, 1)); };
        QTest::newRow("read PA0..19") << rd(5, 0x64, 20) << true;
        QTest::newRow("read PA59") << rd(5, 0x9F, 1) << true;
        QTest::newRow("read past PA59") << rd(5, 0x9F, 2) << false;
        QTest::newRow("read 21") << rd(5, 0x64, 21) << false;
        QTest::newRow("read monitor 0x14+4") << rd(5, 0x14, 4) << true;
        QTest::newRow("read into the hole") << rd(5, 0x14, 5) << false;
        QTest::newRow("read broadcast") << rd(0, 0x64, 1) << false;
        QTest::newRow("write PA40..59") << wr(0x8C, 20) << true;
        QTest::newRow("write monitor") << wr(0x00, 1) << false;
        QTest::newRow("write PA59+1") << wr(0x9F, 2) << false;
        QTest::newRow("EE new op 5") << encodeEeRequest(5, EeOp::Defaults, EeFormat::New) << true;
        QTest::newRow("EE new op 6") << withCrc16(hex("05 10 00 3A 00 01 02 00 06")) << false;
        QTest::newRow("EE new 2 regs") << wr(0x3A, 2) << false;
        QTest::newRow("EE legacy op 1 broadcast") << encodeEeRequest(0, EeOp::Set, EeFormat::Legacy) << true;
        QTest::newRow("EE legacy op 0") << mbrtu::encodeWriteSingleRequest(5, 0, 0) << false;
        QTest::newRow("0x06 to a PA") << mbrtu::encodeWriteSingleRequest(5, 0x64, 1) << false;
    }
    void validate()
    {
        QFETCH(QByteArray, adu);
        QFETCH(bool, ok);
        const auto d = mbrtu::decodeRequest(adu);
        QVERIFY2(d.ok(), qPrintable(d.error));
        const mbrtu::Request r = *d.value;
        const QString why = validateRequest(r);
        QVERIFY2(why.isEmpty() == ok, qPrintable(why));
    }
    void validateOddRequests()
    {
        mbrtu::Request r;
        r.address = 5;
        r.function = 0x04;
        r.count = 1;
        QVERIFY(!validateRequest(r).isEmpty());
        r.function = mbrtu::WriteMultipleRegisters;
        r.start = 0x64;
        r.count = 2;
        r.values = {1};
        QVERIFY(!validateRequest(r).isEmpty());
        r.function = mbrtu::WriteSingleRegister;
        r.start = 0;
        r.values = {};
        QVERIFY(!validateRequest(r).isEmpty());
    }
};

QTEST_APPLESS_MAIN(TestServoModbusMap)
#include "tst_servomodbusmap.moc"
