// translations/drivedesk_zh_CN.ts is complete: every message has a finished, non-empty
// translation with the same placeholders as its source, and no entry is left over from
// text that is gone (vanished / obsolete). Chinese is a first-class language: a string
// that reaches the user untranslated is a bug, so the lupdate target's new entries must be
// translated before a branch is merged.
// stringsInTheSourcesAreInTheTs runs lupdate itself (on the sources the build's lupdate
// target reads, into a temporary copy of the .ts): a tr() string added to the code without
// running lupdate fails here, not only after someone remembers to run it.
#include "tests/support/requiretool.h"

#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QXmlStreamReader>
#include <QtTest>

namespace {

struct TsMessage
{
    QString context;
    QString source;
    QString type;             // the translation's type attribute: "", unfinished, vanished, obsolete
    QStringList translations; // the text, or each numerus form
    bool numerus = false;
};

QList<TsMessage> readTs(const QString &path, QString *error)
{
    QList<TsMessage> messages;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = file.errorString();
        return messages;
    }
    QXmlStreamReader xml(&file);
    QString context;
    TsMessage m;
    while (!xml.atEnd()) {
        xml.readNext();
        if (!xml.isStartElement())
            continue;
        const auto name = xml.name();
        if (name == QLatin1String("name")) {
            context = xml.readElementText();
        } else if (name == QLatin1String("message")) {
            m = TsMessage{
                context, {}, {}, {}, xml.attributes().value(QLatin1String("numerus")) == QLatin1String("yes")};
        } else if (name == QLatin1String("source")) {
            m.source = xml.readElementText();
        } else if (name == QLatin1String("translation")) {
            m.type = xml.attributes().value(QLatin1String("type")).toString();
            if (m.numerus) {
                while (xml.readNextStartElement()) {
                    if (xml.name() == QLatin1String("numerusform"))
                        m.translations << xml.readElementText();
                    else
                        xml.skipCurrentElement();
                }
            } else {
                m.translations << xml.readElementText();
            }
            messages << m;
        }
    }
    if (xml.hasError())
        *error = QStringLiteral("%1 (line %2)").arg(xml.errorString()).arg(xml.lineNumber());
    return messages;
}

QSet<QString> placeholders(const QString &text)
{
    static const QRegularExpression re(QStringLiteral("%(L?[0-9]{1,2}|n)"));
    QSet<QString> found;
    for (auto it = re.globalMatch(text); it.hasNext();)
        found.insert(it.next().captured(0));
    return found;
}

} // namespace

class TestTranslationFile : public QObject
{
    Q_OBJECT

private slots:
    void chineseIsComplete();
    void stringsInTheSourcesAreInTheTs();
};

void TestTranslationFile::chineseIsComplete()
{
    const QString path = qEnvironmentVariable("DRIVEDESK_SOURCE_DIR")
        + QStringLiteral("/translations/drivedesk_zh_CN.ts");
    QString error;
    const QList<TsMessage> messages = readTs(path, &error);
    QVERIFY2(error.isEmpty(), qPrintable(path + QStringLiteral(": ") + error));
    QVERIFY2(messages.size() > 500,
             qPrintable(QStringLiteral("%1 has only %2 messages").arg(path).arg(messages.size())));

    QStringList problems;
    for (const TsMessage &m : messages) {
        const QString where = QStringLiteral("%1 \"%2\"").arg(m.context, m.source.left(70));
        if (!m.type.isEmpty()) {
            problems << QStringLiteral("%1: %2").arg(m.type, where);
            continue;
        }
        if (m.translations.isEmpty())
            problems << QStringLiteral("no translation: %1").arg(where);
        for (const QString &t : m.translations) {
            if (t.trimmed().isEmpty() && !m.source.trimmed().isEmpty())
                problems << QStringLiteral("empty translation: %1").arg(where);
            else if (placeholders(t) != placeholders(m.source))
                problems << QStringLiteral("placeholders differ: %1 -> \"%2\"").arg(where, t.left(70));
        }
    }
    QVERIFY2(problems.isEmpty(),
             qPrintable(QStringLiteral("%1 problem(s) in %2 (run the drivedesk_ui_lupdate target, "
                                       "then translate):\n  ")
                            .arg(problems.size())
                            .arg(path)
                        + problems.join(QStringLiteral("\n  "))));
}

