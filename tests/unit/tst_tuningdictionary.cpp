#include "core/common/coreresources.h"
#include "core/params/parameterdictionary.h"
#include "sim/servocan/simservocandrive.h"
#include "sim/servomodbus/simservomodbusdrive.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

using namespace dd;

namespace {
QJsonObject simulatorJson(Family family)
{
    QFile f(ParameterDictionary::simulatorResourcePath(family));
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QJsonDocument::fromJson(f.readAll()).object();
}

QByteArray toBytes(const QJsonObject &o)
{
    return QJsonDocument(o).toJson(QJsonDocument::Compact);
}

QJsonObject entry(const QString &key, const QString &role)
{
    return {{QStringLiteral("key"), key}, {QStringLiteral("role"), role}};
}
} // namespace

// The dictionaries' "tuning" group, and the simulator's loop gains it names.
class TestTuningDictionary : public QObject
{
    Q_OBJECT

    static void checkAgainstSimulator(Family family, const QList<LoopGainParameter> &table)
    {
        const ParameterDictionary &d = ParameterDictionary::bundledSimulator(family);
        QCOMPARE(d.tuning().size(), table.size());
        for (const LoopGainParameter &g : table) {
            const QString role = LoopGainParameter::roleId(g.role);
            QCOMPARE(d.indexOfRole(role), g.index);
            QCOMPARE(d.roleOf(g.index), role);
            const ParameterInfo *p = d.byIndex(g.index);
            QVERIFY(p);
            QCOMPARE(p->min, g.min);
            QCOMPARE(p->max, g.max);
            QCOMPARE(p->defaultValue.value_or(-1), g.defaultValue);
            QCOMPARE(p->unit, LoopGainParameter::unit(g.role));
            QVERIFY(p->displayName(QLocale(QLocale::English)).contains(QLatin1String("simulator")));
        }
    }

private slots:
    void simulatorDictionariesNameTheSimulatorsGains()
    {
        checkAgainstSimulator(Family::ServoCan, SimServoCanDrive::loopGainParameters());
        checkAgainstSimulator(Family::ServoModbus, SimServoModbusDrive::loopGainParameters());
        // The simulated drives start on the defaults the dictionaries give.
        const auto can = SimServoCanDrive::defaultParameters(1);
        for (const LoopGainParameter &g : SimServoCanDrive::loopGainParameters())
            QCOMPARE(qint64(can[size_t(g.index)]), g.defaultValue);
    }

    void familyDictionariesClaimNoGains()
    {
        // The seeds name no gain parameter: the dictionaries used with real drives say nothing.
        for (Family f : allFamilies())
            QVERIFY(ParameterDictionary::bundled(f).tuning().isEmpty());
        // The shuoke simulator is an open-loop stepper: no simulator dictionary, no gains.
        QVERIFY(ParameterDictionary::simulatorResourcePath(Family::Shuoke).isEmpty());
        QVERIFY(ParameterDictionary::bundledSimulator(Family::Shuoke).tuning().isEmpty());
    }

    void badTuningGroupsRefused_data()
    {
        QTest::addColumn<QJsonValue>("group");
        QTest::addColumn<QStringList>("words");
        QTest::newRow("not an array") << QJsonValue(QStringLiteral("P60")) << QStringList{"tuning", "array"};
        QTest::newRow("entry not an object") << QJsonValue(QJsonArray{1}) << QStringList{"tuning[0]", "object"};
        QTest::newRow("unknown key") << QJsonValue(QJsonArray{entry("P999", "speed-kp")})
                                     << QStringList{"tuning[0]", "P999"};
        QTest::newRow("unknown role") << QJsonValue(QJsonArray{entry("P60", "speed-gain")})
                                      << QStringList{"tuning[0]", "speed-gain", "speed-kp"};
        QTest::newRow("role twice") << QJsonValue(QJsonArray{entry("P60", "speed-kp"), entry("P61", "speed-kp")})
                                    << QStringList{"tuning[1]", "speed-kp", "tuning[0]"};
        QTest::newRow("parameter twice") << QJsonValue(QJsonArray{entry("P60", "speed-kp"), entry("p60", "speed-ki")})
                                         << QStringList{"tuning[1]", "P60", "tuning[0]"};
        QJsonObject extra = entry("P60", "speed-kp");
        extra.insert(QStringLiteral("scale"), 2);
        QTest::newRow("unknown field") << QJsonValue(QJsonArray{extra}) << QStringList{"tuning[0]", "scale"};
        QTest::newRow("no role") << QJsonValue(QJsonArray{QJsonObject{{"key", "P60"}}})
                                 << QStringList{"tuning[0]", "role"};
    }

    void badTuningGroupsRefused()
    {
        QFETCH(QJsonValue, group);
        QFETCH(QStringList, words);
        QJsonObject root = simulatorJson(Family::ServoCan);
        QVERIFY(!root.isEmpty());
        root.insert(QStringLiteral("tuning"), group);
        ParameterDictionary d;
        QVERIFY(!d.loadFromJson(toBytes(simulatorJson(Family::ServoCan)), QStringLiteral("good.json")));
        const Error e = d.loadFromJson(toBytes(root), QStringLiteral("bad.json"));
        QVERIFY(e.isError());
        for (const QString &w : words)
            QVERIFY2(e.message.contains(w, Qt::CaseInsensitive), qPrintable(e.message + " / " + w));
        QCOMPARE(d.tuning().size(), 6); // a failed load leaves the dictionary as it was
    }

    void writeOnlyParameterCannotTune()
    {
        QFile f(ParameterDictionary::resourcePath(Family::Shuoke));
        QVERIFY(f.open(QIODevice::ReadOnly));
        QJsonObject root = QJsonDocument::fromJson(f.readAll()).object();
        QString writeOnlyKey;
        for (const QJsonValue &v : root.value(QStringLiteral("parameters")).toArray())
            if (v.toObject().value(QStringLiteral("access")).toString() == QLatin1String("wo"))
                writeOnlyKey = v.toObject().value(QStringLiteral("key")).toString();
        QVERIFY(!writeOnlyKey.isEmpty());
        root.insert(QStringLiteral("tuning"), QJsonArray{entry(writeOnlyKey, "acceleration")});
        ParameterDictionary d;
        const Error e = d.loadFromJson(toBytes(root), QStringLiteral("wo.json"));
        QVERIFY(e.isError());
        QVERIFY2(e.message.contains(QLatin1String("write-only")), qPrintable(e.message));
    }
};

QTEST_GUILESS_MAIN(TestTuningDictionary)
#include "tst_tuningdictionary.moc"
