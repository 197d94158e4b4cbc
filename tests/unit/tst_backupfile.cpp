#include <QtTest>

#include "core/params/backupfile.h"
#include "core/params/parameterdictionary.h"
#include "tests/support/jsonmutation.h"
#include "tests/support/testdata.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <functional>

#ifdef Q_OS_LINUX
#include <csignal>
#include <sys/resource.h>
#include <unistd.h>
#endif

using namespace dd;

namespace {

using dd::test::dataDir;

const QDateTime fixedTime(QDate(2024, 5, 1), QTime(8, 30, 0), QTimeZone::utc());

BackupFile shuokeBackup()
{
    BackupFile b;
    b.setFamily(Family::Shuoke);
    b.setAddress(3);
    b.setModel(QStringLiteral("M6505"));
    b.setCreated(fixedTime);
    b.setToolVersion(QStringLiteral("0.1.0"));
    b.setLink(QJsonObject{{"port", "COM3"}, {"baud", 9600}, {"framing", "rtu"}});
    ParameterSet v;
    v.set(0x25, 500);
    v.set(0x27, 20000);
    v.set(0x5F, 4);
    v.set(0x5C, 1, ValueSource::LastWritten);
    v.set(0x65, 200, ValueSource::LastWritten);
    v.setUnknown(0x5D); // never written: not saved
    b.setValues(v);
    return b;
}

BackupFile modbusBackup()
{
    BackupFile b;
    b.setFamily(Family::ServoModbus);
    b.setAddress(1);
    b.setFirmware(QStringLiteral("7051"));
    b.setCreated(fixedTime);
    b.setLink(QJsonObject{{"port", "/dev/ttyUSB0"}, {"baud", 19200}, {"framing", "8N1"}});
    ParameterSet v;
    for (int n = 0; n < 60; ++n)
        v.set(n, n * 10 - 100);
    v.set(51, 1);
    b.setValues(v);
    return b;
}

QByteArray bytesOf(const BackupFile &b)
{
    QByteArray out;
    const Error e = b.toJson(ParameterDictionary::bundled(*b.family()), &out);
    if (e)
        qWarning() << e.message;
    return out;
}

QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

bool writeAll(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly | QIODevice::Truncate) && f.write(bytes) == bytes.size();
}

using Mutation = test::JsonMutation;

QByteArray mutated(const QByteArray &json, const Mutation &m)
{
    QJsonObject o = QJsonDocument::fromJson(json).object();
    m(o);
    return QJsonDocument(o).toJson();
}

const auto onParameter = test::onParameterEntry;

// Recomputes the checksum, so that a mutation reaches the checks after it.
Mutation rehashed(const Mutation &m)
{
    return [m](QJsonObject &root) {
        m(root);
        ParameterSet v;
        for (const QJsonValue &e : root.value("parameters").toArray())
            v.set(e.toObject().value("index").toInt(), e.toObject().value("value").toInteger());
        root["checksum"] = BackupFile::checksum(v);
    };
}

} // namespace

Q_DECLARE_METATYPE(dd::ErrorCode)

class TestBackupFile : public QObject
{
    Q_OBJECT
private slots:
    void checksumVectors()
    {
        ParameterSet v;
        QCOMPARE(BackupFile::checksum(v),
                 QStringLiteral("sha256:e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855"));
        v.set(75, 3);
        v.set(4, 8);
        v.set(74, 1);
        v.setUnknown(100); // unknown values are not part of the file
        QCOMPARE(BackupFile::canonicalValues(v), QByteArray("4=8\n74=1\n75=3\n"));
        QCOMPARE(BackupFile::checksum(v),
                 QStringLiteral("sha256:d71bd7d1b54186c51eae0f01d1cd940b3adde69b9c000ffd4dfb33dfcc7af80b"));
        ParameterSet extremes;
        extremes.set(1, 32767);
        extremes.set(0, -32768, ValueSource::LastWritten); // the source is not hashed
        QCOMPARE(BackupFile::checksum(extremes),
                 QStringLiteral("sha256:07df9252da93f55ddfb41670847b2c63252b6c217a491f9f5544189d589c89e5"));
    }

