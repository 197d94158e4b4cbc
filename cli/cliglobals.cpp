#include "cli/cliglobals.h"

#include "cli/clivalues.h"
#include "core/link/cansettings.h"
#include "core/protocol/familytraits.h"

namespace dd {

QList<CliOptionSpec> CliGlobals::optionSpecs()
{
    return {
        {QStringLiteral("family"), true, {}},
        {QStringLiteral("port"), true, {}},
        {QStringLiteral("can"), true, {}},
        {QStringLiteral("baud"), true, {}},
        {QStringLiteral("bitrate"), true, {}},
        {QStringLiteral("framing"), true, {}},
        {QStringLiteral("address"), true, {}},
        {QStringLiteral("timeout"), true, {}},
        {QStringLiteral("retries"), true, {}},
        {QStringLiteral("json"), false, {}},
        {QStringLiteral("trace"), false, {}},
        {QStringLiteral("dictionary"), true, {}},
        {QStringLiteral("machine"), true, {}},
        {QStringLiteral("option"), true, {}, true},
        {QStringLiteral("sim"), false, {}},
        {QStringLiteral("sim-drives"), true, {}},
        {QStringLiteral("sim-state"), true, {}},
        {QStringLiteral("sim-motion"), false, {}},
        {QStringLiteral("sim-resonance-hz"), true, {}},
        {QStringLiteral("lang"), true, {}}, // read by Cli::run before parsing (CliLanguage)
        {QStringLiteral("help"), false, QLatin1Char('h')},
        {QStringLiteral("version"), false, QLatin1Char('V')},
    };
}

bool CliGlobals::isCanLink() const
{
    if (connection.isCan())
        return true;
    const FamilyTraits &t = familyTraits(connection.family);
    if (const FramingTraits *f = t.framing(connection.framing))
        return f->link == LinkKind::Can;
    return !t.talks(LinkKind::Serial);
}

int CliGlobals::defaultAddress(Family)
{
    return 1;
}

bool CliGlobals::load(const CliInvocation &inv, QString *error)
{
    return loadFlags(inv, error) && loadLink(inv, error) && loadFamily(inv, error) && loadNumbers(inv, error)
        && loadOptions(inv, error) && loadAddress(inv, error) && loadSimDrives(inv, error);
}

bool CliGlobals::loadFlags(const CliInvocation &inv, QString *error)
{
    json = inv.has(QStringLiteral("json"));
    trace = inv.has(QStringLiteral("trace"));
    sim = inv.has(QStringLiteral("sim")) || inv.has(QStringLiteral("sim-drives"))
        || inv.has(QStringLiteral("sim-state")) || inv.has(QStringLiteral("sim-motion"))
        || inv.has(QStringLiteral("sim-resonance-hz"));
    simMotion = inv.has(QStringLiteral("sim-motion"));
    if (inv.has(QStringLiteral("sim-resonance-hz"))) {
        bool ok = false;
        simResonanceHz = inv.value(QStringLiteral("sim-resonance-hz")).toDouble(&ok);
        if (!ok || !(simResonanceHz >= 1.0 && simResonanceHz <= 1000.0)) {
            *error = tr("--sim-resonance-hz must be a frequency from 1 to 1000 Hz, not \"%1\".")
                         .arg(inv.value(QStringLiteral("sim-resonance-hz")));
            return false;
        }
    }
    simStateFile = inv.value(QStringLiteral("sim-state"));
    if (inv.has(QStringLiteral("sim-state")) && simStateFile.isEmpty()) {
        *error = tr("--sim-state needs a file name.");
        return false;
    }
    machine = inv.value(QStringLiteral("machine")).trimmed();
    if (inv.has(QStringLiteral("machine")) && (machine.isEmpty() || machine.size() > 200)) {
        *error = tr("--machine needs a name of 1 to 200 characters, e.g. --machine \"Press line 3\".");
        return false;
    }
    dictionaryFile = inv.value(QStringLiteral("dictionary"));
    if (inv.has(QStringLiteral("dictionary")) && dictionaryFile.isEmpty()) {
        *error = tr("--dictionary needs a file name.");
        return false;
    }
    return true;
}

bool CliGlobals::loadLink(const CliInvocation &inv, QString *error)
{
    ConnectionSettings &c = connection;
    c.port = inv.value(QStringLiteral("port"));
    c.can = inv.value(QStringLiteral("can"));
    if (inv.has(QStringLiteral("port")) && c.port.isEmpty()) {
        *error = tr("--port needs a device, e.g. /dev/ttyUSB0 or COM3.");
        return false;
    }
    if (inv.has(QStringLiteral("can")) && c.can.isEmpty()) {
        *error = tr("--can needs PLUGIN:INTERFACE, e.g. socketcan:can0.");
        return false;
    }
    if (!c.port.isEmpty() && !c.can.isEmpty()) {
        *error = tr("Give either --port or --can, not both.");
        return false;
    }
    if (!c.can.isEmpty()) {
        CanSettings cs;
        if (!CanSettings::parse(c.can, &cs) || cs.plugin.isEmpty() || cs.interface.isEmpty()) {
            *error = tr("--can \"%1\": write PLUGIN:INTERFACE, e.g. socketcan:can0 or virtualcan:can0.").arg(c.can);
            return false;
        }
    }
    if (sim && (!c.port.isEmpty() || !c.can.isEmpty())) {
        *error = tr("--sim brings its own simulated bus: leave out --port and --can.");
        return false;
    }
    if (!sim && c.port.isEmpty() && c.can.isEmpty() && !linkOptional) {
        *error = tr("No link given: add --port DEVICE (e.g. /dev/ttyUSB0) or --can PLUGIN:INTERFACE "
                    "(e.g. socketcan:can0), or --sim to use the built-in simulator.");
        return false;
    }
    return true;
}

// The family, its framing, and whether the link given is one the family (and framing) can
// use: all read from the family's traits.
bool CliGlobals::loadFamily(const CliInvocation &inv, QString *error)
{
    ConnectionSettings &c = connection;
    if (inv.has(QStringLiteral("family"))) {
        const auto f = familyFromId(inv.value(QStringLiteral("family")));
        if (!f) {
            *error = tr("Unknown family \"%1\". Families: %2.")
                         .arg(inv.value(QStringLiteral("family")), familyIds().join(QLatin1String(", ")));
            return false;
        }
        c.family = *f;
    } else {
        // Without --family: the first family of the table that talks the link's kind.
        const LinkKind link = c.isCan() ? LinkKind::Can : LinkKind::Serial;
        for (const FamilyTraits *t : allFamilyTraits()) {
            if (t->talks(link)) {
                c.family = t->family;
                break;
            }
        }
    }
    const FamilyTraits &t = familyTraits(c.family);
    if (inv.has(QStringLiteral("framing"))) {
        c.framing = inv.value(QStringLiteral("framing")).trimmed().toLower();
        if (!allFramingIds().contains(c.framing)) {
            *error = tr("Unknown framing \"%1\". Framings: %2.")
                         .arg(inv.value(QStringLiteral("framing")), allFramingIds().join(QLatin1String(", ")));
            return false;
        }
        const FramingTraits *f = t.framing(c.framing);
        if (!f) {
            *error = tr("The %1 family has no %2 framing. Its framings: %3.")
                         .arg(t.id(), c.framing,
                              (t.framingIds(LinkKind::Serial) + t.framingIds(LinkKind::Can)).join(QLatin1String(", ")));
            return false;
        }
        if (f->link == LinkKind::Can && !c.port.isEmpty()) {
            *error = tr("--framing %1 needs a CAN bus: use --can PLUGIN:INTERFACE.").arg(c.framing);
            return false;
        }
        if (f->link == LinkKind::Serial && !c.can.isEmpty()) {
            *error = tr("--framing %1 needs a serial port: use --port DEVICE.").arg(c.framing);
            return false;
        }
    } else if (!c.port.isEmpty() && !t.talks(LinkKind::Serial)) {
        *error = tr("The %1 family talks CAN: use --can PLUGIN:INTERFACE instead of --port.").arg(t.id());
        return false;
    } else if (!c.can.isEmpty() && !t.talks(LinkKind::Can)) {
        *error = tr("The %1 family talks RS485: use --port DEVICE instead of --can.").arg(t.id());
        return false;
    }
    // A family with several framings is told which one it runs: the link's default, or
    // with --sim (no link yet) its first.
    if (c.framing.isEmpty() && t.framings.size() > 1) {
        const FramingTraits *f = sim ? &t.framings.first()
                                     : t.defaultFraming(c.isCan() ? LinkKind::Can : LinkKind::Serial);
        c.framing = f ? f->id : QString();
    }
    return true;
}

bool CliGlobals::loadNumbers(const CliInvocation &inv, QString *error)
{
    struct Number
    {
        const char *option;
        qint64 min, max;
        int *target;
    };
    const Number numbers[] = {
        {"baud", 50, 4000000, &connection.baud},
        {"bitrate", 1000, 8000000, &connection.bitrate},
        {"timeout", 1, 60000, &connection.timeoutMs},
        {"retries", 0, 10, &connection.retries},
    };
    for (const Number &n : numbers) {
        const QString name = QString::fromLatin1(n.option);
        if (!inv.has(name))
            continue;
        const auto v = CliValues::integer(inv.value(name), n.min, n.max, QStringLiteral("--") + name, error);
        if (!v)
            return false;
        *n.target = int(*v);
    }
    return true;
}

// Family settings where the protocol documents are ambiguous (docs/protocols/, the
// decisions): --option shuoke.checksum=twos-complement, repeatable. The backend checks them.
bool CliGlobals::loadOptions(const CliInvocation &inv, QString *error)
{
    for (const QString &item : inv.values(QStringLiteral("option"))) {
        const int eq = item.indexOf(QLatin1Char('='));
        const QString key = item.left(eq).trimmed();
        if (eq <= 0 || key.isEmpty() || !key.contains(QLatin1Char('.'))) {
            *error = tr("--option: write FAMILY.KEY=VALUE, e.g. --option shuoke.checksum=twos-complement "
                        "(got \"%1\").")
                         .arg(item);
            return false;
        }
        connection.options.insert(key, item.mid(eq + 1).trimmed());
    }
    return true;
}

// --address: within the addresses a drive of the family can have on this link and framing.
bool CliGlobals::loadAddress(const CliInvocation &inv, QString *error)
{
    addressGiven = inv.has(QStringLiteral("address"));
    address = defaultAddress(connection.family);
    if (!addressGiven)
        return true;
    const AddressRange range = addressRange();
    const auto list = CliValues::integerList(inv.value(QStringLiteral("address")), range.first, range.last,
                                             QStringLiteral("--address"), error);
    if (!list)
        return false;
    addresses.clear();
    for (qint64 a : *list) {
        if (addresses.contains(int(a))) {
            *error = tr("--address: %1 is given twice.").arg(a);
            return false;
        }
        addresses << int(a);
    }
    address = addresses.first();
    return true;
}

AddressRange CliGlobals::addressRange() const
{
    const FamilyTraits &t = familyTraits(connection.family);
    const LinkKind link = isCanLink() ? LinkKind::Can : LinkKind::Serial;
    if (const FramingTraits *f = t.framingFor(link, connection.framing))
        return f->addresses;
    return t.addresses(link);
}

bool CliGlobals::loadSimDrives(const CliInvocation &inv, QString *error)
{
    simDrives.clear();
    if (!inv.has(QStringLiteral("sim-drives")))
        return true;
    const QStringList items = inv.value(QStringLiteral("sim-drives")).split(QLatin1Char(','));
    for (const QString &item : items) {
        const QStringList parts = item.split(QLatin1Char('@'));
        SimDrive d;
        const auto a = parts.size() <= 2
            ? CliValues::integer(parts.value(0), 0, 255, QStringLiteral("--sim-drives"), error)
            : std::nullopt;
        if (!a) {
            if (parts.size() > 2)
                *error = tr("--sim-drives: write ADDR[@BAUD],..., e.g. 3@19200,7.");
            return false;
        }
        d.address = int(*a);
        if (parts.size() == 2) {
            const auto b = CliValues::integer(parts.at(1), 50, 4000000, QStringLiteral("--sim-drives"), error);
            if (!b)
                return false;
            d.baud = int(*b);
        }
        simDrives << d;
    }
    return true;
}

} // namespace dd
