// The family table is the one source of what a front end knows of a family: for every
// family in it, the GUI's connect dialog, the CLI and the simulator offer exactly the
// family's traits (link kinds, framings, address ranges, scan bauds, defaults).
#include "cli/clicommand.h"
#include "cli/clicommands.h"
#include "cli/cliglobals.h"
#include "cli/cliparser.h"
#include "cli/scancommand.h"
#include "core/protocol/familytraits.h"
#include "core/protocol/framedescriber.h"
#include "sim/bench/simbenchoptions.h"
#include "sim/bench/simfamilies.h"
#include "ui/bus/connectdialog.h"
#include "ui/bus/connectrequest.h"
#include "ui/common/displaytext.h"
#include "ui/panels/motion/motionpanel.h"

#include <QComboBox>
#include <QProcess>
#include <QSpinBox>
#include <QTest>

using namespace dd;

namespace {

QString linkArgument(LinkKind link)
{
    return link == LinkKind::Can ? QStringLiteral("virtualcan:can0") : QStringLiteral("/dev/ttyDD0");
}

// The CLI's global options (and a scan command) for one family on one link.
struct CliSetup
{
    CliContext context;
    QString error;
    bool ok = false;
};

void loadCli(CliSetup *setup, const QString &family, LinkKind link, const QStringList &extra)
{
    QStringList args{QStringLiteral("--family"), family,
                     link == LinkKind::Can ? QStringLiteral("--can") : QStringLiteral("--port"), linkArgument(link)};
    args += extra;
    CliParser parser(CliGlobals::optionSpecs(), CliCommands::specs());
    CliInvocation inv;
    if (!parser.parse(args, &inv, &setup->error))
        return;
    setup->ok = setup->context.globals.load(inv, &setup->error);
}

} // namespace

class TestFamilyTraits : public QObject
{
    Q_OBJECT

private slots:
    void tableIsComplete()
    {
        // Every family id has an entry in each table, and each entry is consistent.
        QCOMPARE(allFamilyTraits().size(), allFamilies().size());
        for (const FamilyTraits *t : allFamilyTraits()) {
            QVERIFY2(!t->framings.isEmpty(), qPrintable(t->id()));
            QVERIFY(familyFromId(t->id()) == t->family);
            QCOMPARE(&familyTraits(t->family), t);
            QCOMPARE(t->talks(LinkKind::Serial), t->defaultBaud > 0);
            QCOMPARE(t->talks(LinkKind::Serial), !t->scanBauds.isEmpty());
            QCOMPARE(t->talks(LinkKind::Can), t->defaultBitrate > 0);
            QVERIFY(t->describer != nullptr);
            QVERIFY(createFrameDescriber(t->family) != nullptr);
            const SimFamily &sim = simFamily(t->family);
            QCOMPARE(sim.family, t->family);
            QCOMPARE(sim.serial != nullptr, t->talks(LinkKind::Serial));
            QCOMPARE(sim.can != nullptr, t->talks(LinkKind::Can));
            QVERIFY(t->maxSpeed > 0 && t->jogSpeed > 0 && t->jogSpeed <= t->maxSpeed);
        }
    }

    void guiOffersTheTraits_data()
    {
        QTest::addColumn<int>("family");
        QTest::addColumn<int>("link");
        for (const FamilyTraits *t : allFamilyTraits())
            for (LinkKind link : {LinkKind::Serial, LinkKind::Can})
                if (t->talks(link))
                    QTest::addRow("%s %s", qPrintable(t->id()), link == LinkKind::Can ? "can" : "serial")
                        << int(t->family) << int(link);
    }

    void guiOffersTheTraits()
    {
        QFETCH(int, family);
        QFETCH(int, link);
        const FamilyTraits &t = familyTraits(Family(family));
        const LinkKind kind = LinkKind(link);
        ConnectRequest r;
        r.detect = false;
        r.settings.family = t.family;
        (kind == LinkKind::Can ? r.settings.can : r.settings.port) = linkArgument(kind);
        r.sweepBauds = true;
        ConnectDialog dialog;
        dialog.setRequest(r);

        // The framings offered are the family's on this link; a family with one framing has
        // nothing to choose.
        auto *framing = dialog.findChild<QComboBox *>(QStringLiteral("framingCombo"));
        QVERIFY(framing);
        QStringList offered;
        for (int i = 0; i < framing->count(); ++i)
            offered << framing->itemData(i).toString();
        QCOMPARE(offered, t.framingIds(kind));
        QCOMPARE(framing->isEnabled(), t.framings.size() > 1);

        // The scan's address range is bounded by the family's.
        const QList<QSpinBox *> spins = dialog.findChildren<QSpinBox *>();
        QSpinBox *from = nullptr;
        QSpinBox *to = nullptr;
        for (QSpinBox *s : spins) {
            if (s->objectName() == QLatin1String("probeTimeout"))
                continue;
            (from ? to : from) = s;
        }
        QVERIFY(from && to);
        QCOMPARE(from->minimum(), t.addresses(kind).first);
        QCOMPARE(to->maximum(), t.addresses(kind).last);

        // What the dialog asks for scans with the family's bauds and range.
        const ConnectRequest back = dialog.request();
        const QList<ConnectionSettings> attempts = back.attempts();
        QCOMPARE(attempts.size(), 1);
        const ScanOptions scan = back.scanOptionsFor(attempts.first());
        QCOMPARE(scan.bauds, kind == LinkKind::Serial ? t.scanBauds : QList<int>());
        QVERIFY(scan.from >= t.addresses(kind).first);
        QVERIFY(scan.to <= t.addresses(kind).last);

        QCOMPARE(DisplayText::familyName(t.family), t.displayName());
        QCOMPARE(MotionPanel::speedRange(t.family).maximum, t.maxSpeed);
    }

