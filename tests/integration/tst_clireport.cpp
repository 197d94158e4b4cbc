// drivedesk-cli report: the commissioning record of simulated drives, read back with
// pdftotext (poppler-utils) as a customer would read it.
#include "tests/support/clirun.h"
#include "tests/support/pdftext.h"

#include <QCryptographicHash>
#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

using namespace dd::test;

class TestCliReport : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    QString file(const QString &name) const { return m_dir.filePath(name); }
    QHash<QString, QString> env() const { return {{QStringLiteral("XDG_DATA_HOME"), file(QStringLiteral("data"))}}; }
    QStringList sim() const
    {
        return {QStringLiteral("--family"), QStringLiteral("servo-modbus"), QStringLiteral("--sim-drives"),
                QStringLiteral("1,2"),      QStringLiteral("--sim-state"),  file(QStringLiteral("bench.json"))};
    }
    static QJsonObject readJson(const QString &path)
    {
        QFile f(path);
        return f.open(QIODevice::ReadOnly) ? QJsonDocument::fromJson(f.readAll()).object() : QJsonObject();
    }
    // The journal files (not their locks) under the data folder `data`.
    static QStringList journalFiles(const QString &data)
    {
        QStringList files;
        const QDir dir(data + "/drivedesk/journal");
        for (const QString &name : dir.entryList({"*.json"}, QDir::Files))
            files << dir.filePath(name);
        return files;
    }
    // The record (JSON) of the drive at `address` on the bench `state` as `machine` (empty:
    // none) knows it, with the data folder `data`.
    QJsonObject recordOf(const QString &data, const QString &state, int address, const QString &machine = QString())
    {
        QStringList args{"--family",    "servo-modbus", "--sim-drives", "1,2",
                         "--sim-state", state,          "--address",    QString::number(address)};
        if (!machine.isEmpty())
            args << "--machine" << machine;
        const QString json = file(QStringLiteral("recordof-%1.json").arg(++m_records));
        const CliRun r = runCli(args + QStringList{"report", "-o", file("recordof.pdf"), "--json-out", json},
                                {{"XDG_DATA_HOME", data}});
        if (r.exitCode != 0)
            qWarning() << r.text();
        return readJson(json).value("drives").toArray().at(0).toObject();
    }
    int m_records = 0;
    static QString text(const QString &pdf, int first = 0, int last = 0)
    {
        QString error;
        const QString t = pdfText(pdf, first, last, &error);
        if (t.isEmpty())
            qWarning() << error;
        return t;
    }

private slots:
    void recordOfEveryDriveOnTheLink();
    void chineseRecord();
    void aFailedVerificationIsOnTheFirstPage();
    void tuningRunsAreInTheRecordOfTheirDrive();
    void eachDriveKeepsItsOwnHistory();
    void everyCliWritePathIsJournaled();
    void badInputIsRefusedBeforeAnythingIsSent_data();
    void badInputIsRefusedBeforeAnythingIsSent();
};

