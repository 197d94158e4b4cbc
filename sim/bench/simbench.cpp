#include "sim/bench/simbench.h"
#include "core/protocol/familytraits.h"
#include "sim/bench/simfamilies.h"

#include "core/link/cansettings.h"
#include "sim/bus/ptyendpoint.h"
#include "sim/bus/simcanbus.h"
#include "sim/bus/simserialbus.h"
#include "sim/bus/virtualcanhub.h"
#include "sim/servocan/simservocandrive.h"
#include "sim/servomodbus/simservomodbusdrive.h"
#include "sim/shuoke/simshuokecandevice.h"
#include "sim/shuoke/simshuokeserialdevice.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QSaveFile>

namespace dd {

namespace {
constexpr quint16 kVirtualCanDefaultPort = 35468; // the plugin's default server port
const char kStateFormat[] = "drivedesk-sim-state";

// One simulated drive per address on `bus`, made by the family's simulator, with the
// bench's latency and fault settings (each drive its own fault seed).
template <class Bus, class Device>
Error addDevices(Bus *bus, const SimBenchOptions &o, std::unique_ptr<Device> (*make)(const SimDeviceSpec &, Error *))
{
    for (int address : std::as_const(o.addresses)) {
        Error e;
        const SimDeviceSpec spec{address,      o.bauds.value(address, o.baud), o.bitrate,    o.framing,
                                 o.demoMotion, [bus] { return bus->nowUs(); }, o.resonanceHz};
        std::unique_ptr<Device> device = make(spec, &e);
        if (!device)
            return e;
        if (o.latencyUs >= 0)
            device->setLatencyUs(o.latencyUs);
        FaultSettings f = o.faults;
        f.seed = o.faults.seed + static_cast<quint32>(address);
        device->faults().setSettings(f);
        bus->addDevice(std::move(device));
    }
    return Error::none();
}
} // namespace

int SimBenchOptions::defaultAddress(Family)
{
    return 1;
}

int SimBenchOptions::defaultBaud(Family family)
{
    return familyTraits(family).defaultBaud;
}

int SimBenchOptions::defaultBitrate(Family family)
{
    return familyTraits(family).defaultBitrate;
}

SimBench::SimBench(QObject *parent)
    : QObject(parent)
{
}

SimBench::~SimBench()
{
    stop();
}

bool SimBench::isRunning() const
{
    return m_serial || m_can;
}

Error SimBench::start(const SimBenchOptions &options)
{
    stop();
    m_options = options;
    if (m_options.addresses.isEmpty())
        m_options.addresses = {SimBenchOptions::defaultAddress(options.family)};
    if (m_options.baud <= 0)
        m_options.baud = SimBenchOptions::defaultBaud(options.family);
    if (m_options.bitrate <= 0)
        m_options.bitrate = SimBenchOptions::defaultBitrate(options.family);
    Error e = m_options.can.isEmpty() ? startSerial() : startCan();
    if (e.isError()) {
        stop();
        return e;
    }
    if (!m_options.stateFile.isEmpty() && QFile::exists(m_options.stateFile)) {
        QFile f(m_options.stateFile);
        if (!f.open(QIODevice::ReadOnly)) {
            stop();
            return {ErrorCode::FileError,
                    tr("Cannot read the state file %1: %2").arg(m_options.stateFile, f.errorString())};
        }
        QJsonParseError pe;
        const QJsonDocument doc = QJsonDocument::fromJson(f.read(4 * 1024 * 1024), &pe);
        if (pe.error != QJsonParseError::NoError || !doc.isObject()) {
            stop();
            return {ErrorCode::Malformed,
                    tr("The state file %1 is not valid JSON: %2").arg(m_options.stateFile, pe.errorString())};
        }
        e = applyState(doc.object());
        if (e.isError()) {
            stop();
            return e;
        }
    }
    return Error::none();
}

Error SimBench::startSerial()
{
    auto *pty = new PtyEndpoint;
    if (const Error e = pty->open(m_options.linkPath); e.isError()) {
        delete pty;
        return e;
    }
    m_ptyPath = pty->slavePath();
    m_serial = new SimSerialBus(pty, this);
    const SimFamily &family = simFamily(m_options.family);
    if (!family.serial)
        return {ErrorCode::InvalidArgument,
                tr("%1 drives live on a CAN bus: give --can PLUGIN:INTERFACE.").arg(familyId(m_options.family))};
    return addDevices(m_serial, m_options, family.serial);
}

Error SimBench::startCan()
{
    CanSettings cs;
    if (!CanSettings::parse(m_options.can, &cs))
        return {ErrorCode::InvalidArgument,
                tr("\"%1\" is not a CAN interface: use PLUGIN:INTERFACE, e.g. virtualcan:can0.").arg(m_options.can)};
    QString iface = cs.interface;
    if (cs.plugin == QLatin1String("virtualcan") && !iface.startsWith(QLatin1String("tcp://"))) {
        // A low-delay hub instead of the plugin's own server (which leaves Nagle on).
        // "auto": a private hub on a free port; otherwise the default port, so that
        // clients naming plain "can0" find it — unless a server already runs there.
        m_hub = new VirtualCanHub(this);
        const bool privateHub = iface == QLatin1String("auto");
        if (m_hub->start(privateHub ? 0 : kVirtualCanDefaultPort)) {
            const QString channel = privateHub ? QStringLiteral("can0") : iface;
            iface = QStringLiteral("tcp://127.0.0.1:%1/%2").arg(m_hub->port()).arg(channel);
            m_clientCan = privateHub ? QStringLiteral("virtualcan:") + iface : QStringLiteral("virtualcan:") + channel;
        } else {
            delete m_hub;
            m_hub = nullptr;
            if (privateHub)
                return {ErrorCode::OpenFailed, tr("Cannot start a virtual CAN hub on this machine.")};
            m_clientCan = m_options.can;
        }
    } else {
        m_clientCan = m_options.can;
    }
    m_can = new SimCanBus(this);
    // On our own hub the simulated drives attach to it directly (one socket hop per frame
    // instead of two: see hubcandevice.h); anywhere else through the plugin.
    int hubChannel = -1;
    if (m_hub) {
        bool ok = false;
        const QString name = iface.section(QLatin1Char('/'), -1);
        const int n = name.startsWith(QLatin1String("can")) ? name.mid(3).toInt(&ok) : -1;
        if (ok && n >= 0)
            hubChannel = n;
    }
    const Error opened = hubChannel >= 0
        ? m_can->open(m_hub->createLocalDevice(hubChannel), cs.plugin, iface, m_options.bitrate)
        : m_can->open(cs.plugin, iface, m_options.bitrate);
    if (opened.isError())
        return opened;
    connect(m_can, &SimCanBus::connected, this, [this] { VirtualCanHub::setLowDelay(m_can->canDevice()); });
    const SimFamily &family = simFamily(m_options.family);
    if (!family.can)
        return {ErrorCode::InvalidArgument, tr("%1 drives live on RS485: use --pty.").arg(familyId(m_options.family))};
    return addDevices(m_can, m_options, family.can);
}

void SimBench::stop()
{
    if (!isRunning())
        return;
    if (!m_options.stateFile.isEmpty())
        saveState();
    delete m_serial;
    m_serial = nullptr;
    if (m_can)
        m_can->close();
    delete m_can;
    m_can = nullptr;
    delete m_hub;
    m_hub = nullptr;
    m_ptyPath.clear();
}

void SimBench::setSilent(bool silent)
{
    for (int i = 0; m_serial && i < m_serial->deviceCount(); ++i)
        m_serial->device(i)->faults().setSilent(silent);
    for (int i = 0; m_can && i < m_can->deviceCount(); ++i)
        m_can->device(i)->faults().setSilent(silent);
}

bool SimBench::canInjectAlarm() const
{
    if (m_serial && m_serial->deviceCount() > 0 && dynamic_cast<SimServoModbusDrive *>(m_serial->device(0)))
        return true;
    return m_can && m_can->deviceCount() > 0 && dynamic_cast<SimServoCanDrive *>(m_can->device(0));
}

bool SimBench::injectAlarm(int address, int code)
{
    const int i = m_options.addresses.indexOf(address);
    if (i < 0)
        return false;
    if (m_serial) {
        if (auto *d = dynamic_cast<SimServoModbusDrive *>(m_serial->device(i))) {
            d->setAlarm(code);
            return true;
        }
    }
    if (m_can) {
        if (auto *d = dynamic_cast<SimServoCanDrive *>(m_can->device(i))) {
            d->injectAlarm(code);
            return true;
        }
    }
    return false;
}

QString SimBench::where() const
{
    if (m_serial)
        return QStringLiteral("pty: ") + m_ptyPath;
    if (m_can)
        return QStringLiteral("can: ") + m_clientCan;
    return {};
}

ConnectionSettings SimBench::clientSettings() const
{
    ConnectionSettings s;
    s.family = m_options.family;
    if (m_serial) {
        s.port = m_options.linkPath.isEmpty() ? m_ptyPath : m_options.linkPath;
        s.baud = m_options.baud;
    } else {
        s.can = m_clientCan;
        s.bitrate = m_options.bitrate;
    }
    s.framing = m_options.framing;
    return s;
}

QJsonObject SimBench::stateOf() const
{
    QJsonArray drives;
    auto add = [&drives](int address, const QJsonObject &state) {
        drives.append(QJsonObject{{QStringLiteral("address"), address}, {QStringLiteral("state"), state}});
    };
    for (int i = 0; m_serial && i < m_serial->deviceCount(); ++i) {
        if (auto *d = dynamic_cast<SimServoModbusDrive *>(m_serial->device(i)))
            add(m_options.addresses.value(i), d->saveState());
        else if (auto *k = dynamic_cast<SimShuokeSerialDevice *>(m_serial->device(i)))
            add(m_options.addresses.value(i), k->drive().saveState());
    }
    for (int i = 0; m_can && i < m_can->deviceCount(); ++i) {
        if (auto *d = dynamic_cast<SimServoCanDrive *>(m_can->device(i)))
            add(m_options.addresses.value(i), d->saveState());
        else if (auto *k = dynamic_cast<SimShuokeCanDevice *>(m_can->device(i)))
            add(m_options.addresses.value(i), k->drive().saveState());
    }
    return {{QStringLiteral("format"), QLatin1String(kStateFormat)},
            {QStringLiteral("family"), familyId(m_options.family)},
            {QStringLiteral("drives"), drives}};
}

Error SimBench::applyState(const QJsonObject &root)
{
    const QString file = m_options.stateFile;
    if (root.value(QStringLiteral("format")).toString() != QLatin1String(kStateFormat))
        return {ErrorCode::Malformed, tr("%1 is not a DriveDesk simulator state file.").arg(file)};
    if (root.value(QStringLiteral("family")).toString() != familyId(m_options.family))
        return {ErrorCode::InvalidArgument,
                tr("%1 holds the state of %2 drives, not %3.")
                    .arg(file, root.value(QStringLiteral("family")).toString(), familyId(m_options.family))};
    const QJsonArray drives = root.value(QStringLiteral("drives")).toArray();
    for (const QJsonValue &v : drives) {
        const QJsonObject o = v.toObject();
        const int address = o.value(QStringLiteral("address")).toInt(-1);
        const int i = m_options.addresses.indexOf(address);
        if (i < 0)
            continue; // a drive not on this bench now
        QString why;
        bool ok = true;
        const QJsonObject state = o.value(QStringLiteral("state")).toObject();
        if (m_serial) {
            if (auto *d = dynamic_cast<SimServoModbusDrive *>(m_serial->device(i)))
                ok = d->loadState(state, &why);
            else if (auto *k = dynamic_cast<SimShuokeSerialDevice *>(m_serial->device(i)))
                ok = k->drive().loadState(state, &why);
        } else if (m_can) {
            if (auto *d = dynamic_cast<SimServoCanDrive *>(m_can->device(i)))
                ok = d->loadState(state, &why);
            else if (auto *k = dynamic_cast<SimShuokeCanDevice *>(m_can->device(i)))
                ok = k->drive().loadState(state, &why);
        }
        if (!ok)
            return {ErrorCode::Malformed, tr("%1: drive %2: %3").arg(file).arg(address).arg(why)};
    }
    return Error::none();
}

Error SimBench::saveState() const
{
    if (m_options.stateFile.isEmpty())
        return Error::none();
    QSaveFile f(m_options.stateFile);
    if (!f.open(QIODevice::WriteOnly))
        return {ErrorCode::FileError, tr("Cannot write %1: %2").arg(m_options.stateFile, f.errorString())};
    const QByteArray bytes = QJsonDocument(stateOf()).toJson();
    if (f.write(bytes) != bytes.size() || !f.flush() || !f.commit())
        return {ErrorCode::FileError, tr("Cannot write %1: %2").arg(m_options.stateFile, f.errorString())};
    return Error::none();
}

} // namespace dd
