// CsvTrendWriter: header with units, rows in seconds, empty cells, quoting, errors.
#include "trend/csvtrendwriter.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace dd;

class TestCsvTrendWriter : public QObject
{
    Q_OBJECT

private slots:
    void headerAndRows();
    void headerOnlyWhenNoSample();
    void quoting();
    void unwritablePath();

private:
    static QByteArray read(const QString &path)
    {
        QFile f(path);
        return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    }
};

void TestCsvTrendWriter::headerAndRows()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("t.csv"));
    CsvTrendWriter w;
    QVERIFY(!w.open(path, {{QStringLiteral("speed"), QStringLiteral("Speed"), QStringLiteral("r/min"), 0},
                           {QStringLiteral("current"), QStringLiteral("Current"), QStringLiteral("A"), 2},
                           {QStringLiteral("inputs"), QStringLiteral("Inputs"), QString(), 0}}));
    QVERIFY(!w.writeRow(0.0, {{QStringLiteral("speed"), 100}, {QStringLiteral("current"), 1.234},
                              {QStringLiteral("inputs"), 5}}));
    QVERIFY(!w.writeRow(0.1, {{QStringLiteral("speed"), -3}}));
    // Rows are on disk before close (an interrupted recording keeps them).
    QCOMPARE(read(path).count('\n'), 3);
    QCOMPARE(w.rowCount(), 2);
    QVERIFY(!w.close());
    QCOMPARE(read(path), QByteArray("time [s],speed [r/min],current [A],inputs\n"
                                    "0.000000,100,1.23,5\n"
                                    "0.100000,-3,,\n"));
}

void TestCsvTrendWriter::headerOnlyWhenNoSample()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("t.csv"));
    CsvTrendWriter w;
    QVERIFY(!w.open(path, {}));
    QVERIFY(!w.setChannels({{QStringLiteral("torque"), QStringLiteral("Torque"), QStringLiteral("%"), 1}}));
    QVERIFY(!w.close());
    QCOMPARE(read(path), QByteArray("time [s],torque [%]\n"));
}

void TestCsvTrendWriter::quoting()
{
    QCOMPARE(CsvTrendWriter::quoted(QStringLiteral("plain")), QStringLiteral("plain"));
    QCOMPARE(CsvTrendWriter::quoted(QStringLiteral("a,b")), QStringLiteral("\"a,b\""));
    QCOMPARE(CsvTrendWriter::quoted(QStringLiteral("say \"hi\"")), QStringLiteral("\"say \"\"hi\"\"\""));
}

void TestCsvTrendWriter::unwritablePath()
{
    CsvTrendWriter w;
    const Error e = w.open(QStringLiteral("/nonexistent-dir/t.csv"), {});
    QCOMPARE(e.code, ErrorCode::FileError);
    QVERIFY(e.message.contains(QLatin1String("/nonexistent-dir/t.csv")));
    QCOMPARE(w.writeRow(0, {}).code, ErrorCode::FileError);
}

QTEST_GUILESS_MAIN(TestCsvTrendWriter)
#include "tst_csvtrendwriter.moc"
