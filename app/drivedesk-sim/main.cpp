// drivedesk-sim: simulated drives of one family on a pty or a CAN bus, for DriveDesk's
// tests, for its demo, and for integrators who test PLC programs without a drive.
#include "core/common/coreresources.h"
#include "core/common/eventdispatcherchoice.h"
#include "core/common/localtimezone.h"
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
    QTextStream(stderr) << "drivedesk-sim: " << message << '\n' << tr("Try 'drivedesk-sim --help'.") << '\n';
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

// "servo-modbus 19200, shuoke 9600": each family's default of `value` (0: none), for --help.
QString familyDefaults(int FamilyTraits::*value)
{
    QStringList defaults;
    for (const FamilyTraits *t : allFamilyTraits())
        if (t->*value > 0)
            defaults << QStringLiteral("%1 %2").arg(t->id()).arg(t->*value);
    return defaults.join(QStringLiteral(", "));
}

// "shuoke: rtu, ascii, plc, can": the framings of each family that has several, for --help.
QString familyFramings()
{
    QStringList framings;
    for (const FamilyTraits *t : allFamilyTraits())
        if (t->framings.size() > 1)
            framings << QStringLiteral("%1: %2").arg(
                t->id(), (t->framingIds(LinkKind::Serial) + t->framingIds(LinkKind::Can)).join(QLatin1String(", ")));
    return framings.join(QStringLiteral("; "));
}

QString description()
{
    return tr("Simulated servo and stepper drives on a pty or a CAN bus.\n"
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
              "port and prints its address (can: virtualcan:tcp://127.0.0.1:PORT/can0).");
}

// The command line's options, and how they become the bench's options.
struct CommandLine
{
    QCommandLineOption family{QStringLiteral("family"),
                              tr("Drive family: %1.").arg(familyIds().join(QStringLiteral(", "))),
                              QStringLiteral("FAMILY")};
    QCommandLineOption address{QStringLiteral("address"),
                               tr("A drive at this address (repeat, or a comma list). Default: 1."),
                               QStringLiteral("N")};
    QCommandLineOption pty{QStringLiteral("pty"), tr("Serve on a new pseudo-terminal (serial families).")};
    QCommandLineOption link{QStringLiteral("link"), tr("With --pty: also make a symbolic link to the pty at PATH."),
                            QStringLiteral("PATH")};
    QCommandLineOption can{QStringLiteral("can"), tr("Serve on a CAN bus, e.g. virtualcan:can0 or socketcan:can0."),
                           QStringLiteral("PLUGIN:INTERFACE")};
    QCommandLineOption baud{QStringLiteral("baud"),
                            tr("Serial baud rate of the drives (%1).").arg(familyDefaults(&FamilyTraits::defaultBaud)),
                            QStringLiteral("N")};
    QCommandLineOption bitrate{
        QStringLiteral("bitrate"),
        tr("CAN bitrate for the timing model (%1).").arg(familyDefaults(&FamilyTraits::defaultBitrate)),
        QStringLiteral("N")};
    QCommandLineOption framing{QStringLiteral("framing"), tr("Framing (%1).").arg(familyFramings()),
                               QStringLiteral("F")};
    QCommandLineOption latency{QStringLiteral("latency-ms"),
                               tr("Drive reply latency in milliseconds (default 1 serial, 0.2 CAN)."),
                               QStringLiteral("N")};
    QCommandLineOption drop{QStringLiteral("drop"), tr("Probability of dropping a reply (0..1 or N%)."),
                            QStringLiteral("P")};
    QCommandLineOption corrupt{QStringLiteral("corrupt"), tr("Probability of corrupting a reply (0..1 or N%)."),
                               QStringLiteral("P")};
    QCommandLineOption seed{QStringLiteral("seed"), tr("Seed of the fault injection (deterministic)."),
                            QStringLiteral("N")};
    QCommandLineOption state{QStringLiteral("state"),
                             tr("Load parameters from FILE at start (if it exists), save them at exit."),
                             QStringLiteral("FILE")};
    QCommandLineOption demo{QStringLiteral("demo-motion"),
                            tr("Let the drives move on their own (a slow demo profile).")};
    QCommandLineOption resonance{
        QStringLiteral("resonance-hz"),
        tr("Give the closed-loop drives a compliant load resonating at F Hz (1..1000; the simulator's model)."),
        QStringLiteral("F")};