    void fileContents()
    {
        const QJsonObject root = QJsonDocument::fromJson(bytesOf(shuokeBackup())).object();
        QCOMPARE(root.value("format").toString(), QStringLiteral("drivedesk-backup"));
        QCOMPARE(root.value("formatVersion").toInt(), 1);
        QCOMPARE(root.value("toolVersion").toString(), QStringLiteral("0.1.0"));
        QCOMPARE(root.value("created").toString(), QStringLiteral("2024-05-01T08:30:00Z"));
        QCOMPARE(root.value("family").toString(), QStringLiteral("shuoke"));
        QCOMPARE(root.value("address").toInt(), 3);
        QCOMPARE(root.value("model").toString(), QStringLiteral("M6505"));
        QCOMPARE(root.value("firmware").toString(), QString());
        QCOMPARE(root.value("link").toObject().value("baud").toInt(), 9600);
        const QJsonArray params = root.value("parameters").toArray();
        QCOMPARE(params.size(), 5); // 0x5D (unknown) left out
        const QJsonObject start = params.at(0).toObject();
        QCOMPARE(start.value("index").toInt(), 0x25);
        QCOMPARE(start.value("key").toString(), QStringLiteral("start-speed"));
        QCOMPARE(start.value("name").toString(), QStringLiteral("Start speed"));
        QCOMPARE(start.value("value").toInt(), 500);
        QCOMPARE(start.value("unit").toString(), QStringLiteral("pulse/s"));
        QCOMPARE(start.value("access").toString(), QStringLiteral("rw"));
        QVERIFY(!start.contains("lastWritten"));
        const QJsonObject encoder = params.at(2).toObject(); // ascending index: 0x25 0x27 0x5C 0x5F 0x65
        QCOMPARE(encoder.value("key").toString(), QStringLiteral("encoder-direction"));
        QCOMPARE(encoder.value("access").toString(), QStringLiteral("wo"));
        QCOMPARE(encoder.value("lastWritten").toBool(), true);
        QVERIFY(root.value("checksum").toString().startsWith("sha256:"));
    }

    void roundTripIsByteStable_data()
    {
        QTest::addColumn<int>("which");
        QTest::newRow("shuoke") << 0;
        QTest::newRow("servo-modbus") << 1;
    }
    void roundTripIsByteStable()
    {
        QFETCH(int, which);
        const BackupFile original = which == 0 ? shuokeBackup() : modbusBackup();
        QTemporaryDir dir;
        const QString path = dir.filePath("backup.json");
        Error e = original.save(path);
        QVERIFY2(!e, qPrintable(e.message));
        const QByteArray first = readAll(path);
        QCOMPARE(first, bytesOf(original));

        BackupFile loaded;
        e = loaded.load(path);
        QVERIFY2(!e, qPrintable(e.message));
        QCOMPARE(loaded.family(), original.family());
        QCOMPARE(loaded.address(), original.address());
        QCOMPARE(loaded.firmware(), original.firmware());
        QCOMPARE(loaded.model(), original.model());
        QCOMPARE(loaded.created(), fixedTime);
        QCOMPARE(loaded.toolVersion(), original.toolVersion());
        QCOMPARE(loaded.link(), original.link());

        ParameterSet expected;
        for (int index : original.values().knownIndices())
            expected.set(index, *original.values().value(index), original.values().entry(index).source);
        QCOMPARE(loaded.values(), expected);

        QVERIFY(!loaded.save(path));
        QCOMPARE(readAll(path), first);
    }

    void writeOnlyValuesComeBackAsLastWritten()
    {
        BackupFile loaded;
        QVERIFY(!loaded.loadFromJson(bytesOf(shuokeBackup()), "s.json"));
        QCOMPARE(loaded.values().entry(0x5C).source, ValueSource::LastWritten);
        QCOMPARE(loaded.values().entry(0x65).source, ValueSource::LastWritten);
        QCOMPARE(loaded.values().entry(0x25).source, ValueSource::ReadFromDrive);
        QVERIFY(!loaded.values().contains(0x5D));
    }

