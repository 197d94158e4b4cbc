// The commissioning record (core/report): header files, the JSON and its schema, the PDF as
// a reader sees it (pdftotext), the verification journal.
#include "core/drive/drivetypes.h"
#include "core/link/trafficrecord.h"
#include "core/params/parameterdictionary.h"
#include "core/report/journalkey.h"
#include "core/report/linkhealthcounter.h"
#include "core/report/recordheader.h"
#include "core/report/recordjson.h"
#include "core/report/recordrenderer.h"
#include "core/report/recordruns.h"
#include "core/report/runplot.h"
#include "core/report/verificationjournal.h"
#include "tests/support/clirun.h"
#include "tests/support/pdftext.h"
#include "tests/support/recordfixture.h"

#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QThread>
#include <QtTest>
#include <memory>

using namespace dd;

class TestRecord : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    QString path(const QString &name) const { return m_dir.filePath(name); }
    // Writes `record` as PDF (and JSON); returns the JSON's SHA-256.
    QString write(const CommissioningRecord &record, const QString &pdf, QPageSize::PageSizeId size = QPageSize::A4,
                  QByteArray *json = nullptr)
    {
        const QByteArray bytes = RecordJson::toJson(record);
        const QString sha = RecordJson::sha256(bytes);
        RecordRenderer renderer(record, sha);
        renderer.setPageSize(size);
        const Error e = renderer.writePdf(pdf);
        if (e)
            qWarning() << e.message;
        if (json)
            *json = bytes;
        return e ? QString() : sha;
    }
    static QString text(const QString &pdf, int first = 0, int last = 0)
    {
        QString error;
        const QString t = test::pdfText(pdf, first, last, &error);
        if (t.isEmpty())
            qWarning() << error;
        return t;
    }

    static JournalKey journalKey(const QString &link, int address, const QString &firmware)
    {
        DriveIdentity id;
        id.family = Family::ServoModbus;
        id.address = address;
        id.firmware = firmware;
        return JournalKey::of(id, link, QString());
    }
    static ParameterWriteResult writeOf(int index, qint64 value)
    {
        ParameterWriteResult w;
        w.index = index;
        w.requested = w.readBack = value;
        w.readable = w.written = w.verified = true;
        w.outcome = WriteOutcome::Verified;
        return w;
    }
    static QList<ParameterWriteResult> okAndMismatch()
    {
        ParameterWriteResult ok = writeOf(5, 123);
        ParameterWriteResult bad = ok;
        bad.index = 6;
        bad.readBack = 12;
        bad.verified = false;
        bad.outcome = WriteOutcome::Mismatch;
        bad.error = QStringLiteral("read back 12");
        return {ok, bad};
    }
    static BackupReference backupRef(const QString &file)
    {
        return {QStringLiteral("backup"), file, QStringLiteral("sha256:") + QString(64, QLatin1Char('1')),
                QDateTime::currentDateTimeUtc()};
    }

    // Each file's verdict against docs/record-schema.json: "valid" or "invalid: <why>".
    static QList<QByteArray> schemaVerdicts(const QStringList &files)
    {
        const QString schema = qEnvironmentVariable("DRIVEDESK_SOURCE_DIR")
            + QStringLiteral("/docs/record-schema.json");
        if (!QFile::exists(schema))
            return {};
        QProcess python;
        python.start(QStringLiteral("python3"),
                     QStringList{QStringLiteral("-c"),
                                 QStringLiteral("import json, sys, jsonschema\n"
                                                "s = json.load(open(sys.argv[1]))\n"
                                                "jsonschema.Draft202012Validator.check_schema(s)\n"
                                                "v = jsonschema.Draft202012Validator(s)\n"
                                                "for f in sys.argv[2:]:\n"
                                                "    e = list(v.iter_errors(json.load(open(f))))\n"
                                                "    print('valid' if not e else 'invalid: ' + e[0].message)\n"),
                                 schema}
                         + files);
        if (!python.waitForFinished(30000) || python.exitCode() != 0) {
            qWarning() << python.readAllStandardError();
            return {};
        }
        return python.readAllStandardOutput().trimmed().split('\n');
    }