void TestTranslationFile::stringsInTheSourcesAreInTheTs()
{
    // Set by tests/CMakeLists.txt when the GUI (and with it the lupdate target) is built.
    const QString lupdate = qEnvironmentVariable("DRIVEDESK_LUPDATE");
    const QString project = qEnvironmentVariable("DRIVEDESK_LUPDATE_PROJECT");
    DD_REQUIRE_TOOL(!lupdate.isEmpty() && QFile::exists(lupdate), "lupdate not found (the GUI is not built)");
    // The project file Qt's CMake API writes for the lupdate target: set(lupdate_sources "a;b;...").
    QFile pf(project);
    QVERIFY2(pf.open(QIODevice::ReadOnly), qPrintable(project + QStringLiteral(": ") + pf.errorString()));
    const QString text = QString::fromUtf8(pf.readAll());
    const QRegularExpressionMatch sources = QRegularExpression(QStringLiteral("set\\(lupdate_sources \"([^\"]*)\"\\)"))
                                                .match(text);
    const QRegularExpressionMatch includes =
        QRegularExpression(QStringLiteral("set\\(lupdate_include_paths \"([^\"]*)\"\\)")).match(text);
    QVERIFY2(sources.hasMatch(), qPrintable(project));
    const QStringList files = sources.captured(1).split(QLatin1Char(';'), Qt::SkipEmptyParts);
    QVERIFY(files.size() > 100);

    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString ts = dir.filePath(QStringLiteral("drivedesk_zh_CN.ts"));
    QVERIFY(QFile::copy(
        qEnvironmentVariable("DRIVEDESK_SOURCE_DIR") + QStringLiteral("/translations/drivedesk_zh_CN.ts"), ts));
    QFile::setPermissions(ts, QFile::ReadOwner | QFile::WriteOwner);
    QFile list(dir.filePath(QStringLiteral("sources.lst")));
    QVERIFY(list.open(QIODevice::WriteOnly));
    for (const QString &i : includes.captured(1).split(QLatin1Char(';'), Qt::SkipEmptyParts))
        list.write((QStringLiteral("-I") + i + QLatin1Char('\n')).toUtf8());
    for (const QString &f : files)
        list.write((f + QLatin1Char('\n')).toUtf8());
    list.close();
    // The options of the lupdate target (ui/CMakeLists.txt).
    QProcess p;
    p.start(lupdate,
            {QStringLiteral("-locations"), QStringLiteral("none"), QStringLiteral("-no-ui-lines"),
             QStringLiteral("-no-sort"), QStringLiteral("-silent"), QLatin1Char('@') + list.fileName(),
             QStringLiteral("-ts"), ts});
    QVERIFY(p.waitForFinished(120000));
    QVERIFY2(p.exitStatus() == QProcess::NormalExit && p.exitCode() == 0, p.readAllStandardError().constData());

    QString error;
    QStringList missing;
    for (const TsMessage &m : readTs(ts, &error))
        if (!m.type.isEmpty())
            missing << QStringLiteral("%1: %2 \"%3\"").arg(m.type, m.context, m.source.left(70));
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QVERIFY2(missing.isEmpty(),
             qPrintable(QStringLiteral("%1 string(s) of the sources are not (or no longer) in the .ts: run the "
                                       "drivedesk_ui_lupdate target and translate:\n  ")
                            .arg(missing.size())
                        + missing.join(QStringLiteral("\n  "))));
}

QTEST_APPLESS_MAIN(TestTranslationFile)
#include "tst_translationfile.moc"