void TestCliReport::recordOfEveryDriveOnTheLink()
{
    // 1. What the simulated drive holds at first becomes the defaults of a dictionary.
    CliRun r = runCli(
        sim() + QStringList{"--address", "2", "report", "-o", file("first.pdf"), "--json-out", file("first.json")},
        env());
    QVERIFY2(r.exitCode == 0, r.text().toUtf8().constData());
    QHash<int, qint64> start;
    for (const QJsonValue &p :
         readJson(file("first.json")).value("drives").toArray().at(0).toObject().value("parameters").toArray())
        if (p.toObject().value("value").isDouble())
            start.insert(p.toObject().value("index").toInt(), qint64(p.toObject().value("value").toDouble()));
    QVERIFY(start.size() > 20);
    QFile bundled(qEnvironmentVariable("DRIVEDESK_SOURCE_DIR") + "/resources/dictionaries/servo-modbus.json");
    QVERIFY(bundled.open(QIODevice::ReadOnly));
    QJsonObject dict = QJsonDocument::fromJson(bundled.readAll()).object();
    QJsonArray params = dict.value("parameters").toArray();
    for (int i = 0; i < params.size(); ++i) {
        QJsonObject p = params.at(i).toObject();
        const int index = p.value("index").toInt();
        if (start.contains(index))
            p.insert("default", double(start.value(index)));
        params.replace(i, p);
    }
    dict.insert("parameters", params);
    QFile dictFile(file("defaults.json"));
    QVERIFY(dictFile.open(QIODevice::WriteOnly));
    dictFile.write(QJsonDocument(dict).toJson());
    dictFile.close();

    // 2. The engineer changes a few parameters (verified writes, kept in the journal).
    r = runCli(sim() + QStringList{"--address", "2", "set", "PA10=123", "PA11=-77"}, env());
    QVERIFY2(r.exitCode == 0, r.text().toUtf8().constData());
    r = runCli(sim() + QStringList{"--address", "1", "set", "PA12=99"}, env());
    QVERIFY2(r.exitCode == 0, r.text().toUtf8().constData());

    // 3. The record of every drive on the link.
    QFile header(file("header.json"));
    QVERIFY(header.open(QIODevice::WriteOnly));
    header.write(R"({"machine": "Press line 3", "customer": "ACME", "site": "Hall B", "engineer": "Li Wei"})");
    header.close();
    // (The simulator shares the CLI's thread: probes get more than the adaptive minimum, and the
    // scan stays short.)
    r = runCli(sim()
                   + QStringList{"--timeout", "100", "--dictionary", dictFile.fileName(), "--json", "report", "--all",
                                 "--from", "1", "--to", "4", "--header", header.fileName(), "-o", file("record.pdf"),
                                 "--json-out", file("record.json")},
               env(), 60000);
    QVERIFY2(r.exitCode == 0, r.text().toUtf8().constData());
    QCOMPARE(r.json().value("drives").toArray().size(), 2);

    QFile json(file("record.json"));
    QVERIFY(json.open(QIODevice::ReadOnly));
    const QString sha = QString::fromLatin1(
        QCryptographicHash::hash(json.readAll(), QCryptographicHash::Sha256).toHex());
    QCOMPARE(r.json().value("sha256").toString(), sha);

    const QString t = text(file("record.pdf"));
    QVERIFY(t.contains(sha));
    QVERIFY(t.contains("Press line 3"));
    QVERIFY(t.contains("Li Wei"));
    const QJsonArray drives = readJson(file("record.json")).value("drives").toArray();
    for (const QJsonValue &d : drives) {
        const QJsonObject o = d.toObject();
        QVERIFY(t.contains(QStringLiteral("Servo (Modbus) at address %1").arg(o.value("address").toInt())));
        QVERIFY(!o.value("firmware").toString().isEmpty());
        QVERIFY(t.contains(o.value("firmware").toString()));
    }
    // Every parameter that differs from its default, with its value and the default.
    const QList<std::tuple<int, QString, int>> changed{{1, "PA12", 99}, {2, "PA10", 123}, {2, "PA11", -77}};
    for (const auto &[address, key, value] : changed) {
        const int index = key.mid(2).toInt();
        const QRegularExpression row(QStringLiteral("\\b%1\\s+%2\\s+Parameter %2\\s+%3\\s+%4\\b")
                                         .arg(index)
                                         .arg(key)
                                         .arg(value)
                                         .arg(start.value(index)));
        QVERIFY2(row.match(t).hasMatch(), qPrintable(key));
    }
    // (the defaults are drive 2's first values: drive 1 also differs where a drive holds its own address)
    auto changedKeys = [](const QJsonObject &drive) {
        QStringList keys;
        for (const QJsonValue &p : drive.value("parameters").toArray())
            if (p.toObject().value("differs").toBool())
                keys << p.toObject().value("key").toString();
        return keys;
    };
    QVERIFY(changedKeys(drives.at(0).toObject()).contains("PA12"));
    QCOMPARE(changedKeys(drives.at(1).toObject()), QStringList({"PA10", "PA11"}));
    QCOMPARE(drives.at(1).toObject().value("nonDefault").toInt(), 2);
    // The writes were verified, and the record says when.
    const QJsonObject v2 = drives.at(1).toObject().value("verification").toObject();
    QCOMPARE(v2.value("kind").toString(), QStringLiteral("write"));
    QCOMPARE(v2.value("passed").toBool(), true);
    QCOMPARE(v2.value("entries").toArray().size(), 2);
    QVERIFY(t.contains("2 parameter(s) written and verified."));
    // Link health of this run.
    QVERIFY(QRegularExpression("while this record was made: [1-9]\\d* request\\(s\\), [1-9]\\d* answered, turnaround")
                .match(t.simplified())
                .hasMatch());
}