    void toJsonRefusesInvalidSets()
    {
        QByteArray out = "untouched";
        BackupFile noFamily;
        QCOMPARE(noFamily.toJson(ParameterDictionary::bundled(Family::ServoCan), &out).code,
                 ErrorCode::InvalidArgument);

        BackupFile b = modbusBackup();
        QCOMPARE(b.toJson(ParameterDictionary::bundled(Family::ServoCan), &out).code, ErrorCode::InvalidArgument);

        ParameterSet v = b.values();
        v.set(51, 300);
        b.setValues(v);
        const Error e = b.toJson(ParameterDictionary::bundled(Family::ServoModbus), &out);
        QCOMPARE(e.code, ErrorCode::OutOfRange);
        QVERIFY(e.message.contains("PA51"));

        v.set(51, 1);
        v.set(60, 0); // not a servo-modbus parameter
        b.setValues(v);
        QCOMPARE(b.toJson(ParameterDictionary::bundled(Family::ServoModbus), &out).code, ErrorCode::InvalidArgument);

        b = modbusBackup();
        b.setAddress(256);
        QCOMPARE(b.toJson(ParameterDictionary::bundled(Family::ServoModbus), &out).code, ErrorCode::OutOfRange);

        // Whatever load() would refuse is refused when writing, too.
        b = modbusBackup();
        b.setLink(QJsonObject{{"serial", QJsonObject{{"baud", 9600}}}});
        Error linkError = b.toJson(ParameterDictionary::bundled(Family::ServoModbus), &out);
        QCOMPARE(linkError.code, ErrorCode::InvalidArgument);
        QVERIFY2(linkError.message.contains("link.serial"), qPrintable(linkError.message));
        b = modbusBackup();
        b.setFirmware(QString(65, QLatin1Char('7')));
        QCOMPARE(b.toJson(ParameterDictionary::bundled(Family::ServoModbus), &out).code, ErrorCode::InvalidArgument);
        b = modbusBackup();
        b.setToolVersion(QString());
        QCOMPARE(b.toJson(ParameterDictionary::bundled(Family::ServoModbus), &out).code, ErrorCode::InvalidArgument);
        QCOMPARE(out, QByteArray("untouched"));
    }

