#include "cliglobals.h"

#include "clivalues.h"
#include "link/cansettings.h"

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
        {QStringLiteral("option"), true, {}, true},
        {QStringLiteral("sim"), false, {}},
        {QStringLiteral("sim-drives"), true, {}},
        {QStringLiteral("sim-state"), true, {}},
        {QStringLiteral("sim-motion"), false, {}},
        {QStringLiteral("lang"), true, {}},   // read by Cli::run before parsing (CliLanguage)
        {QStringLiteral("help"), false, QLatin1Char('h')},
        {QStringLiteral("version"), false, QLatin1Char('V')},
    };
}

bool CliGlobals::isCanLink() const
{
    return connection.isCan() || connection.family == Family::ServoCan
        || connection.framing == QLatin1String("can");
}

int CliGlobals::defaultAddress(Family)
{
    return 1;
}

bool CliGlobals::load(const CliInvocation &inv, QString *error)
{
    json = inv.has(QStringLiteral("json"));
    trace = inv.has(QStringLiteral("trace"));
    sim = inv.has(QStringLiteral("sim")) || inv.has(QStringLiteral("sim-drives"))
        || inv.has(QStringLiteral("sim-state")) || inv.has(QStringLiteral("sim-motion"));
    simMotion = inv.has(QStringLiteral("sim-motion"));
    simStateFile = inv.value(QStringLiteral("sim-state"));
    if (inv.has(QStringLiteral("sim-state")) && simStateFile.isEmpty()) {
        *error = tr("--sim-state needs a file name.");
        return false;
    }
    dictionaryFile = inv.value(QStringLiteral("dictionary"));
    if (inv.has(QStringLiteral("dictionary")) && dictionaryFile.isEmpty()) {
        *error = tr("--dictionary needs a file name.");
        return false;
    }

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
            *error = tr("--can \"%1\": write PLUGIN:INTERFACE, e.g. socketcan:can0 or virtualcan:can0.")
                         .arg(c.can);
            return false;
        }
    }

    if (inv.has(QStringLiteral("family"))) {
        const auto f = familyFromId(inv.value(QStringLiteral("family")));
        if (!f) {
            *error = tr("Unknown family \"%1\". Families: %2.")
                         .arg(inv.value(QStringLiteral("family")), familyIds().join(QLatin1String(", ")));
            return false;
        }
        c.family = *f;
    } else {
        c.family = c.isCan() ? Family::ServoCan : Family::ServoModbus;
    }

    if (inv.has(QStringLiteral("framing"))) {
        c.framing = inv.value(QStringLiteral("framing")).trimmed().toLower();
        const QStringList known = {QStringLiteral("rtu"), QStringLiteral("ascii"),
                                   QStringLiteral("can"), QStringLiteral("plc")};
        if (!known.contains(c.framing)) {
            *error = tr("Unknown framing \"%1\". Framings: rtu, ascii, can, plc.")
                         .arg(inv.value(QStringLiteral("framing")));
            return false;
        }
    }

    // Which link each family can use.
    switch (c.family) {
    case Family::ServoCan:
        if (!c.port.isEmpty()) {
            *error = tr("The servo-can family talks CAN: use --can PLUGIN:INTERFACE instead of --port.");
            return false;
        }
        if (!c.framing.isEmpty() && c.framing != QLatin1String("can")) {
            *error = tr("The servo-can family has only the can framing.");
            return false;
        }
        break;
    case Family::ServoModbus:
        if (!c.can.isEmpty()) {
            *error = tr("The servo-modbus family talks RS485: use --port DEVICE instead of --can.");
            return false;
        }
        if (!c.framing.isEmpty() && c.framing != QLatin1String("rtu")) {
            *error = tr("The servo-modbus family has only the rtu framing.");
            return false;
        }
        break;
    case Family::Shuoke:
        if (c.framing == QLatin1String("can") && !c.port.isEmpty()) {
            *error = tr("--framing can needs a CAN bus: use --can PLUGIN:INTERFACE.");
            return false;
        }
        if (!c.framing.isEmpty() && c.framing != QLatin1String("can") && !c.can.isEmpty()) {
            *error = tr("--framing %1 needs a serial port: use --port DEVICE.").arg(c.framing);
            return false;
        }
        if (c.framing.isEmpty() && !c.can.isEmpty())
            c.framing = QStringLiteral("can");
        break;
    }

    if (sim && (!c.port.isEmpty() || !c.can.isEmpty())) {
        *error = tr("--sim brings its own simulated bus: leave out --port and --can.");
        return false;
    }
    if (sim && c.family == Family::Shuoke && c.framing.isEmpty())
        c.framing = QStringLiteral("rtu");
    if (!sim && c.port.isEmpty() && c.can.isEmpty()) {
        *error = tr("No link given: add --port DEVICE (e.g. /dev/ttyUSB0) or --can PLUGIN:INTERFACE "
                    "(e.g. socketcan:can0), or --sim to use the built-in simulator.");
        return false;
    }

    if (inv.has(QStringLiteral("baud"))) {
        const auto v = CliValues::integer(inv.value(QStringLiteral("baud")), 50, 4000000,
                                          QStringLiteral("--baud"), error);
        if (!v)
            return false;
        c.baud = int(*v);
    }
    if (inv.has(QStringLiteral("bitrate"))) {
        const auto v = CliValues::integer(inv.value(QStringLiteral("bitrate")), 1000, 8000000,
                                          QStringLiteral("--bitrate"), error);
        if (!v)
            return false;
        c.bitrate = int(*v);
    }
    if (inv.has(QStringLiteral("timeout"))) {
        const auto v = CliValues::integer(inv.value(QStringLiteral("timeout")), 1, 60000,
                                          QStringLiteral("--timeout"), error);
        if (!v)
            return false;
        c.timeoutMs = int(*v);
    }
    if (inv.has(QStringLiteral("retries"))) {
        const auto v = CliValues::integer(inv.value(QStringLiteral("retries")), 0, 10,
                                          QStringLiteral("--retries"), error);
        if (!v)
            return false;
        c.retries = int(*v);
    }

    // Family settings where the protocol documents are ambiguous (PROTOCOLS.md "Decisions"):
    // --option shuoke.checksum=twos-complement, repeatable. The backend checks them.
    for (const QString &item : inv.values(QStringLiteral("option"))) {
        const int eq = item.indexOf(QLatin1Char('='));
        const QString key = item.left(eq).trimmed();
        if (eq <= 0 || key.isEmpty() || !key.contains(QLatin1Char('.'))) {
            *error = tr("--option: write FAMILY.KEY=VALUE, e.g. --option shuoke.checksum=twos-complement "
                        "(got \"%1\").").arg(item);
            return false;
        }
        c.options.insert(key, item.mid(eq + 1).trimmed());
    }

    addressGiven = inv.has(QStringLiteral("address"));
    address = defaultAddress(c.family);
    if (addressGiven) {
        const int max = c.family == Family::ServoCan ? 99 : c.family == Family::ServoModbus ? 247 : 255;
        const auto v = CliValues::integer(inv.value(QStringLiteral("address")), 0, max,
                                          QStringLiteral("--address"), error);
        if (!v)
            return false;
        address = int(*v);
    }

    simDrives.clear();
    if (inv.has(QStringLiteral("sim-drives"))) {
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
                const auto b = CliValues::integer(parts.at(1), 50, 4000000,
                                                  QStringLiteral("--sim-drives"), error);
                if (!b)
                    return false;
                d.baud = int(*b);
            }
            simDrives << d;
        }
    }
    return true;
}

} // namespace dd