void TestCliReport::chineseRecord()
{
    const CliRun r = runCli(sim() + QStringList{"--lang", "zh_CN", "--address", "1", "report", "-o", file("zh.pdf")},
                            env());
    QVERIFY2(r.exitCode == 0, r.text().toUtf8().constData());
    const QString t = text(file("zh.pdf"));
    QVERIFY2(t.contains(QStringLiteral("调试记录")), qPrintable(t.left(600))); // the title, translated
    QVERIFY(t.contains(QStringLiteral("参数 PA5")));                           // the dictionary's Chinese names
    QVERIFY(t.contains(QStringLiteral("附录")));
}

void TestCliReport::aFailedVerificationIsOnTheFirstPage()
{
    // A restore whose read-back differed, as the journal keeps it: the drive's journal (made
    // by a write, so that it is keyed by the drive) with that restore put in.
    CliRun r = runCli(sim() + QStringList{"--address", "1", "set", "PA5=10"}, {{"XDG_DATA_HOME", file("failed")}});
    QVERIFY2(r.exitCode == 0, r.text().toUtf8().constData());
    const QStringList made = journalFiles(file("failed"));
    QCOMPARE(made.size(), 1);
    QJsonObject doc = readJson(made.first());
    doc.insert("verification",
               QJsonDocument::fromJson(R"({"kind": "restore", "when": "2026-11-25T10:00:00Z",
        "sourceFile": "/tmp/a.json", "sourceChecksum": "sha256:00", "entries": [
        {"index": 5, "key": "PA5", "requested": 10, "readBack": 11, "outcome": "mismatch", "message": "read back 11"},
        {"index": 6, "key": "PA6", "requested": 20, "readBack": 20, "outcome": "verified", "message": ""}]})")
                   .object());
    QFile journal(made.first());
    QVERIFY(journal.open(QIODevice::WriteOnly));
    journal.write(QJsonDocument(doc).toJson());
    journal.close();
    r = runCli(sim() + QStringList{"--address", "1", "report", "-o", file("failed.pdf")},
               {{"XDG_DATA_HOME", file("failed")}});
    QVERIFY2(r.exitCode == 0, r.text().toUtf8().constData());
    QVERIFY(r.text().contains("failed their last verification"));
    const QString first = text(file("failed.pdf"), 1, 1);
    QVERIFY2(first.contains("VERIFICATION FAILED"), qPrintable(first));
    QVERIFY2(QRegularExpression("1\\s+of\\s+2\\s+parameter\\(s\\)\\s+not\\s+verified").match(first).hasMatch(),
             qPrintable(first));
    QVERIFY(first.contains("FAILED (1)"));
}