    QList<QCommandLineOption> all() const
    {
        return {family,  address, pty,     link, can,   baud, bitrate,  framing,
                latency, drop,    corrupt, seed, state, demo, resonance};
    }

    // Fills *o from the parsed command line; returns what is wrong with it (empty: nothing).
    QString read(const QCommandLineParser &p, SimBenchOptions *o) const
    {
        for (auto step : {&CommandLine::readFamilyAndLink, &CommandLine::readTiming, &CommandLine::readFraming,
                          &CommandLine::readAddresses, &CommandLine::readFaults}) {
            if (const QString error = (this->*step)(p, o); !error.isEmpty())
                return error;
        }
        o->stateFile = p.value(state);
        o->demoMotion = p.isSet(demo);
        if (p.isSet(resonance)) {
            bool ok = false;
            const double hz = p.value(resonance).toDouble(&ok);
            if (!ok || !(hz >= 1.0 && hz <= 1000.0))
                return tr("--resonance-hz must be a frequency from 1 to 1000 Hz, not '%1'.").arg(p.value(resonance));
            o->resonanceHz = hz;
        }
        return {};
    }

private:
    LinkKind linkKind(const QCommandLineParser &p) const { return p.isSet(can) ? LinkKind::Can : LinkKind::Serial; }

    QString readFamilyAndLink(const QCommandLineParser &p, SimBenchOptions *o) const
    {
        const QString families = familyIds().join(QLatin1String(", "));
        if (!p.isSet(family))
            return tr("--family is required (%1).").arg(families);
        const auto f = familyFromId(p.value(family));
        if (!f)
            return tr("Unknown family '%1': use %2.").arg(p.value(family), families);
        o->family = *f;
        const FamilyTraits &traits = familyTraits(o->family);
        if (p.isSet(pty) == p.isSet(can))
            return tr("Give exactly one of --pty and --can.");
        if (!traits.talks(linkKind(p)))
            return linkKind(p) == LinkKind::Can
                ? tr("%1 drives live on RS485: use --pty.").arg(traits.id())
                : tr("%1 drives live on a CAN bus: use --can PLUGIN:INTERFACE.").arg(traits.id());
        if (p.isSet(link) && !p.isSet(pty))
            return tr("--link needs --pty.");
        o->can = p.value(can);
        o->linkPath = p.value(link);
        return {};
    }

    // false when `opt` is given but is no whole number from min to max.
    static bool intValue(const QCommandLineParser &p, const QCommandLineOption &opt, int min, int max, int *out)
    {
        if (!p.isSet(opt))
            return true;
        bool ok = false;
        const int v = p.value(opt).toInt(&ok);
        if (!ok || v < min || v > max)
            return false;
        *out = v;
        return true;
    }

    QString readTiming(const QCommandLineParser &p, SimBenchOptions *o) const
    {
        if (!intValue(p, baud, 300, 4000000, &o->baud))
            return tr("Bad --baud '%1': use a rate such as 9600 or 115200.").arg(p.value(baud));
        if (!intValue(p, bitrate, 5000, 1000000, &o->bitrate))
            return tr("Bad --bitrate '%1': use 5000..1000000.").arg(p.value(bitrate));
        int latencyMs = -1;
        if (!intValue(p, latency, 0, 10000, &latencyMs))
            return tr("Bad --latency-ms '%1': use 0..10000.").arg(p.value(latency));
        o->latencyUs = latencyMs < 0 ? -1 : latencyMs * 1000;
        return {};
    }