    void badFiles_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<ErrorCode>("code");
        QTest::addColumn<QStringList>("fragments");
        const QByteArray good = bytesOf(modbusBackup());
        const ErrorCode M = ErrorCode::Malformed;
        QTest::newRow("truncated") << good.left(good.size() - 10) << M << QStringList{"not valid JSON", "truncated"};
        QTest::newRow("half") << good.left(good.size() / 2) << M << QStringList{"not valid JSON"};
        QTest::newRow("empty") << QByteArray() << M << QStringList{"empty or truncated"};
        QTest::newRow("not object") << QByteArray("[1, 2]") << M << QStringList{"top level"};
        QTest::newRow("tampered value") << mutated(
            good, onParameter(5, [](QJsonObject &e) { e["value"] = e["value"].toInt() + 1; }))
                                        << ErrorCode::ChecksumError << QStringList{"checksum does not match"};
        QTest::newRow("tampered index") << mutated(
            good, onParameter(5, [](QJsonObject &e) {
                e["index"] = 59;
                e["key"] = "PA59";
            })) << M << QStringList{"index 59 appears more than once"};
        QTest::newRow("removed parameter") << mutated(good, [](QJsonObject &o) {
            QJsonArray a = o["parameters"].toArray();
            a.removeAt(3);
            o["parameters"] = a;
        }) << ErrorCode::ChecksumError << QStringList{"checksum"};
        QTest::newRow("checksum upper case")
            << mutated(good, [](QJsonObject &o) { o["checksum"] = o["checksum"].toString().toUpper(); }) << M
            << QStringList{"\"checksum\"", "lower-case hex"};
        QTest::newRow("format name") << mutated(good, [](QJsonObject &o) { o["format"] = "drivedesk-dictionary"; }) << M
                                     << QStringList{"not a DriveDesk backup file"};
        QTest::newRow("format version 2") << mutated(good, [](QJsonObject &o) { o["formatVersion"] = 2; })
                                          << ErrorCode::NotSupported << QStringList{"version 2", "reads version 1"};
        QTest::newRow("format version 0") << mutated(good, [](QJsonObject &o) { o["formatVersion"] = 0; })
                                          << ErrorCode::NotSupported << QStringList{"version 0"};
        QTest::newRow("format version string") << mutated(good, [](QJsonObject &o) { o["formatVersion"] = "1"; }) << M
                                               << QStringList{"\"formatVersion\"", "integer"};
        QTest::newRow("unknown family") << mutated(good, [](QJsonObject &o) { o["family"] = "servo-ethercat"; })
                                        << ErrorCode::NotSupported << QStringList{"servo-ethercat"};
        QTest::newRow("family case") << mutated(good, [](QJsonObject &o) { o["family"] = "Servo-Modbus"; })
                                     << ErrorCode::NotSupported << QStringList{"Servo-Modbus"};
        QTest::newRow("address string") << mutated(good, [](QJsonObject &o) { o["address"] = "1"; }) << M
                                        << QStringList{"\"address\"", "integer", "string"};
        QTest::newRow("address range") << mutated(good, [](QJsonObject &o) { o["address"] = 256; }) << M
                                       << QStringList{"\"address\"", "0 to 255"};
        QTest::newRow("firmware number") << mutated(good, [](QJsonObject &o) { o["firmware"] = 7051; }) << M
                                         << QStringList{"\"firmware\"", "string"};
        QTest::newRow("created") << mutated(good, [](QJsonObject &o) { o["created"] = "01/05/2024"; }) << M
                                 << QStringList{"\"created\"", "ISO 8601"};
        QTest::newRow("tool version empty") << mutated(good, [](QJsonObject &o) { o["toolVersion"] = ""; }) << M
                                            << QStringList{"\"toolVersion\"", "empty"};
        QTest::newRow("link array") << mutated(good, [](QJsonObject &o) { o["link"] = QJsonArray(); }) << M
                                    << QStringList{"\"link\"", "object"};
        QTest::newRow("link nested") << mutated(good, [](QJsonObject &o) {
            QJsonObject l = o["link"].toObject();
            l["serial"] = QJsonObject{{"baud", 9600}};
            o["link"] = l;
        }) << M << QStringList{"link.serial", "object"};
        QTest::newRow("link null") << mutated(good, [](QJsonObject &o) {
            o["link"] = QJsonObject{{"port", QJsonValue()}};
        }) << M << QStringList{"link.port", "null"};
        QTest::newRow("parameters object") << mutated(good, [](QJsonObject &o) { o["parameters"] = QJsonObject(); })
                                           << M << QStringList{"\"parameters\"", "array"};
        QTest::newRow("unknown field") << mutated(good, [](QJsonObject &o) { o["signature"] = "x"; }) << M
                                       << QStringList{"unknown field \"signature\""};
        QTest::newRow("value string") << mutated(good, onParameter(0, [](QJsonObject &e) { e["value"] = "12"; })) << M
                                      << QStringList{"parameters[0] (PA0)", "\"value\"", "integer"};
        QTest::newRow("value fraction") << mutated(good, onParameter(0, [](QJsonObject &e) { e["value"] = 0.5; })) << M
                                        << QStringList{"(PA0)", "whole number"};
        QTest::newRow("value huge") << mutated(good, onParameter(0, [](QJsonObject &e) { e["value"] = 1e300; })) << M
                                    << QStringList{"(PA0)", "too large"};
        {
            QByteArray raw = mutated(good, onParameter(0, [](QJsonObject &e) { e["value"] = "RAW"; }));
            raw.replace("\"RAW\"", "-9007199254740993");
            QTest::newRow("value beyond -2^53") << raw << M << QStringList{"(PA0)", "too large"};
        }
        QTest::newRow("entry not object") << mutated(good, [](QJsonObject &o) {
            QJsonArray a = o["parameters"].toArray();
            a[2] = QJsonArray{2, 5};
            o["parameters"] = a;
        }) << M << QStringList{"parameters[2]", "object", "array"};
        QTest::newRow("entry missing key") << mutated(good, onParameter(1, [](QJsonObject &e) { e.remove("key"); }))
                                           << M << QStringList{"parameters[1]", "\"key\"", "missing"};
        QTest::newRow("entry missing access")
            << mutated(good, onParameter(1, [](QJsonObject &e) { e.remove("access"); })) << M
            << QStringList{"(PA1)", "\"access\"", "missing"};
        QTest::newRow("entry unknown field") << mutated(good, onParameter(1, [](QJsonObject &e) { e["scale"] = 1; }))
                                             << M << QStringList{"(PA1)", "unknown field \"scale\""};
        QTest::newRow("not in dictionary") << mutated(
            good, rehashed([](QJsonObject &o) {
                QJsonArray a = o["parameters"].toArray();
                a.append(QJsonObject{
                    {"index", 60}, {"key", "PA60"}, {"name", "x"}, {"value", 0}, {"unit", ""}, {"access", "rw"}});
                o["parameters"] = a;
            })) << M << QStringList{"(PA60)", "no parameter 60"};
        QTest::newRow("key mismatch") << mutated(good,
                                                 rehashed(onParameter(4, [](QJsonObject &e) { e["key"] = "PA5"; })))
                                      << M << QStringList{"(PA5)", "index 4 is PA4"};
        QTest::newRow("access mismatch") << mutated(
            good, rehashed(onParameter(2, [](QJsonObject &e) { e["access"] = "rw"; })))
                                         << M << QStringList{"(PA2)", "access \"rw\"", "\"ro\""};
        QTest::newRow("lastWritten on readable")
            << mutated(good, rehashed(onParameter(0, [](QJsonObject &e) { e["lastWritten"] = true; }))) << M
            << QStringList{"(PA0)", "only allowed on write-only"};
        QTest::newRow("out of range") << mutated(good,
                                                 rehashed(onParameter(51, [](QJsonObject &e) { e["value"] = 256; })))
                                      << ErrorCode::OutOfRange << QStringList{"(PA51)", "value 256", "0 to 255"};
        QTest::newRow("out of int16") << mutated(good,
                                                 rehashed(onParameter(7, [](QJsonObject &e) { e["value"] = 40000; })))
                                      << ErrorCode::OutOfRange << QStringList{"(PA7)", "-32768 to 32767"};
        const QByteArray shuoke = bytesOf(shuokeBackup());
        QTest::newRow("write-only unmarked")
            << mutated(shuoke, rehashed(onParameter(2, [](QJsonObject &e) { e.remove("lastWritten"); }))) << M
            << QStringList{"(encoder-direction)", "lastWritten"};
        QTest::newRow("write-only marked false")
            << mutated(shuoke, rehashed(onParameter(2, [](QJsonObject &e) { e["lastWritten"] = false; }))) << M
            << QStringList{"(encoder-direction)", "lastWritten"};
        QTest::newRow("lastWritten not bool")
            << mutated(shuoke, rehashed(onParameter(2, [](QJsonObject &e) { e["lastWritten"] = 1; }))) << M
            << QStringList{"\"lastWritten\"", "true or false"};
    }
    void badFiles()
    {
        QFETCH(QByteArray, json);
        QFETCH(ErrorCode, code);
        QFETCH(QStringList, fragments);
        BackupFile b = shuokeBackup();
        const Error e = b.loadFromJson(json, "bad.json");
        QCOMPARE(errorCodeName(e.code), errorCodeName(code));
        QVERIFY2(e.message.startsWith("bad.json"), qPrintable(e.message));
        for (const QString &f : fragments)
            QVERIFY2(e.message.contains(f), qPrintable(QStringLiteral("'%1' not in: %2").arg(f, e.message)));
        // Nothing changed.
        QCOMPARE(bytesOf(b), bytesOf(shuokeBackup()));
    }

    void missingFields_data()
    {
        QTest::addColumn<QString>("field");
        for (const char *f : {"format", "formatVersion", "toolVersion", "created", "family", "address", "firmware",
                              "model", "link", "parameters", "checksum"})
            QTest::newRow(f) << QString::fromLatin1(f);
    }
    void missingFields()
    {
        QFETCH(QString, field);
        const QByteArray json = mutated(bytesOf(modbusBackup()), [&](QJsonObject &o) { o.remove(field); });
        BackupFile b;
        const Error e = b.loadFromJson(json, "m.json");
        QCOMPARE(e.code, ErrorCode::Malformed);
        QVERIFY2(e.message.contains(QStringLiteral("\"%1\" is missing").arg(field)), qPrintable(e.message));
    }

    void missingEntryFields_data()
    {
        QTest::addColumn<QString>("field");
        for (const char *f : {"index", "key", "name", "value", "unit", "access"})
            QTest::newRow(f) << QString::fromLatin1(f);
    }
    void missingEntryFields()
    {
        QFETCH(QString, field);
        const QByteArray json = mutated(bytesOf(modbusBackup()),
                                        onParameter(9, [&](QJsonObject &e) { e.remove(field); }));
        BackupFile b;
        const Error e = b.loadFromJson(json, "m.json");
        QCOMPARE(e.code, ErrorCode::Malformed);
        QVERIFY2(e.message.contains("parameters[9]")
                     && e.message.contains(QStringLiteral("\"%1\" is missing").arg(field)),
                 qPrintable(e.message));
    }

    void explicitDictionary()
    {
        ParameterDictionary custom;
        QVERIFY(!custom.loadFromFile(dataDir() + "/dictionaries/good/servo-can-small.json"));
        BackupFile b;
        b.setFamily(Family::ServoCan);
        ParameterSet v;
        v.set(2, 100); // in range for the custom dictionary (-100..100)...
        b.setValues(v);
        QByteArray json;
        QVERIFY(!b.toJson(custom, &json));
        BackupFile loaded;
        QVERIFY(!loaded.loadFromJson(json, "c.json", &custom));
        // ...and the custom dictionary's key/access are what the file carries.
        QCOMPARE(loaded.values().value(2), std::optional<qint64>(100));
        // The bundled servo-can dictionary calls index 2 "P2" too but has access rw, not ro.
        const Error e = loaded.loadFromJson(json, "c.json");
        QCOMPARE(e.code, ErrorCode::Malformed);
        QVERIFY(e.message.contains("access"));
        // A dictionary of another family is refused.
        QCOMPARE(loaded.loadFromJson(json, "c.json", &ParameterDictionary::bundled(Family::Shuoke)).code,
                 ErrorCode::InvalidArgument);
    }

    void corpus()
    {
        const QDir bad(dataDir() + "/backup/bad");
        const QStringList files = bad.entryList({"*.json"}, QDir::Files);
        QVERIFY2(files.size() >= 20, qPrintable(bad.path()));
        for (const QString &name : files) {
            BackupFile b;
            const Error e = b.load(bad.filePath(name));
            QVERIFY2(errorCodeName(e.code) == name.section("--", 0, 0),
                     qPrintable(QStringLiteral("%1: %2 (%3)").arg(name, errorCodeName(e.code), e.message)));
        }
        const QDir good(dataDir() + "/backup/good");
        QVERIFY(good.entryList({"*.json"}, QDir::Files).size() >= 3);
        QTemporaryDir tmp;
        for (const QString &name : good.entryList({"*.json"}, QDir::Files)) {
            BackupFile b;
            Error e = b.load(good.filePath(name));
            QVERIFY2(!e, qPrintable(name + ": " + e.message));
            // Re-saving and reloading keeps everything.
            e = b.save(tmp.filePath(name));
            QVERIFY2(!e, qPrintable(e.message));
            BackupFile again;
            QVERIFY(!again.load(tmp.filePath(name)));
            QCOMPARE(again.values(), b.values());
            QCOMPARE(again.link(), b.link());
        }
    }

    void documentedExampleLoads()
    {
        // docs/backup-format.md shows a real file: keep it loadable and byte-identical.
        const QString doc = readAll(dataDir() + "/../../docs/backup-format.md");
        QVERIFY(!doc.isEmpty());
        const int start = doc.indexOf("```json\n") + 8;
        const int end = doc.indexOf("```", start);
        QVERIFY(start > 8 && end > start);
        const QByteArray example = doc.mid(start, end - start).toUtf8();
        BackupFile b;
        const Error e = b.loadFromJson(example, "backup-format.md");
        QVERIFY2(!e, qPrintable(e.message));
        QCOMPARE(b.values().value(37), std::optional<qint64>(500));
        QCOMPARE(b.values().entry(92).source, ValueSource::LastWritten);
        QCOMPARE(bytesOf(b), example);
    }

    void fileSizeCap()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("huge.json");
        // Valid JSON start, padded past the cap: refused before parsing.
        QByteArray big = bytesOf(modbusBackup());
        big.append(QByteArray(BackupFile::MaxFileSize, ' '));
        QVERIFY(writeAll(path, big));
        BackupFile b;
        Error e = b.load(path);
        QCOMPARE(e.code, ErrorCode::FileError);
        QVERIFY(e.message.contains("larger than"));
        e = b.load(dir.filePath("absent.json"));
        QCOMPARE(e.code, ErrorCode::FileError);
        QVERIFY(e.message.contains("absent.json"));
    }

    void saveFailsCleanly_missingDirectory()
    {
        QTemporaryDir dir;
        const Error e = shuokeBackup().save(dir.filePath("no/such/dir/b.json"));
        QCOMPARE(e.code, ErrorCode::FileError);
        QVERIFY(e.message.contains("b.json"));
    }

    void saveFailsCleanly_targetIsDirectory()
    {
        QTemporaryDir dir;
        QVERIFY(QDir(dir.path()).mkdir("taken"));
        QCOMPARE(shuokeBackup().save(dir.filePath("taken")).code, ErrorCode::FileError);
        QVERIFY(QFileInfo(dir.filePath("taken")).isDir());
    }

    void saveKeepsOldFile_unwritableDirectory()
    {
#ifdef Q_OS_UNIX
        QTemporaryDir dir;
        const QString path = dir.filePath("b.json");
        QVERIFY(!modbusBackup().save(path));
        const QByteArray old = readAll(path);
        QVERIFY(QFile::setPermissions(dir.path(), QFileDevice::ReadOwner | QFileDevice::ExeOwner));
        auto restore = qScopeGuard([&] {
            QFile::setPermissions(dir.path(), QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
        });
        {
            QFile probe(dir.filePath("probe"));
            if (probe.open(QIODevice::WriteOnly)) {
                probe.close();
                probe.remove();
                QSKIP("directory permissions do not apply to this user (root); covered by the write-failure test");
            }
        }
        const Error e = shuokeBackup().save(path);
        QCOMPARE(e.code, ErrorCode::FileError);
        QCOMPARE(readAll(path), old);
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{"b.json"});
#else
        QSKIP("POSIX permissions only");
#endif
    }

    void saveKeepsOldFile_writeFails()
    {
#ifdef Q_OS_LINUX
        // A file-size limit makes the write itself fail (EFBIG) even for root.
        QTemporaryDir dir;
        const QString path = dir.filePath("b.json");
        QVERIFY(!shuokeBackup().save(path));
        const QByteArray old = readAll(path);
        QVERIFY(old.size() > 600);

        rlimit saved{};
        QCOMPARE(getrlimit(RLIMIT_FSIZE, &saved), 0);
        const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
        rlimit tight = saved;
        tight.rlim_cur = 512;
        QCOMPARE(setrlimit(RLIMIT_FSIZE, &tight), 0);
        const Error e = modbusBackup().save(path); // several kB
        setrlimit(RLIMIT_FSIZE, &saved);
        std::signal(SIGXFSZ, oldHandler);

        QCOMPARE(e.code, ErrorCode::FileError);
        QVERIFY2(e.message.contains("unchanged"), qPrintable(e.message));
        QCOMPARE(readAll(path), old);
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{"b.json"});
        BackupFile b;
        QVERIFY(!b.load(path));
        QCOMPARE(b.family(), std::optional<Family>(Family::Shuoke));