void TestCliReport::eachDriveKeepsItsOwnHistory()
{
    // Two machines each with a servo-modbus drive at address 1 (two simulated benches: two
    // links), and the same bench under two machine names, in one data folder.
    const QString data = file("history");
    const QHash<QString, QString> env{{"XDG_DATA_HOME", data}};
    const QString benchA = file("history-a.json");
    const QString benchB = file("history-b.json");
    auto bench = [](const QString &state, int address = 1) {
        return QStringList{"--family",    "servo-modbus", "--sim-drives", "1,2",
                           "--sim-state", state,          "--address",    QString::number(address)};
    };
    CliRun r = runCli(bench(benchA) + QStringList{"set", "PA10=111"}, env);
    QVERIFY2(r.exitCode == 0, r.text().toUtf8().constData());
    r = runCli(bench(benchB) + QStringList{"set", "PA10=222"}, env);
    QVERIFY2(r.exitCode == 0, r.text().toUtf8().constData());
    r = runCli(bench(benchA) + QStringList{"--machine", "Press 3", "set", "PA12=33"}, env);
    QVERIFY2(r.exitCode == 0, r.text().toUtf8().constData());
    QCOMPARE(journalFiles(data).size(), 3);

    auto written = [](const QJsonObject &drive) {
        QStringList w;
        for (const QJsonValue &e : drive.value("verification").toObject().value("entries").toArray())
            w << QStringLiteral("%1=%2")
                     .arg(e.toObject().value("key").toString())
                     .arg(e.toObject().value("requested").toInt());
        return w;
    };
    const QJsonObject a = recordOf(data, benchA, 1);
    QCOMPARE(written(a), QStringList{"PA10=111"});
    QVERIFY2(a.value("identification")
                 .toString()
                 .contains(QStringLiteral("servo-modbus address 1 on sim:%1, firmware ")
                               .arg(QFileInfo(benchA).absoluteFilePath())),
             qPrintable(a.value("identification").toString()));
    QVERIFY(a.value("identification").toString().contains("No machine name was set"));
    QCOMPARE(written(recordOf(data, benchB, 1)), QStringList{"PA10=222"});
    const QJsonObject press = recordOf(data, benchA, 1, "Press 3");
    QCOMPARE(written(press), QStringList{"PA12=33"});
    QVERIFY(press.value("identification").toString().contains(QStringLiteral("machine “Press 3”")));
    QVERIFY(recordOf(data, benchA, 1, "Press 4").value("verification").isNull());
    QVERIFY(recordOf(data, benchA, 2).value("verification").isNull()); // drive 2 of bench A: nothing written

    // A journal of the old form (family-address) is nobody's: left alone, never in a record.
    QFile legacy(data + "/drivedesk/journal/servo-modbus-2.json");
    QVERIFY(legacy.open(QIODevice::WriteOnly));
    legacy.write(R"({"format": "drivedesk-journal", "version": 1, "backups": [],
        "verification": {"kind": "restore", "when": "2026-11-25T08:03:01Z", "sourceFile": "mcap_edit.ddrun",
        "sourceChecksum": "sha256:00", "entries": [
        {"index": 5, "key": "PA5", "requested": 60, "readBack": 60, "outcome": "verified", "message": ""}]}})");
    legacy.close();
    r = runCli(bench(benchA, 2) + QStringList{"report", "-o", file("legacy.pdf")}, env);
    QVERIFY2(r.exitCode == 0, r.text().toUtf8().constData());
    const QString t = text(file("legacy.pdf"));
    QVERIFY(!t.contains("mcap_edit"));
    QVERIFY(t.contains("No restore or parameter write of this drive is recorded."));

    // A damaged journal is said, in the record and when writing, and left as it is.
    const QStringList before = journalFiles(data);
    QString aFile;
    for (const QString &f : before)
        if (readJson(f).value("drive").toObject().value("link").toString().endsWith("history-b.json"))
            aFile = f;
    QVERIFY(!aFile.isEmpty());
    QFile bad(aFile);
    QVERIFY(bad.open(QIODevice::WriteOnly));
    bad.write("not json");
    bad.close();
    r = runCli(bench(benchB) + QStringList{"set", "PA10=223"}, env);
    QVERIFY2(r.exitCode == 0, r.text().toUtf8().constData()); // the write itself happened
    QVERIFY2(r.text().contains("is damaged (not JSON at byte"), r.text().toUtf8().constData());
    QVERIFY(bad.open(QIODevice::ReadOnly));
    QCOMPARE(bad.readAll(), QByteArray("not json"));
    bad.close();
    const QJsonObject b = recordOf(data, benchB, 1);
    QVERIFY(b.value("verification").isNull());
    QVERIFY2(b.value("journalError").toString().contains("is damaged"), qPrintable(b.value("journalError").toString()));
}

