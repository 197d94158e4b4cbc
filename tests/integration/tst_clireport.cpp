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
    // A restore whose read-back differed, as the journal keeps it.
    const QString dir = file("failed/drivedesk/journal");
    QVERIFY(QDir().mkpath(dir));
    QFile journal(dir + "/servo-modbus-1.json");
    QVERIFY(journal.open(QIODevice::WriteOnly));
    journal.write(R"({"format": "drivedesk-journal", "version": 1, "backups": [],
        "verification": {"kind": "restore", "when": "2026-11-25T10:00:00Z", "sourceFile": "/tmp/a.json",
        "sourceChecksum": "sha256:00", "entries": [
        {"index": 5, "key": "PA5", "requested": 10, "readBack": 11, "outcome": "mismatch", "message": "read back 11"},
        {"index": 6, "key": "PA6", "requested": 20, "readBack": 20, "outcome": "verified", "message": ""}]}})");
    journal.close();
    const CliRun r = runCli(sim() + QStringList{"--address", "1", "report", "-o", file("failed.pdf")},
                            {{"XDG_DATA_HOME", file("failed")}});
    QVERIFY2(r.exitCode == 0, r.text().toUtf8().constData());
    QVERIFY(r.text().contains("failed their last verification"));
    const QString first = text(file("failed.pdf"), 1, 1);
    QVERIFY2(first.contains("VERIFICATION FAILED"), qPrintable(first));
    QVERIFY2(QRegularExpression("1\\s+of\\s+2\\s+parameter\\(s\\)\\s+not\\s+verified").match(first).hasMatch(),
             qPrintable(first));
    QVERIFY(first.contains("FAILED (1)"));
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