#else
        QSKIP("uses RLIMIT_FSIZE (Linux)");
#endif
    }

    void compatibility()
    {
        BackupFile b = modbusBackup(); // firmware 7051
        QVERIFY(!b.checkCompatible(Family::ServoModbus, "7051", false));
        QVERIFY(!b.checkCompatible(Family::ServoModbus, " 7051 ", false));

        Error e = b.checkCompatible(Family::ServoCan, "7051", false);
        QCOMPARE(e.code, ErrorCode::NotSupported);
        QVERIFY(e.message.contains("servo-modbus") && e.message.contains("servo-can"));
        QCOMPARE(b.checkCompatible(Family::Shuoke, "7051", true).code, ErrorCode::NotSupported); // force does not help

        e = b.checkCompatible(Family::ServoModbus, "7062", false);
        QCOMPARE(e.code, ErrorCode::InvalidArgument);
        QVERIFY(e.message.contains("7051") && e.message.contains("7062") && e.message.contains("force"));
        QVERIFY(!b.checkCompatible(Family::ServoModbus, "7062", true));

        e = b.checkCompatible(Family::ServoModbus, "", false); // drive's firmware unknown
        QCOMPARE(e.code, ErrorCode::InvalidArgument);
        QVERIFY(e.message.contains("unknown"));
        QVERIFY(!b.checkCompatible(Family::ServoModbus, "", true));

        b.setFirmware("");
        QCOMPARE(b.checkCompatible(Family::ServoModbus, "7051", false).code, ErrorCode::InvalidArgument);
        QVERIFY(!b.checkCompatible(Family::ServoModbus, "", false)); // neither side has one (shuoke)

        BackupFile none;
        QCOMPARE(none.checkCompatible(Family::ServoCan, "", true).code, ErrorCode::InvalidArgument);
    }
};

QTEST_GUILESS_MAIN(TestBackupFile)
#include "tst_backupfile.moc"