void TestCliReport::everyCliWritePathIsJournaled()
{
    const QString data = file("paths");
    const QHash<QString, QString> env{{"XDG_DATA_HOME", data}};
    const QString state = file("paths-bench.json");
    const QStringList bench{"--family", "servo-modbus", "--sim-drives", "1,2", "--sim-state", state};
    auto one = [&](int address) { return bench + QStringList{"--address", QString::number(address)}; };
    auto verification = [&](int address) { return recordOf(data, state, address).value("verification").toObject(); };

    // set
    CliRun r = runCli(one(1) + QStringList{"set", "PA10=5"}, env);
    QVERIFY2(r.exitCode == 0, r.text().toUtf8().constData());
    QCOMPARE(verification(1).value("kind").toString(), QStringLiteral("write"));

    // backup, then restore of a changed value
    r = runCli(one(1) + QStringList{"backup", "-o", file("paths-1.json")}, env);
    QVERIFY2(r.exitCode == 0, r.text().toUtf8().constData());
    r = runCli(one(1) + QStringList{"set", "PA10=6"}, env);
    QVERIFY2(r.exitCode == 0, r.text().toUtf8().constData());
    r = runCli(one(1) + QStringList{"restore", file("paths-1.json")}, env);
    QVERIFY2(r.exitCode == 0, r.text().toUtf8().constData());
    QJsonObject v = verification(1);
    QCOMPARE(v.value("kind").toString(), QStringLiteral("restore"));
    QVERIFY(v.value("sourceFile").toString().endsWith("paths-1.json"));
    QCOMPARE(v.value("entries").toArray().at(0).toObject().value("key").toString(), QStringLiteral("PA10"));

    // apply-run: a capture's tuning snapshot written back after PA5 changed
    r = runCli(one(1) + QStringList{"capture", "speed", "--duration", "0.1", "-o", file("paths.ddrun")}, env);
    QVERIFY2(r.exitCode == 0, r.text().toUtf8().constData());
    r = runCli(one(1) + QStringList{"--json", "get", "PA5"}, env);
    QVERIFY2(r.exitCode == 0, r.text().toUtf8().constData());
    const int pa5 = r.json().value("parameters").toArray().at(0).toObject().value("value").toInt();
    r = runCli(one(1) + QStringList{"set", QStringLiteral("PA5=%1").arg(pa5 + 1)}, env);
    QVERIFY2(r.exitCode == 0, r.text().toUtf8().constData());
    r = runCli(one(1) + QStringList{"apply-run", file("paths.ddrun")}, env);
    QVERIFY2(r.exitCode == 0, r.text().toUtf8().constData());
    v = verification(1);
    QCOMPARE(v.value("kind").toString(), QStringLiteral("restore"));
    QVERIFY(v.value("sourceFile").toString().endsWith("paths.ddrun"));
    QCOMPARE(v.value("entries").toArray().size(), 1);
    QCOMPARE(v.value("entries").toArray().at(0).toObject().value("key").toString(), QStringLiteral("PA5"));
    QCOMPARE(v.value("entries").toArray().at(0).toObject().value("requested").toInt(), pa5);

    // EE operation: noted apart, the last verification stays
    r = runCli(one(1) + QStringList{"ee", "set"}, env);
    QVERIFY2(r.exitCode == 0, r.text().toUtf8().constData());
    const QJsonObject d1 = recordOf(data, state, 1);
    QCOMPARE(d1.value("eeOperation").toObject().value("operation").toString(), QStringLiteral("EE-Set"));
    QCOMPARE(d1.value("eeOperation").toObject().value("ok").toBool(), true);
    QCOMPARE(d1.value("verification").toObject().value("sourceFile").toString(), v.value("sourceFile").toString());

    // fleet restore (a backup folder of both drives)
    r = runCli(bench + QStringList{"--address", "1,2", "backup", "-o", file("paths-fleet")}, env);
    QVERIFY2(r.exitCode == 0, r.text().toUtf8().constData());
    r = runCli(one(2) + QStringList{"set", "PA11=7"}, env);
    QVERIFY2(r.exitCode == 0, r.text().toUtf8().constData());
    r = runCli(bench + QStringList{"--address", "1,2", "restore", file("paths-fleet")}, env);
    QVERIFY2(r.exitCode == 0, r.text().toUtf8().constData());
    v = verification(2);
    QCOMPARE(v.value("kind").toString(), QStringLiteral("restore"));
    QVERIFY2(v.value("sourceFile").toString().contains("paths-fleet"), qPrintable(v.value("sourceFile").toString()));
    QCOMPARE(v.value("entries").toArray().at(0).toObject().value("key").toString(), QStringLiteral("PA11"));
}

void TestCliReport::tuningRunsAreInTheRecordOfTheirDrive()
{
    // A capture of drive 2 on the simulated bench, as the engineer takes it.
    const QString run = file("axis2.ddrun");
    CliRun r = runCli(sim() + QStringList{"--address", "2", "capture", "speed,torque", "--duration", "0.2", "-o", run},
                      env());
    QVERIFY2(r.exitCode == 0, r.text().toUtf8().constData());
    QFile runFile(run);
    QVERIFY(runFile.open(QIODevice::ReadOnly));
    const QString checksum = "sha256:"
        + QCryptographicHash::hash(runFile.readAll(), QCryptographicHash::Sha256).toHex();

    r = runCli(sim()
                   + QStringList{"--timeout", "100", "report", "--all", "--from", "1", "--to", "3", "--runs", run, "-o",
                                 file("runs.pdf"), "--json-out", file("runs.json")},
               env());
    QVERIFY2(r.exitCode == 0, r.text().toUtf8().constData());
    const QJsonArray drives = readJson(file("runs.json")).value("drives").toArray();
    QCOMPARE(drives.size(), 2);
    QCOMPARE(drives.at(0).toObject().value("runs").toArray().size(), 0);
    const QJsonObject jr = drives.at(1).toObject().value("runs").toArray().at(0).toObject();
    QCOMPARE(jr.value("checksum").toString(), checksum);
    // Each drive's link health is its own (core/link's LinkHealth for its address): every
    // request to it answered on the clean simulated link, with a turnaround.
    for (const QJsonValue &d : drives) {
        const QJsonObject h = d.toObject().value("linkHealth").toObject();
        QVERIFY(h.value("measured").toBool());
        QVERIFY2(h.value("requests").toInt() >= 4, qPrintable(QJsonDocument(h).toJson()));
        QCOMPARE(h.value("answered").toInt(), h.value("requests").toInt());
        QCOMPARE(h.value("timeouts").toInt() + h.value("checksumErrors").toInt() + h.value("errors").toInt(), 0);
        QVERIFY(h.value("turnaroundMs").toObject().value("max").toDouble() > 0);
    }
    QCOMPARE(jr.value("test").toString(), QString("capture"));
    QVERIFY(jr.value("plot").isObject());
    QVERIFY(!jr.value("snapshot").toArray().isEmpty());
    const QString t = text(file("runs.pdf"));
    QVERIFY2(t.contains("Tuning runs (1)") && t.contains("axis2 — Capture") && t.contains(checksum), qPrintable(t));
    QVERIFY(t.contains("Parameters during the run"));

    // A record of drive 1 alone cannot hold drive 2's run: refused, nothing sent or written.
    r = runCli(sim() + QStringList{"--address", "1", "--trace", "report", "--runs", run, "-o", file("one.pdf")}, env());
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.text().contains("axis2.ddrun was taken on the drive at address 2; this record is of address 1"),
             r.text().toUtf8().constData());
    QCOMPARE(r.txFrames(), 0);
    QVERIFY(!QFile::exists(file("one.pdf")));
}