private slots:
    void headerFileIsRead()
    {
        RecordHeader h;
        const QByteArray json = R"({"machine": "Press 3", "customer": "ACME 客户", "site": "Hall B",
                                    "engineer": "Li Wei", "notes": "line 1\nline 2"})";
        QVERIFY(!h.loadFromJson(json, QStringLiteral("h.json")));
        QCOMPARE(h.machine, QStringLiteral("Press 3"));
        QCOMPARE(h.customer, QStringLiteral("ACME 客户"));
        QCOMPARE(h.notes, QStringLiteral("line 1\nline 2"));
        RecordHeader partial;
        QVERIFY(!partial.loadFromJson(R"({"engineer": "Zhang"})", QStringLiteral("p.json")));
        QCOMPARE(partial.engineer, QStringLiteral("Zhang"));
        QVERIFY(partial.machine.isEmpty());
    }

    void badHeaderFilesAreRefusedWithTheReason_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("reason");
        QTest::newRow("not json") << QByteArray("{machine: 1") << QStringLiteral("not valid JSON");
        QTest::newRow("array") << QByteArray("[\"Press 3\"]") << QStringLiteral("one JSON object");
        QTest::newRow("unknown field") << QByteArray(R"({"enginer": "Li"})")
                                       << QStringLiteral("unknown field \"enginer\"");
        QTest::newRow("number") << QByteArray(R"({"machine": 3})") << QStringLiteral("\"machine\" must be text");
        QTest::newRow("too long") << QByteArray("{\"site\": \"" + QByteArray(201, 'x') + "\"}")
                                  << QStringLiteral("\"site\" is 201 characters long; at most 200");
        QTest::newRow("control character")
            << QByteArray(R"({"customer": "A\u0007B"})") << QStringLiteral("control character (U+0007)");
    }

    void badHeaderFilesAreRefusedWithTheReason()
    {
        QFETCH(QByteArray, json);
        QFETCH(QString, reason);
        RecordHeader h;
        h.machine = QStringLiteral("kept");
        const Error e = h.loadFromJson(json, QStringLiteral("bad.json"));
        QVERIFY(e.isError());
        QVERIFY2(e.message.contains(reason), qPrintable(e.message));
        QVERIFY2(e.message.contains(QStringLiteral("bad.json")), qPrintable(e.message));
        QCOMPARE(h.machine, QStringLiteral("kept")); // nothing changed
    }

    void missingOrHugeHeaderFileIsRefused()
    {
        RecordHeader h;
        Error e = h.load(path(QStringLiteral("none.json")));
        QVERIFY(e.message.contains(QStringLiteral("does not exist")));
        QFile big(path(QStringLiteral("big.json")));
        QVERIFY(big.open(QIODevice::WriteOnly));
        big.write(QByteArray(RecordHeader::MaxFileSize + 1, ' '));
        big.close();
        e = h.load(big.fileName());
        QVERIFY2(e.message.contains(QStringLiteral("at most")), qPrintable(e.message));
    }

    void parametersAreComparedWithTheDictionaryDefaults()
    {
        const QByteArray dict = R"({"format": "drivedesk-dictionary", "formatVersion": 1, "family": "servo-can",
            "valueType": "int16", "parameters": [
            {"index": 0, "key": "P0", "name": {"en": "Speed gain", "zh": "速度增益"}, "description": {"en": "x", "zh": "x"}, "unit": "Hz", "min": 0, "max": 1000, "default": 100, "access": "rw"},
            {"index": 1, "key": "P1", "name": {"en": "Inertia", "zh": "惯量"}, "description": {"en": "x", "zh": "x"}, "unit": "", "min": 0, "max": 1000, "default": 5, "access": "rw"},
            {"index": 2, "key": "P2", "name": {"en": "Filter", "zh": "滤波"}, "description": {"en": "x", "zh": "x"}, "unit": "ms", "min": 0, "max": 1000, "access": "rw"}]})";
        ParameterDictionary d;
        const Error loaded = d.loadFromJson(dict, QStringLiteral("d.json"));
        QVERIFY2(!loaded, qPrintable(loaded.message));
        DriveRecord r;
        r.setParameters(d, {{0, 250}, {1, 5}, {2, 7}}, QLocale(QLocale::Chinese, QLocale::China));
        QCOMPARE(r.parameters.size(), 3);
        const QList<RecordParameter> changed = r.nonDefault();
        QCOMPARE(changed.size(), 1);
        QCOMPARE(changed.first().key, QStringLiteral("P0"));
        QCOMPARE(changed.first().name, QStringLiteral("速度增益"));
        QCOMPARE(*changed.first().value, 250);
        QCOMPARE(*changed.first().defaultValue, 100);
        QCOMPARE(r.withoutDefault(), 1); // P2: no default, not compared
    }

    void pdfShowsIdentitiesEveryChangedParameterAndTheChecksum()
    {
        const CommissioningRecord record = test::fixtureRecord(2, 60);
        const QString pdf = path(QStringLiteral("two.pdf"));
        const QString sha = write(record, pdf);
        QVERIFY(!sha.isEmpty());
        const QString t = text(pdf);
        QVERIFY(!t.isEmpty());
        QVERIFY(t.contains(QStringLiteral("Press line 3")));
        QVERIFY(t.contains(QStringLiteral("ACME Stamping")));
        QVERIFY(t.contains(QStringLiteral("Li Wei")));
        QVERIFY(t.contains(sha));
        for (const DriveRecord &d : record.drives) {
            QVERIFY(t.contains(QStringLiteral("at address %1").arg(d.address)));
            QVERIFY(t.contains(d.firmware));
            QVERIFY(t.contains(d.model));
            QVERIFY(!d.nonDefault().isEmpty());
            for (const RecordParameter &p : d.nonDefault()) {
                // index, key, name, value and default on one line of the drive's table
                const QRegularExpression row(QStringLiteral("\\b%1\\s+%2\\s+%3\\s+%4\\s+%5\\b")
                                                 .arg(p.index)
                                                 .arg(p.key, p.name)
                                                 .arg(*p.value)
                                                 .arg(*p.defaultValue));
                QVERIFY2(row.match(t).hasMatch(), qPrintable(p.key));
            }
        }
        // The alarm history, link health and backup checksums are there too.
        QVERIFY(t.contains(QStringLiteral("Overcurrent")));
        QVERIFY(t.contains(QStringLiteral("6000 request(s), 5995 answered")));
        QVERIFY(t.contains(record.drives.first().backups.first().checksum));
    }

    void everyPageIsNumberedAndLongTablesRepeatTheirHeader()
    {
        const CommissioningRecord record = test::fixtureRecord(1, 220);
        const QString pdf = path(QStringLiteral("long.pdf"));
        QVERIFY(!write(record, pdf).isEmpty());
        const QStringList texts = text(pdf).split(QLatin1Char('\f'), Qt::SkipEmptyParts); // one per page
        const int pages = int(texts.size());
        QVERIFY2(pages >= 5, qPrintable(QString::number(pages))); // summary, drive, appendix over several pages
        for (int page = 1; page <= pages; ++page)
            QVERIFY(texts.at(page - 1).contains(QStringLiteral("Page %1 of %2").arg(page).arg(pages)));
        // The appendix's last page continues the table: its header row is repeated there.
        const QString last = texts.last();
        QVERIFY2(last.contains(QStringLiteral("P219")), qPrintable(last));
        QVERIFY(!last.contains(QStringLiteral("Appendix")));
        QVERIFY2(QRegularExpression(QStringLiteral("Index\\s+Parameter\\s+Name\\s+Value\\s+Default\\s+Unit"))
                     .match(last)
                     .hasMatch(),
                 qPrintable(last));
    }

    void aFailedVerificationIsOnTheFirstPage()
    {
        const CommissioningRecord record = test::fixtureRecord(3, 40, 2);
        const QString pdf = path(QStringLiteral("failed.pdf"));
        QVERIFY(!write(record, pdf).isEmpty());
        const QString first = text(pdf, 1, 1);
        QVERIFY2(first.contains(QStringLiteral("VERIFICATION FAILED")), qPrintable(first));
        QVERIFY(first.contains(QStringLiteral("at address 2")));
        QVERIFY(first.contains(QStringLiteral("FAILED (1)")));
        QCOMPARE(first.count(QStringLiteral("VERIFICATION FAILED")), 1); // drives 1 and 3 passed
        // and the drive's own first page says so too, with the parameter
        const QString all = text(pdf);
        QVERIFY(all.contains(QStringLiteral("FAILED (mismatch)")));

        const CommissioningRecord good = test::fixtureRecord(3, 40, 0);
        QVERIFY(!write(good, pdf).isEmpty());
        QVERIFY(!text(pdf, 1, 1).contains(QStringLiteral("VERIFICATION FAILED")));
    }

    void a4AndLetter()
    {
        const CommissioningRecord record = test::fixtureRecord(1, 10);
        const QString a4 = path(QStringLiteral("a4.pdf"));
        const QString letter = path(QStringLiteral("letter.pdf"));
        QVERIFY(!write(record, a4, QPageSize::A4).isEmpty());
        QVERIFY(!write(record, letter, QPageSize::Letter).isEmpty());
        QVERIFY2(test::pdfInfo(a4).contains(QStringLiteral("(A4)")), qPrintable(test::pdfInfo(a4)));
        QVERIFY2(test::pdfInfo(letter).contains(QStringLiteral("(letter)")), qPrintable(test::pdfInfo(letter)));
        QCOMPARE(RecordRenderer::defaultPageSize(QLocale(QLocale::English, QLocale::UnitedStates)), QPageSize::Letter);
        QCOMPARE(RecordRenderer::defaultPageSize(QLocale(QLocale::Chinese, QLocale::China)), QPageSize::A4);
    }

    void chineseTextIsEmbedded()
    {
        CommissioningRecord record = test::fixtureRecord(1, 10);
        record.locale = QLocale(QLocale::Chinese, QLocale::China);
        // Characters that double as a Kangxi radical (厂, 户, 门, ...) come out of pdftotext as the
        // radical (Qt 6.4's PDF writer maps a shared glyph to its lowest code point; docs/record.md).
        record.header.customer = QStringLiteral("上海机床公司");
        record.drives[0].parameters[3].name = QStringLiteral("速度增益");
        const QString pdf = path(QStringLiteral("zh.pdf"));
        QVERIFY(!write(record, pdf).isEmpty());
        const QString t = text(pdf);
        QVERIFY2(t.contains(QStringLiteral("上海机床公司")), qPrintable(t.left(800)));
        QVERIFY(t.contains(QStringLiteral("速度增益")));
    }

    void jsonFollowsTheSchemaAndItsHashIsPrinted()
    {
        const CommissioningRecord record = test::fixtureRecord(2, 30, 1, 2);
        const QString pdf = path(QStringLiteral("j.pdf"));
        QByteArray json;
        const QString sha = write(record, pdf, QPageSize::A4, &json);
        QFile file(path(QStringLiteral("j.json")));
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(json);
        file.close();
        // Same bytes, same hash: the one the PDF prints.
        QCOMPARE(QString::fromLatin1(QCryptographicHash::hash(json, QCryptographicHash::Sha256).toHex()), sha);
        QVERIFY(text(pdf).contains(sha));
        QCOMPARE(RecordJson::toJson(record), json); // deterministic

        const QJsonObject root = QJsonDocument::fromJson(json).object();
        QCOMPARE(root.value(QStringLiteral("format")).toString(), QStringLiteral("drivedesk-record"));
        QCOMPARE(root.value(QStringLiteral("formatVersion")).toInt(), 1);
        const QJsonObject d1 = root.value(QStringLiteral("drives")).toArray().at(0).toObject();
        QCOMPARE(d1.value(QStringLiteral("verification")).toObject().value(QStringLiteral("passed")).toBool(), false);
        QCOMPARE(d1.value(QStringLiteral("runs")).toArray().size(), 1);

        // And a record that breaks the schema is caught by it (the check is real).
        QJsonObject broken = root;
        broken.insert(QStringLiteral("formatVersion"), 2);
        QFile bad(path(QStringLiteral("bad.json")));
        QVERIFY(bad.open(QIODevice::WriteOnly));
        bad.write(QJsonDocument(broken).toJson());
        bad.close();
        const QList<QByteArray> verdicts = schemaVerdicts({file.fileName(), bad.fileName()});
        QCOMPARE(verdicts.size(), 2);
        QCOMPARE(verdicts.at(0), QByteArray("valid"));
        QVERIFY2(verdicts.at(1).startsWith("invalid"), verdicts.at(1).constData());
    }

    void runFilesBecomePlotMetricsAndSnapshot()
    {
        const TuningRun run = test::fixtureRun(2);
        const QString file = path(QStringLiteral("axis2-step.ddrun"));
        QVERIFY(!run.save(file));
        RecordRunFile loaded;
        Error e = RecordRuns::load(file, &loaded);
        QVERIFY2(!e, qPrintable(e.message));
        QVERIFY(loaded.checksum.startsWith(QLatin1String("sha256:")));
        CommissioningRecord record = test::fixtureRecord(2, 80);
        e = RecordRuns::attach({loaded}, &record.drives, record.locale);
        QVERIFY2(!e, qPrintable(e.message));
        QCOMPARE(record.drives.at(0).runs.size(), 0);
        QCOMPARE(record.drives.at(1).runs.size(), 1); // the drive it was taken on
        const RunRecord &r = record.drives.at(1).runs.at(0);
        QCOMPARE(r.plot.width(), RunPlot::DefaultWidth);
        QCOMPARE(r.test, QStringLiteral("velocity-step"));

        const QString pdf = path(QStringLiteral("runs.pdf"));
        QByteArray json;
        QVERIFY(!write(record, pdf, QPageSize::A4, &json).isEmpty());
        const QString t = text(pdf);
        const double overshoot = *run.metrics.overshoot.value;
        const double rise = *run.metrics.riseTime.value * 1000.0;
        QVERIFY(overshoot > 10 && overshoot < 20);
        for (const QString &expected : {QStringLiteral("axis2-step — Velocity step"), loaded.checksum,
                                        QStringLiteral("Parameters during the run"),
                                        QStringLiteral("501 sample(s), one every 1.00 ms on average")})
            QVERIFY2(t.contains(expected), qPrintable(expected));
        QVERIFY(QRegularExpression(QStringLiteral("Overshoot\\s+%1\\s+%").arg(QString::number(overshoot, 'g', 4)))
                    .match(t)
                    .hasMatch());
        QVERIFY(
            QRegularExpression(QStringLiteral("Rise time \\(10–90 %\\)\\s+%1\\s+ms").arg(QString::number(rise, 'g', 4)))
                .match(t)
                .hasMatch());
        QVERIFY(QRegularExpression(QStringLiteral("P60\\s+Parameter 60\\s+30")).match(t).hasMatch());
        QVERIFY(QRegularExpression(QStringLiteral("P61\\s+Parameter 61\\s+25")).match(t).hasMatch());

        const QJsonObject jr = QJsonDocument::fromJson(json)
                                   .object()
                                   .value(QStringLiteral("drives"))
                                   .toArray()
                                   .at(1)
                                   .toObject()
                                   .value(QStringLiteral("runs"))
                                   .toArray()
                                   .at(0)
                                   .toObject();
        QCOMPARE(jr.value(QStringLiteral("checksum")).toString(), loaded.checksum);
        QCOMPARE(jr.value(QStringLiteral("file")).toString(), QFileInfo(file).absoluteFilePath());
        bool found = false;
        for (const QJsonValue &m : jr.value(QStringLiteral("metrics")).toArray())
            if (m.toObject().value(QStringLiteral("key")).toString() == QLatin1String("overshoot")) {
                found = true;
                QCOMPARE(m.toObject().value(QStringLiteral("value")).toDouble(), overshoot);
                QCOMPARE(m.toObject().value(QStringLiteral("unit")).toString(), QStringLiteral("%"));
            }
        QVERIFY(found);
        QFile jf(path(QStringLiteral("runs.json")));
        QVERIFY(jf.open(QIODevice::WriteOnly));
        jf.write(json);
        jf.close();
        QCOMPARE(schemaVerdicts({jf.fileName()}), QList<QByteArray>{"valid"});
    }

    void runPlotBreaksItsLineAtAGap()
    {
        TuningRun run = test::fixtureRun(1);
        // Take out 0.2 .. 0.3 s: a stretch without samples.
        CaptureData &c = run.capture;
        for (int i = int(c.time.size()) - 1; i >= 0; --i)
            if (c.time.at(i) > 0.2 && c.time.at(i) < 0.3) {
                c.time.remove(i);
                for (QVector<double> &col : c.columns)
                    col.remove(i);
            }
        c.interval = IntervalStats::of(c.time);
        const QImage plot = RunPlot::render(run, QLocale::c());
        // The speed strip (the first): x of time t, the line's blue in a column of the strip.
        auto x = [&](double t) { return int(100 + (t - c.time.first()) / (c.time.last() - c.time.first()) * 1082); };
        auto lineIn = [&](int column) {
            for (int y = 12; y < 10 + RunPlot::StripHeight - 2; ++y) {
                const QColor p = plot.pixelColor(column, y);
                if (p.blue() > 140 && p.red() < 120 && p.green() < 140)
                    return true;
            }
            return false;
        };
        QVERIFY(lineIn(x(0.15)));
        QVERIFY(lineIn(x(0.35)));
        QVERIFY(!lineIn(x(0.25))); // no ramp drawn across the gap
    }

    void badRunFilesAndRunsOfOtherDrivesAreRefused()
    {
        const QString garbage = path(QStringLiteral("garbage.ddrun"));
        QFile f(garbage);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("{\"format\": \"drivedesk-run\", \"formatVersion\": 1}");
        f.close();
        RecordRunFile loaded;
        Error e = RecordRuns::load(garbage, &loaded);
        QVERIFY(e);
        QVERIFY2(e.message.contains(QLatin1String("garbage.ddrun: created must be a string")), qPrintable(e.message));
        e = RecordRuns::load(path(QStringLiteral("missing.ddrun")), &loaded);
        QVERIFY2(e && e.message.contains(QLatin1String("missing.ddrun")), qPrintable(e.message));

        const QString other = path(QStringLiteral("axis5.ddrun"));
        QVERIFY(!test::fixtureRun(5).save(other));
        QVERIFY(!RecordRuns::load(other, &loaded));
        CommissioningRecord record = test::fixtureRecord(2, 10);
        e = RecordRuns::attach({loaded}, &record.drives, record.locale);
        QVERIFY2(e.message.contains(QLatin1String("axis5.ddrun was taken on servo-can at address 5, which is not in "
                                                  "this record (it holds servo-can at 1, servo-can at 2)")),
                 qPrintable(e.message));
        QVERIFY(record.drives.at(0).runs.isEmpty() && record.drives.at(1).runs.isEmpty());
        // One good run and the same file twice: refused, nothing attached.
        const QString good = path(QStringLiteral("axis1.ddrun"));
        QVERIFY(!test::fixtureRun(1).save(good));
        QVERIFY(!RecordRuns::load(good, &loaded));
        e = RecordRuns::attach({loaded, loaded}, &record.drives, record.locale);
        QVERIFY2(e.message.contains(QLatin1String("chosen twice")), qPrintable(e.message));
        QVERIFY(record.drives.at(0).runs.isEmpty());
    }

    void linkHealthIsCountedPerDriveFromTheTraffic()
    {
        // Serial traffic of two drives at 115200: drive 1 answers in 5 ms; drive 2's first
        // reply is dropped for a bad checksum, the retry is answered in 8 ms; a broadcast and
        // a request to drive 3 that nobody answers (still out at the end: not counted). The
        // retry went out on a line that was never quiet (SerialLink's note on it).
        LinkHealthCounter counter(nullptr, 115200);
        auto record = [&counter](qint64 ms, TrafficRecord::Direction d, QByteArray bytes, const char *note = "") {
            TrafficRecord r;
            r.timestampUs = ms * 1000;
            r.direction = d;
            r.bytes = bytes;
            r.note = QLatin1String(note);
            counter.count(r);
        };
        using D = TrafficRecord::Direction;
        record(0, D::Tx, QByteArray::fromHex("010300640001c5d5"));
        record(5, D::Rx, QByteArray::fromHex("01030200001984"));
        record(10, D::Tx, QByteArray::fromHex("020300640001c5e6"));
        record(14, D::Discarded, QByteArray::fromHex("0203020000ffff"), "bad checksum");
        record(60, D::Tx, QByteArray::fromHex("020300640001c5e6"),
               "(retry 1) (the line was not quiet for 500 ms: sent anyway)");
        record(68, D::Rx, QByteArray::fromHex("02030200001984"));
        record(70, D::Tx, QByteArray::fromHex("000600640001"));
        record(80, D::Tx, QByteArray::fromHex("030300640001"));
        counter.countError(2);

        const RecordLinkHealth one = counter.health(1, QStringLiteral("test"));
        QVERIFY(one.measured);
        QCOMPARE(one.requests, 1);
        QCOMPARE(one.answered, 1);
        QCOMPARE(one.turnaroundMedianMs, 5.0);
        QCOMPARE(one.timeouts + one.checksumErrors + one.retries + one.errors, 0);
        const RecordLinkHealth two = counter.health(2, QStringLiteral("test"));
        QCOMPARE(two.requests, 2);
        QCOMPARE(two.answered, 1);
        QCOMPARE(two.checksumErrors, 1);
        QCOMPARE(two.retries, 1);
        QCOMPARE(two.busyLineSends, 1);
        QCOMPARE(one.busyLineSends, 0);
        QCOMPARE(two.timeouts, 0);
        QCOMPARE(two.turnaroundMaxMs, 8.0);
        QCOMPARE(two.errors, 1);
        const RecordLinkHealth three = counter.health(3, QStringLiteral("test"));
        QCOMPARE(three.requests, 1);
        QCOMPARE(three.answered, 0);

        // As the record shows it.
        CommissioningRecord rec = test::fixtureRecord(1, 5);
        rec.drives[0].linkHealth = two;
        const QString pdf = path(QStringLiteral("health.pdf"));
        QByteArray json;
        QVERIFY(!write(rec, pdf, QPageSize::A4, &json).isEmpty());
        QVERIFY2(QRegularExpression(QStringLiteral("test: 2 request\\(s\\), 1 answered, turnaround 8.0 / 8.0 / 8.0 ms "
                                                   "\\(min / median / max\\); 0 timeout\\(s\\), 1 checksum error"))
                     .match(text(pdf).simplified())
                     .hasMatch(),
                 qPrintable(text(pdf)));
        QVERIFY2(text(pdf).simplified().contains(
                     QStringLiteral("1 request(s) went out on a line that was never quiet: another master on the bus")),
                 qPrintable(text(pdf)));
        const QJsonObject h = QJsonDocument::fromJson(json)
                                  .object()
                                  .value(QStringLiteral("drives"))
                                  .toArray()
                                  .at(0)
                                  .toObject()
                                  .value(QStringLiteral("linkHealth"))
                                  .toObject();
        QCOMPARE(h.value(QStringLiteral("checksumErrors")).toInt(), 1);
        QCOMPARE(h.value(QStringLiteral("busyLineSends")).toInt(), 1);
        QCOMPARE(h.value(QStringLiteral("turnaroundMs")).toObject().value(QStringLiteral("max")).toDouble(), 8.0);
    }

    void parametersWithoutDefaultsAreSaidNotCompared()
    {
        // No default at all (the bundled servo dictionaries): the record must not read as
        // "nothing changed".
        CommissioningRecord record = test::fixtureRecord(2, 12);
        for (RecordParameter &p : record.drives[0].parameters)
            p.defaultValue.reset();
        for (int i = 0; i < 4; ++i) // drive 2: some without a default
            record.drives[1].parameters[i].defaultValue.reset();
        const QString pdf = path(QStringLiteral("nodefaults.pdf"));
        QVERIFY(!write(record, pdf).isEmpty());
        const QString first = text(pdf, 1, 1).simplified();
        QVERIFY2(first.contains(QStringLiteral("0 (12 not compared)")), qPrintable(first));
        QVERIFY2(first.contains(QStringLiteral("(4 not compared)")), qPrintable(first));
        const QString drive1 = text(pdf, 2, 2).simplified();
        QVERIFY2(drive1.contains(QStringLiteral("Not compared: the dictionary gives no factory default for any of the "
                                                "12 parameter(s) read")),
                 qPrintable(drive1));
        QVERIFY(!drive1.contains(QStringLiteral("No parameter read differs")));
        const QString all = text(pdf).simplified();
        QVERIFY(all.contains(QStringLiteral("4 parameter(s) not compared: the dictionary gives no factory default")));
    }

    void journalKeepsTheLastVerificationAndBackups()
    {
        VerificationJournal journal(path(QStringLiteral("journal")));
        const JournalKey key = journalKey(QStringLiteral("/dev/ttyUSB0"), 3, QStringLiteral("7051"));
        QVERIFY(journal.read(key).verification.isEmpty());
        ParameterDictionary dict;
        QVERIFY(!dict.loadBundled(Family::ServoModbus));
        QVERIFY(!journal.recordVerification(key, VerificationJournal::fromWrites(okAndMismatch(), dict)));
        QVERIFY(!journal.recordBackup(key, backupRef(QStringLiteral("/x/a.json"))));
        QVERIFY(!journal.recordEeOperation(key, VerificationJournal::fromEe(EeOperation::Save, {})));
        Error error;
        const VerificationJournal::Entry e = journal.read(key, &error);
        QVERIFY2(!error, qPrintable(error.message));
        QCOMPARE(e.verification.kind, QStringLiteral("write"));
        QCOMPARE(e.verification.entries.size(), 2);
        QCOMPARE(e.verification.entries.at(0).key, QStringLiteral("PA5"));
        QCOMPARE(e.verification.entries.at(1).outcome, QStringLiteral("mismatch"));
        QCOMPARE(e.verification.entries.at(1).readBack, 12);
        QCOMPARE(e.verification.failedCount(), 1);
        QCOMPARE(e.backups.size(), 1);
        QCOMPARE(e.backups.first().path, QStringLiteral("/x/a.json"));
        // An EE-Set after the write keeps the write (it is noted apart).
        QCOMPARE(e.ee.operation, QStringLiteral("EE-Set"));
        QVERIFY(e.ee.ok);
        // another drive's journal is its own
        QVERIFY(
            journal.read(journalKey(QStringLiteral("/dev/ttyUSB0"), 4, QStringLiteral("7051"))).verification.isEmpty());
        JournalKey can = key;
        can.family = Family::ServoCan;
        QVERIFY(journal.read(can).backups.isEmpty());
    }

    void journalIsKeptPerDriveIdentityNotPerAddress()
    {
        // Two machines, each with a servo-modbus drive at address 1: the engineer's laptop
        // reaches them on different ports, or on the same port under different machine names.
        VerificationJournal journal(path(QStringLiteral("identity")));
        ParameterDictionary dict;
        QVERIFY(!dict.loadBundled(Family::ServoModbus));
        const JournalKey usb0 = journalKey(QStringLiteral("/dev/ttyUSB0"), 1, QStringLiteral("7051"));
        const JournalKey usb1 = journalKey(QStringLiteral("/dev/ttyUSB1"), 1, QStringLiteral("7051"));
        JournalKey press3 = usb0;
        press3.machine = QStringLiteral("Press 3");
        JournalKey otherFirmware = usb0;
        otherFirmware.firmware = QStringLiteral("7052");
        const QList<JournalKey> keys{usb0, usb1, press3, otherFirmware};
        for (int i = 0; i < keys.size(); ++i)
            QVERIFY(
                !journal.recordVerification(keys.at(i), VerificationJournal::fromWrites({writeOf(5, 100 + i)}, dict)));
        QSet<QString> files;
        for (int i = 0; i < keys.size(); ++i) {
            const VerificationJournal::Entry e = journal.read(keys.at(i));
            QCOMPARE(e.verification.entries.size(), 1);
            QCOMPARE(e.verification.entries.first().requested, qint64(100 + i)); // its own write, no other
            files << keys.at(i).fileName();
        }
        QCOMPARE(files.size(), keys.size());

        // The record says how the drive was told apart and what it cannot tell apart.
        DriveRecord record;
        journal.attach(press3, &record);
        QCOMPARE(record.verification.entries.first().requested, qint64(102));
        QVERIFY2(record.identification.contains(QStringLiteral(
                     "Identified by machine “Press 3”, servo-modbus address 1 on /dev/ttyUSB0, firmware 7051.")),
                 qPrintable(record.identification));
        QVERIFY2(record.identification.contains(QStringLiteral(
                     "This family reports no serial number: two drives with the same link, address and firmware "
                     "cannot be told apart.")),
                 qPrintable(record.identification));
        QVERIFY(record.journalError.isEmpty());
        DriveRecord unnamed;
        journal.attach(usb0, &unnamed);
        QVERIFY2(unnamed.identification.contains(QStringLiteral("No machine name was set")),
                 qPrintable(unnamed.identification));

        // A journal of the old form (family-address, before drives were told apart) is no
        // drive's: never read into a record.
        QFile legacy(journal.directory() + QStringLiteral("/servo-modbus-9.json"));
        QVERIFY(legacy.open(QIODevice::WriteOnly));
        legacy.write(R"({"format": "drivedesk-journal", "version": 1, "backups": [],
            "verification": {"kind": "write", "when": "2026-11-25T10:00:00Z", "sourceFile": "", "sourceChecksum": "",
            "entries": [{"index": 5, "key": "PA5", "requested": 60, "readBack": 60, "outcome": "verified", "message": ""}]}})");
        legacy.close();
        DriveRecord nine;
        journal.attach(journalKey(QStringLiteral("/dev/ttyUSB0"), 9, QStringLiteral("7051")), &nine);
        QVERIFY(nine.verification.isEmpty());
        QVERIFY(nine.journalError.isEmpty());

        // The record shows it (PDF and JSON, which the schema takes).
        CommissioningRecord c = test::fixtureRecord(1, 4);
        c.drives[0].identification = record.identification;
        c.drives[0].eeOperation = VerificationJournal::fromEe(EeOperation::FactoryDefaults,
                                                              {ErrorCode::Timeout, QStringLiteral("no completion")});
        c.drives[0].journalError = QStringLiteral("journal trouble");
        const QString pdf = path(QStringLiteral("identity.pdf"));
        QByteArray json;
        QVERIFY(!write(c, pdf, QPageSize::A4, &json).isEmpty());
        const QString t = text(pdf).simplified();
        QVERIFY2(t.contains(QStringLiteral("Journal identity")), qPrintable(t.left(2000)));
        QVERIFY(t.contains(QStringLiteral("cannot be told apart")));
        QVERIFY(t.contains(QStringLiteral("Last EEPROM operation: EE-dEF")));
        QVERIFY(t.contains(QStringLiteral("FAILED: no completion")));
        QVERIFY(t.contains(QStringLiteral("journal trouble")));
        QFile jf(path(QStringLiteral("identity.json")));
        QVERIFY(jf.open(QIODevice::WriteOnly));
        jf.write(json);
        jf.close();
        const QList<QByteArray> verdicts = schemaVerdicts({jf.fileName()});
        if (!verdicts.isEmpty())
            QCOMPARE(verdicts.first(), QByteArray("valid"));
    }

    void writeOnlyParametersAreNotCalledVerified()
    {
        // Issue 27: a write-only parameter (no read-back) was listed as "verified".
        ParameterDictionary dict;
        QVERIFY(!dict.loadBundled(Family::ServoModbus));
        ParameterWriteResult writeOnly = writeOf(6, 7);
        writeOnly.readable = false;
        writeOnly.verified = false;
        writeOnly.outcome = WriteOutcome::WriteOnly;
        CommissioningRecord c = test::fixtureRecord(1, 4);
        c.drives[0].verification = VerificationJournal::fromWrites({writeOf(5, 3), writeOnly}, dict);
        const QString pdf = path(QStringLiteral("writeonly.pdf"));
        QVERIFY(!write(c, pdf).isEmpty());
        const QString t = text(pdf).simplified();
        QVERIFY2(
            t.contains(QStringLiteral("1 parameter(s) written and verified, 1 written (not read back: write-only).")),
            qPrintable(t));
        QVERIFY(t.contains(QStringLiteral("written (not read back: write-only)")));
        QVERIFY(!t.contains(QStringLiteral("2 parameter(s) written and verified")));
    }

    void aDamagedJournalIsReportedAndLeftAsItIs()
    {
        VerificationJournal journal(path(QStringLiteral("damaged")));
        ParameterDictionary dict;
        QVERIFY(!dict.loadBundled(Family::ServoModbus));
        const JournalKey key = journalKey(QStringLiteral("/dev/ttyUSB0"), 2, QStringLiteral("7051"));
        QVERIFY(QDir().mkpath(journal.directory()));
        const QByteArray garbage("{\"format\": \"drivedesk-journal\", \"verif");
        QFile f(journal.path(key));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(garbage);
        f.close();
        Error error;
        QVERIFY(journal.read(key, &error).verification.isEmpty());
        QVERIFY2(error.message.contains(QStringLiteral("is damaged (not JSON at byte")), qPrintable(error.message));
        const Error written = journal.recordVerification(key, VerificationJournal::fromWrites({writeOf(5, 1)}, dict));
        QVERIFY(written);
        QVERIFY2(written.message.contains(QStringLiteral("is damaged")), qPrintable(written.message));
        QVERIFY(journal.recordBackup(key, backupRef(QStringLiteral("/x/b.json"))));
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), garbage); // changed nothing
        f.close();
        DriveRecord record;
        journal.attach(key, &record);
        QVERIFY(record.verification.isEmpty());
        QVERIFY2(record.journalError.contains(QStringLiteral("is damaged")), qPrintable(record.journalError));

        // Another drive's journal copied over this one's name is not taken for it.
        const JournalKey other = journalKey(QStringLiteral("/dev/ttyUSB1"), 2, QStringLiteral("7051"));
        QVERIFY(!journal.recordVerification(other, VerificationJournal::fromWrites({writeOf(5, 2)}, dict)));
        QVERIFY(QFile::remove(journal.path(key)));
        QVERIFY(QFile::copy(journal.path(other), journal.path(key)));
        error = {};
        QVERIFY(journal.read(key, &error).verification.isEmpty());
        QVERIFY2(error.message.contains(QStringLiteral("names another drive")), qPrintable(error.message));
    }

    void twoProcessesWritingTheJournalLoseNothing()
    {
        // The CLI (its own process: `set` on a simulated drive) and this process (backups,
        // one after another) change the same drive's journal at the same time. Every change
        // of each must survive the other's, and the file must always parse.
        if (!QFile::exists(test::cliPath()))
            QSKIP("drivedesk-cli is not built");
        const QString data = path(QStringLiteral("twowriters"));
        const QString state = path(QStringLiteral("twowriters-bench.json"));
        const QStringList sim{QStringLiteral("--sim"),
                              QStringLiteral("--family"),
                              QStringLiteral("servo-modbus"),
                              QStringLiteral("--sim-state"),
                              state,
                              QStringLiteral("--address"),
                              QStringLiteral("1")};
        const QHash<QString, QString> env{{QStringLiteral("XDG_DATA_HOME"), data}};
        test::CliRun first = test::runCli(sim + QStringList{QStringLiteral("set"), QStringLiteral("PA10=100")}, env);
        QVERIFY2(first.exitCode == 0, qPrintable(first.text()));
        VerificationJournal journal(data + QStringLiteral("/drivedesk/journal"));
        const QStringList files = QDir(journal.directory()).entryList({QStringLiteral("*.json")}, QDir::Files);
        QCOMPARE(files.size(), 1);
        QFile made(journal.directory() + QLatin1Char('/') + files.first());
        QVERIFY(made.open(QIODevice::ReadOnly));
        const JournalKey key = JournalKey::fromJson(
            QJsonDocument::fromJson(made.readAll()).object().value(QStringLiteral("drive")).toObject());
        made.close();
        QCOMPARE(key.fileName(), files.first());

        int mine = 0; // this process's backups so far: "/bN.json"
        for (int round = 1; round <= 6; ++round) {
            const qint64 value = 100 + round;
            std::unique_ptr<QProcess> cli(
                test::startCli(sim + QStringList{QStringLiteral("set"), QStringLiteral("PA10=%1").arg(value)}, env));
            bool running = true;
            while (running) {
                running = cli->state() != QProcess::NotRunning;
                Error error;
                const VerificationJournal::Entry before = journal.read(key, &error);
                QVERIFY2(!error, qPrintable(error.message));
                if (mine > 0) { // my last backup is still the newest one
                    QVERIFY(!before.backups.isEmpty());
                    QCOMPARE(before.backups.first().path, QStringLiteral("/b%1.json").arg(mine));
                }
                const Error e = journal.recordBackup(key, backupRef(QStringLiteral("/b%1.json").arg(++mine)));
                QVERIFY2(!e, qPrintable(e.message));
                QCoreApplication::processEvents();
                QThread::msleep(2); // a busy writer, not one that never lets go of the lock
            }
            const test::CliRun r = test::waitCli(cli.get());
            QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
            QVERIFY2(!r.text().contains(QStringLiteral("journal")), qPrintable(r.text()));
            const VerificationJournal::Entry after = journal.read(key);
            QCOMPARE(after.verification.entries.size(), 1);
            QCOMPARE(after.verification.entries.first().requested, value); // the CLI's write survived mine
            QCOMPARE(after.backups.first().path, QStringLiteral("/b%1.json").arg(mine)); // and mine the CLI's
            QCOMPARE(after.backups.size(), qMin(mine, VerificationJournal::MaxBackups));
        }
        QVERIFY(mine > 6);
        QVERIFY(QDir(journal.directory()).entryList({QStringLiteral("*.lock")}, QDir::Files).isEmpty());
    }
};

QTEST_MAIN(TestRecord)
#include "tst_record.moc"