    void detectTriesTheTableInOrder()
    {
        for (LinkKind kind : {LinkKind::Serial, LinkKind::Can}) {
            ConnectRequest r;
            r.detect = true;
            (kind == LinkKind::Can ? r.settings.can : r.settings.port) = linkArgument(kind);
            QList<QPair<Family, QString>> expected;
            for (const FamilyTraits *t : allFamilyTraits())
                for (const FramingTraits &f : t->framings)
                    if (f.link == kind && f.detect)
                        expected.append({t->family, t->framings.size() > 1 ? f.id : QString()});
            QList<QPair<Family, QString>> got;
            for (const ConnectionSettings &s : r.attempts())
                got.append({s.family, s.framing});
            QCOMPARE(got, expected);
        }
    }

    void cliOffersTheTraits_data() { guiOffersTheTraits_data(); }

    void cliOffersTheTraits()
    {
        QFETCH(int, family);
        QFETCH(int, link);
        const FamilyTraits &t = familyTraits(Family(family));
        const LinkKind kind = LinkKind(link);
        for (const FramingTraits &f : t.framings) {
            if (f.link != kind)
                continue;
            const QStringList framing{QStringLiteral("--framing"), f.id};
            // --address: exactly the framing's range.
            for (int address : {f.addresses.first, f.addresses.last}) {
                CliSetup ok;
                loadCli(
                    &ok, t.id(), kind,
                    framing
                        + QStringList{QStringLiteral("--address"), QString::number(address), QStringLiteral("info")});
                QVERIFY2(ok.ok, qPrintable(ok.error));
                QCOMPARE(ok.context.globals.address, address);
            }
            for (int address : {f.addresses.first - 1, f.addresses.last + 1}) {
                CliSetup bad;
                loadCli(
                    &bad, t.id(), kind,
                    framing
                        + QStringList{QStringLiteral("--address"), QString::number(address), QStringLiteral("info")});
                QVERIFY2(!bad.ok, qPrintable(QStringLiteral("%1 accepted").arg(address)));
                QVERIFY2(bad.error.contains(QLatin1String("--address")), qPrintable(bad.error));
            }
            // scan: the framing's range and the family's baud sweep.
            CliSetup s;
            loadCli(&s, t.id(), kind, framing + QStringList{QStringLiteral("scan")});
            QVERIFY2(s.ok, qPrintable(s.error));
            ScanCommand scan(&s.context);
            CliInvocation inv;
            QString error;
            QVERIFY2(scan.prepare(inv, &error), qPrintable(error));
            QCOMPARE(scan.options().from, f.addresses.first);
            QCOMPARE(scan.options().to, f.addresses.last);
            QCOMPARE(scan.options().bauds, kind == LinkKind::Serial ? t.scanBauds : QList<int>());
        }
        // A framing the family does not have, or a link it does not talk, is refused.
        for (const QString &other : allFramingIds()) {
            if (t.framing(other))
                continue;
            CliSetup bad;
            loadCli(&bad, t.id(), kind, {QStringLiteral("--framing"), other, QStringLiteral("info")});
            QVERIFY2(!bad.ok, qPrintable(other));
        }
        const LinkKind otherLink = kind == LinkKind::Can ? LinkKind::Serial : LinkKind::Can;
        if (!t.talks(otherLink)) {
            CliSetup bad;
            loadCli(&bad, t.id(), otherLink, {QStringLiteral("info")});
            QVERIFY(!bad.ok);
            QVERIFY2(bad.error.contains(t.id()), qPrintable(bad.error));
        }
    }

    void simulatorOffersTheTraits_data() { guiOffersTheTraits_data(); }

    void simulatorOffersTheTraits()
    {
        QFETCH(int, family);
        QFETCH(int, link);
        const FamilyTraits &t = familyTraits(Family(family));
        const LinkKind kind = LinkKind(link);
        QCOMPARE(SimBenchOptions::defaultBaud(t.family), t.defaultBaud);
        QCOMPARE(SimBenchOptions::defaultBitrate(t.family), t.defaultBitrate);
        // drivedesk-sim refuses an address outside the family's range on that link, before
        // it opens anything.
        const QString sim = qEnvironmentVariable("DRIVEDESK_BINARY_DIR") + QStringLiteral("/app/drivedesk-sim");
        const AddressRange range = t.addresses(kind);
        QStringList args{QStringLiteral("--family"), t.id()};
        if (kind == LinkKind::Can)
            args << QStringLiteral("--can") << QStringLiteral("virtualcan:can0");
        else
            args << QStringLiteral("--pty");
        args << QStringLiteral("--address") << QString::number(range.last + 1);
        QProcess p;
        p.start(sim, args);
        QVERIFY(p.waitForFinished(10000));
        QCOMPARE(p.exitCode(), 2);
        const QString err = QString::fromUtf8(p.readAllStandardError());
        QVERIFY2(err.contains(QStringLiteral("%1..%2").arg(range.first).arg(range.last)), qPrintable(err));
    }
};

QTEST_MAIN(TestFamilyTraits)
#include "tst_familytraits.moc"