void TestCliReport::badInputIsRefusedBeforeAnythingIsSent_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QByteArray>("header");
    QTest::addColumn<QString>("reason");
    QTest::newRow("no -o") << QStringList{"report"} << QByteArray() << "needs the PDF file";
    QTest::newRow("not .pdf") << QStringList{"report", "-o", "OUT.txt"} << QByteArray() << "should end in .pdf";
    QTest::newRow("runs missing") << QStringList{"report", "-o", "OUT.pdf", "--runs", "no-such.ddrun"} << QByteArray()
                                  << "Cannot open the run file no-such.ddrun";
    QTest::newRow("runs bad") << QStringList{"report", "-o", "OUT.pdf", "--runs", "HEADER"}
                              << QByteArray(R"({"format": "drivedesk-run", "formatVersion": 1})")
                              << "bad-header.json: created must be a string";
    QTest::newRow("runs empty name") << QStringList{"report", "-o", "OUT.pdf", "--runs", "a.ddrun,"} << QByteArray()
                                     << "has an empty file name";
    QTest::newRow("range without --all") << QStringList{"report", "-o", "OUT.pdf", "--to", "5"} << QByteArray()
                                         << "--from and --to limit the scan of --all";
    QTest::newRow("page size") << QStringList{"report", "-o", "OUT.pdf", "--page-size", "a5"} << QByteArray()
                               << "use a4 or letter";
    QTest::newRow("header not json") << QStringList{"report", "-o", "OUT.pdf", "--header", "HEADER"}
                                     << QByteArray("machine: Press 3") << "is not valid JSON";
    QTest::newRow("header unknown field")
        << QStringList{"report", "-o", "OUT.pdf", "--header", "HEADER"}
        << QByteArray(R"({"machine": "P3", "date": "today"})") << "unknown field \"date\"";
    QTest::newRow("header number") << QStringList{"report", "-o", "OUT.pdf", "--header", "HEADER"}
                                   << QByteArray(R"({"engineer": 42})") << "\"engineer\" must be text";
}

void TestCliReport::badInputIsRefusedBeforeAnythingIsSent()
{
    QFETCH(QStringList, arguments);
    QFETCH(QByteArray, header);
    QFETCH(QString, reason);
    const QString headerPath = file("bad-header.json");
    if (!header.isEmpty()) {
        QFile f(headerPath);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(header);
    }
    const QString out = file("bad.pdf");
    for (QString &a : arguments)
        a.replace("OUT.pdf", out).replace("OUT.txt", file("bad.txt")).replace("HEADER", headerPath);
    QFile::remove(out);
    // A port that does not exist: the command must stop before opening it.
    const CliRun r = runCli(QStringList{"--port", "/dev/does-not-exist", "--trace"} + arguments, env());
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.text().contains(reason), r.text().toUtf8().constData());
    QCOMPARE(r.txFrames(), 0);
    QVERIFY(!QFile::exists(out));
}

QTEST_MAIN(TestCliReport)
#include "tst_clireport.moc"