    QString readFraming(const QCommandLineParser &p, SimBenchOptions *o) const
    {
        if (!p.isSet(framing))
            return {};
        const FamilyTraits &traits = familyTraits(o->family);
        o->framing = p.value(framing).toLower();
        if (!allFramingIds().contains(o->framing))
            return tr("Bad --framing '%1': use %2.").arg(p.value(framing), allFramingIds().join(QLatin1String(", ")));
        const FramingTraits *ft = traits.framing(o->framing);
        if (!ft || traits.framings.size() < 2)
            return tr("--framing does not apply to the %1 family.").arg(traits.id());
        if (ft->link != linkKind(p))
            return tr("Framing '%1' needs %2.")
                .arg(o->framing, ft->link == LinkKind::Can ? QStringLiteral("--can") : QStringLiteral("--pty"));
        return {};
    }

    // Addresses: those a drive of the family can have on this link and framing.
    QString readAddresses(const QCommandLineParser &p, SimBenchOptions *o) const
    {
        const FamilyTraits &traits = familyTraits(o->family);
        const FramingTraits *ft = traits.framingFor(linkKind(p), o->framing);
        const AddressRange range = ft ? ft->addresses : traits.addresses(linkKind(p));
        for (const QString &item : p.values(address)) {
            for (const QString &part : item.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
                bool ok = false;
                const int a = part.trimmed().toInt(&ok);
                if (!ok || !range.contains(a))
                    return tr("Bad address '%1': use %2..%3 for %4.")
                        .arg(part)
                        .arg(range.first)
                        .arg(range.last)
                        .arg(traits.id());
                if (o->addresses.contains(a))
                    return tr("Address %1 is given twice.").arg(a);
                o->addresses << a;
            }
        }
        return {};
    }

    QString readFaults(const QCommandLineParser &p, SimBenchOptions *o) const
    {
        if (p.isSet(drop) && !parseRate(p.value(drop), &o->faults.dropRate))
            return tr("Bad --drop '%1': use a probability 0..1 or a percentage.").arg(p.value(drop));
        if (p.isSet(corrupt) && !parseRate(p.value(corrupt), &o->faults.corruptRate))
            return tr("Bad --corrupt '%1': use a probability 0..1 or a percentage.").arg(p.value(corrupt));
        if (p.isSet(seed)) {
            bool ok = false;
            o->faults.seed = p.value(seed).toUInt(&ok);
            if (!ok)
                return tr("Bad --seed '%1': use a non-negative whole number.").arg(p.value(seed));
        }
        return {};
    }
};

// Runs the bench until a signal or 'quit', then saves its state; the exit code.
int runBench(QCoreApplication &app, const SimBenchOptions &o)
{
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

} // namespace

int main(int argc, char *argv[])
{
    dd::pinLocalTimeZone();           // before any thread: see localtimezone.h
    dd::preferPlainEventDispatcher(); // before the application object: see eventdispatcherchoice.h
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("drivedesk-sim"));
    QCoreApplication::setApplicationVersion(QStringLiteral(DRIVEDESK_VERSION));
    ensureCoreResources();

    QCommandLineParser p;
    p.setApplicationDescription(description());
    p.addHelpOption();
    p.addVersionOption();
    const CommandLine options;
    p.addOptions(options.all());
    if (!p.parse(QCoreApplication::arguments()))
        return usageError(p.errorText());
    if (p.isSet(QStringLiteral("help")))
        p.showHelp(0);
    if (p.isSet(QStringLiteral("version")))
        p.showVersion();
    if (!p.positionalArguments().isEmpty())
        return usageError(tr("Unexpected argument: %1").arg(p.positionalArguments().constFirst()));

    SimBenchOptions o;
    if (const QString error = options.read(p, &o); !error.isEmpty())
        return usageError(error);
    return runBench(app, o);
}
