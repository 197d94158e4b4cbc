#include "ui/bus/serialportwatcher.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QSerialPortInfo>

namespace dd {

QString SerialPortEntry::label() const
{
    QString text = path;
    QString what = description;
    if (!manufacturer.isEmpty())
        what = what.isEmpty() ? manufacturer : QStringLiteral("%1 (%2)").arg(what, manufacturer);
    if (!what.isEmpty())
        text += QStringLiteral(" — ") + what;
    if (hasIds)
        text +=
            QStringLiteral(" [%1:%2]").arg(vendorId, 4, 16, QLatin1Char('0')).arg(productId, 4, 16, QLatin1Char('0'));
    return text;
}

SerialPortWatcher::SerialPortWatcher(QObject *parent)
    : QObject(parent)
    , m_dirs{QDir::tempPath()}
{
    m_timer.setInterval(PollIntervalMs);
    connect(&m_timer, &QTimer::timeout, this, &SerialPortWatcher::refresh);
}

bool SerialPortWatcher::contains(const QString &path) const
{
    for (const SerialPortEntry &e : m_ports)
        if (e.path == path)
            return true;
    return false;
}

void SerialPortWatcher::addExtraPort(const QString &path, const QString &description)
{
    SerialPortEntry e;
    e.path = path;
    e.description = description;
    e.isVirtual = true;
    m_extra.append(e);
    refresh();
}

void SerialPortWatcher::start()
{
    refresh();
    m_timer.start();
}

void SerialPortWatcher::stop()
{
    m_timer.stop();
}

void SerialPortWatcher::refresh()
{
    QList<SerialPortEntry> now = scan();
    if (now != m_ports) {
        m_ports = now;
        emit portsChanged();
    }
}

QList<SerialPortEntry> SerialPortWatcher::scan() const
{
    QList<SerialPortEntry> out;
    const QList<QSerialPortInfo> infos = QSerialPortInfo::availablePorts();
    for (const QSerialPortInfo &info : infos) {
        SerialPortEntry e;
        e.path = info.systemLocation();
        e.description = info.description();
        e.manufacturer = info.manufacturer();
        e.hasIds = info.hasVendorIdentifier() && info.hasProductIdentifier();
        e.vendorId = info.vendorIdentifier();
        e.productId = info.productIdentifier();
        out.append(e);
    }
    std::sort(out.begin(), out.end(),
              [](const SerialPortEntry &a, const SerialPortEntry &b) { return a.path < b.path; });

    const QString ptyDescription = QCoreApplication::translate("dd::SerialPortWatcher",
                                                               "Virtual port (pseudo-terminal)");
    QStringList seen;
    for (const QString &dirPath : m_dirs) {
        const QFileInfoList entries = QDir(dirPath).entryInfoList(QDir::System | QDir::Files | QDir::NoDotAndDotDot,
                                                                  QDir::Name);
        for (const QFileInfo &fi : entries) {
            if (!fi.isSymLink())
                continue;
            const QString target = fi.symLinkTarget();
            if (!target.startsWith(QLatin1String("/dev/pts/")) || !QFileInfo::exists(target))
                continue;
            SerialPortEntry e;
            e.path = fi.absoluteFilePath();
            e.description = ptyDescription;
            e.manufacturer = target;
            e.isVirtual = true;
            out.append(e);
            seen.append(e.path);
        }
    }
    for (const SerialPortEntry &e : m_extra)
        if (!seen.contains(e.path) && QFileInfo::exists(e.path))
            out.append(e);
    return out;
}

} // namespace dd
