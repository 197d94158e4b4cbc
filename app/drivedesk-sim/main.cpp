// drivedesk-sim: simulated drives of one family on a pty or a CAN bus, for DriveDesk's
// tests, for its demo, and for integrators who test PLC programs without a drive.
#include "core/common/coreresources.h"
#include "core/common/signalwatcher.h"
#include "core/protocol/familytraits.h"
#include "sim/bench/simbench.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QSocketNotifier>
#include <QTextStream>
#include <cstdio>

#ifdef Q_OS_UNIX
#include <unistd.h>
#endif

using namespace dd;

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("dd::SimMain", text);
}

int usageError(const QString &message)
{
    QTextStream(stderr) << "drivedesk-sim: " << message << '\n'
                        << tr("Try 'drivedesk-sim --help'.") << '\n';
    return 2;
}

bool parseRate(const QString &text, double *out)
{
    QString t = text.trimmed();
    double scale = 1.0;
    if (t.endsWith(QLatin1Char('%'))) {
        t.chop(1);
        scale = 0.01;
    }
    bool ok = false;
    const double v = t.toDouble(&ok) * scale;
    if (!ok || v < 0.0 || v > 1.0)
        return false;
    *out = v;
    return true;
}

// Console commands on standard input (optional; ignored when stdin is closed).
void handleCommand(const QString &line, SimBench &bench)
{
    const QStringList w = line.simplified().split(QLatin1Char(' '), Qt::SkipEmptyParts);
    QTextStream out(stdout);
    if (w.isEmpty())
        return;
    if (w[0] == QLatin1String("silent") && w.size() == 2) {
        bench.setSilent(w[1] == QLatin1String("on"));
        out << "silent " << w[1] << Qt::endl;
    } else if (w[0] == QLatin1String("alarm") && w.size() == 3) {
        const bool ok = bench.injectAlarm(w[1].toInt(), w[2].toInt());
        out << (ok ? "alarm set" : "no such drive") << Qt::endl;
    } else if (w[0] == QLatin1String("quit")) {
        QCoreApplication::quit();
    } else if (w[0] == QLatin1String("where")) {
        out << bench.where() << Qt::endl;
    } else {
        out << "commands: silent on|off, alarm ADDRESS CODE, where, quit" << Qt::endl;
    }
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("drivedesk-sim"));
    QCoreApplication::setApplicationVersion(QStringLiteral(DRIVEDESK_VERSION));
    ensureCoreResources();

    QCommandLineParser p;
    p.setApplicationDescription(tr(
        "Simulated servo and stepper drives on a pty or a CAN bus.\n"
        "The first line printed is where to connect: 'pty: /dev/pts/N' or 'can: PLUGIN:INTERFACE'.\n"
        "Runs until SIGINT/SIGTERM (or 'quit' on standard input), then saves --state and exits.\n"
        "Standard input accepts: silent on|off (power loss), alarm ADDRESS CODE (0 clears), where, quit.\n"
        "Timing: a reply leaves after the request's and the reply's byte time at --baud (10 bits a\n"
        "character) or the frame's bit time at --bitrate, plus the drive latency.\n"
        "Examples:\n"
        "  drivedesk-sim --family servo-modbus --address 1 --address 2 --pty --link /tmp/rs485\n"
        "  drivedesk-sim --family servo-can --address 1 --can virtualcan:can0\n"
        "virtualcan: the simulator hosts a low-delay server on the plugin's default port so that\n"
        "clients naming plain can0 join it; --can virtualcan:auto uses a private server on a free\n"
        "port and prints its address (can: virtualcan:tcp://127.0.0.1:PORT/can0)."));
    p.addHelpOption();
    p.addVersionOption();
    const QCommandLineOption family({QStringLiteral("family")}, tr("Drive family: %1.").arg(familyIds().join(QStringLiteral(", "))), QStringLiteral("FAMILY"));
    const QCommandLineOption address({QStringLiteral("address")}, tr("A drive at this address (repeat, or a comma list). Default: 1."), QStringLiteral("N"));
    const QCommandLineOption pty({QStringLiteral("pty")}, tr("Serve on a new pseudo-terminal (serial families)."));
    const QCommandLineOption link({QStringLiteral("link")}, tr("With --pty: also make a symbolic link to the pty at PATH."), QStringLiteral("PATH"));
    const QCommandLineOption can({QStringLiteral("can")}, tr("Serve on a CAN bus, e.g. virtualcan:can0 or socketcan:can0."), QStringLiteral("PLUGIN:INTERFACE"));
    QStringList bauds, bitrates, framings;
    for (const FamilyTraits *t : allFamilyTraits()) {
        if (t->defaultBaud > 0)
            bauds << QStringLiteral("%1 %2").arg(t->id()).arg(t->defaultBaud);
        if (t->defaultBitrate > 0)
            bitrates << QStringLiteral("%1 %2").arg(t->id()).arg(t->defaultBitrate);
        if (t->framings.size() > 1)
            framings << QStringLiteral("%1: %2").arg(t->id(), (t->framingIds(LinkKind::Serial) + t->framingIds(LinkKind::Can)).join(QLatin1String(", ")));
    }
    const QString comma = QStringLiteral(", ");
    const QCommandLineOption baud({QStringLiteral("baud")}, tr("Serial baud rate of the drives (%1).").arg(bauds.join(comma)), QStringLiteral("N"));
    const QCommandLineOption bitrate({QStringLiteral("bitrate")}, tr("CAN bitrate for the timing model (%1).").arg(bitrates.join(comma)), QStringLiteral("N"));
    const QCommandLineOption framing({QStringLiteral("framing")}, tr("Framing (%1).").arg(framings.join(QStringLiteral("; "))), QStringLiteral("F"));
    const QCommandLineOption latency({QStringLiteral("latency-ms")}, tr("Drive reply latency in milliseconds (default 1 serial, 0.2 CAN)."), QStringLiteral("N"));
    const QCommandLineOption drop({QStringLiteral("drop")}, tr("Probability of dropping a reply (0..1 or N%)."), QStringLiteral("P"));
    const QCommandLineOption corrupt({QStringLiteral("corrupt")}, tr("Probability of corrupting a reply (0..1 or N%)."), QStringLiteral("P"));
    const QCommandLineOption seed({QStringLiteral("seed")}, tr("Seed of the fault injection (deterministic)."), QStringLiteral("N"));
    const QCommandLineOption state({QStringLiteral("state")}, tr("Load parameters from FILE at start (if it exists), save them at exit."), QStringLiteral("FILE"));
    const QCommandLineOption demo({QStringLiteral("demo-motion")}, tr("Let the drives move on their own (a slow demo profile)."));
    p.addOptions({family, address, pty, link, can, baud, bitrate, framing, latency, drop, corrupt, seed, state, demo});
    if (!p.parse(QCoreApplication::arguments()))
        return usageError(p.errorText());
    if (p.isSet(QStringLiteral("help")))
        p.showHelp(0);
    if (p.isSet(QStringLiteral("version")))
        p.showVersion();
    if (!p.positionalArguments().isEmpty())
        return usageError(tr("Unexpected argument: %1").arg(p.positionalArguments().constFirst()));

    SimBenchOptions o;
    const QString families = familyIds().join(QLatin1String(", "));
    if (!p.isSet(family))
        return usageError(tr("--family is required (%1).").arg(families));
    const auto f = familyFromId(p.value(family));
    if (!f)
        return usageError(tr("Unknown family '%1': use %2.").arg(p.value(family), families));
    o.family = *f;
    const FamilyTraits &traits = familyTraits(o.family);
    if (p.isSet(pty) == p.isSet(can))
        return usageError(tr("Give exactly one of --pty and --can."));
    const LinkKind linkKind = p.isSet(can) ? LinkKind::Can : LinkKind::Serial;
    if (!traits.talks(linkKind))
        return usageError(linkKind == LinkKind::Can ? tr("%1 drives live on RS485: use --pty.").arg(traits.id())
                                                    : tr("%1 drives live on a CAN bus: use --can PLUGIN:INTERFACE.").arg(traits.id()));
    if (p.isSet(link) && !p.isSet(pty))
        return usageError(tr("--link needs --pty."));
    o.can = p.value(can);
    o.linkPath = p.value(link);
    auto intOption = [&p](const QCommandLineOption &opt, int min, int max, int *out) -> bool {
        if (!p.isSet(opt))
            return true;
        bool ok = false;
        const int v = p.value(opt).toInt(&ok);
        if (!ok || v < min || v > max)
            return false;
        *out = v;
        return true;
    };
    if (!intOption(baud, 300, 4000000, &o.baud))
        return usageError(tr("Bad --baud '%1': use a rate such as 9600 or 115200.").arg(p.value(baud)));
    if (!intOption(bitrate, 5000, 1000000, &o.bitrate))
        return usageError(tr("Bad --bitrate '%1': use 5000..1000000.").arg(p.value(bitrate)));
    int latencyMs = -1;
    if (!intOption(latency, 0, 10000, &latencyMs))
        return usageError(tr("Bad --latency-ms '%1': use 0..10000.").arg(p.value(latency)));
    o.latencyUs = latencyMs < 0 ? -1 : latencyMs * 1000;
    if (p.isSet(framing)) {
        o.framing = p.value(framing).toLower();
        if (!allFramingIds().contains(o.framing))
            return usageError(tr("Bad --framing '%1': use %2.").arg(p.value(framing), allFramingIds().join(QLatin1String(", "))));
        const FramingTraits *ft = traits.framing(o.framing);
        if (!ft || traits.framings.size() < 2)
            return usageError(tr("--framing does not apply to the %1 family.").arg(traits.id()));
        if (ft->link != linkKind)
            return usageError(tr("Framing '%1' needs %2.").arg(o.framing, ft->link == LinkKind::Can ? QStringLiteral("--can") : QStringLiteral("--pty")));
    }
    // Addresses: those a drive of the family can have on this link and framing.
    const FramingTraits *ft = traits.framingFor(linkKind, o.framing);
    const AddressRange range = ft ? ft->addresses : traits.addresses(linkKind);
    for (const QString &item : p.values(address)) {
        for (const QString &part : item.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
            bool ok = false;
            const int a = part.trimmed().toInt(&ok);
            if (!ok || !range.contains(a))
                return usageError(tr("Bad address '%1': use %2..%3 for %4.").arg(part).arg(range.first).arg(range.last).arg(traits.id()));
            if (o.addresses.contains(a))
                return usageError(tr("Address %1 is given twice.").arg(a));
            o.addresses << a;
        }
    }
    if (p.isSet(drop) && !parseRate(p.value(drop), &o.faults.dropRate))
        return usageError(tr("Bad --drop '%1': use a probability 0..1 or a percentage.").arg(p.value(drop)));
    if (p.isSet(corrupt) && !parseRate(p.value(corrupt), &o.faults.corruptRate))
        return usageError(tr("Bad --corrupt '%1': use a probability 0..1 or a percentage.").arg(p.value(corrupt)));
    if (p.isSet(seed)) {
        bool ok = false;
        o.faults.seed = p.value(seed).toUInt(&ok);
        if (!ok)
            return usageError(tr("Bad --seed '%1': use a non-negative whole number.").arg(p.value(seed)));
    }
    o.stateFile = p.value(state);
    o.demoMotion = p.isSet(demo);

    SimBench bench;
    const Error e = bench.start(o);
    if (e.isError()) {
        QTextStream(stderr) << "drivedesk-sim: " << e.message << '\n';
        return e.code == ErrorCode::OpenFailed || e.code == ErrorCode::LinkClosed ? 3 : 2;
    }
    QTextStream(stdout) << bench.where() << Qt::endl;

    SignalWatcher watcher;
    QObject::connect(&watcher, &SignalWatcher::interrupted, &app, [] { QCoreApplication::quit(); });

#ifdef Q_OS_UNIX
    QSocketNotifier input(STDIN_FILENO, QSocketNotifier::Read);
    QByteArray pending;
    QObject::connect(&input, &QSocketNotifier::activated, &app, [&] {
        char buf[256];
        const ssize_t n = ::read(STDIN_FILENO, buf, sizeof buf);
        if (n <= 0) {
            input.setEnabled(false); // end of input: keep running until a signal
            return;
        }
        pending.append(buf, n);
        qsizetype nl;
        while ((nl = pending.indexOf('\n')) >= 0) {
            handleCommand(QString::fromUtf8(pending.left(nl)), bench);
            pending.remove(0, nl + 1);
        }
    });
#endif

    const int rc = app.exec();
    const Error saved = bench.saveState();
    bench.stop();
    if (saved.isError()) {
        QTextStream(stderr) << "drivedesk-sim: " << saved.message << '\n';
        return 1;
    }
    return rc;
}
