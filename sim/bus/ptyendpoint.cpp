#include "sim/bus/ptyendpoint.h"

#include "sim/bus/simlogging.h"

#include <QCoreApplication>
#include <QFile>
#include <QSocketNotifier>

#ifdef Q_OS_UNIX
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>
#endif

namespace dd {

namespace {
constexpr qsizetype MaxPendingBytes = 1 << 20; // beyond this the host is not reading at all

#ifdef Q_OS_UNIX
QString errnoText(int err)
{
    return QString::fromLocal8Bit(std::strerror(err));
}

int baudFromSpeed(speed_t speed)
{
    switch (speed) {
    case B50: return 50;
    case B75: return 75;
    case B110: return 110;
    case B134: return 134;
    case B150: return 150;
    case B200: return 200;
    case B300: return 300;
    case B600: return 600;
    case B1200: return 1200;
    case B1800: return 1800;
    case B2400: return 2400;
    case B4800: return 4800;
    case B9600: return 9600;
    case B19200: return 19200;
    case B38400: return 38400;
#ifdef B57600
    case B57600: return 57600;
#endif
#ifdef B115200
    case B115200: return 115200;
#endif
#ifdef B230400
    case B230400: return 230400;
#endif
#ifdef B460800
    case B460800: return 460800;
#endif
#ifdef B500000
    case B500000: return 500000;
#endif
#ifdef B576000
    case B576000: return 576000;
#endif
#ifdef B921600
    case B921600: return 921600;
#endif
#ifdef B1000000
    case B1000000: return 1000000;
#endif
#ifdef B1152000
    case B1152000: return 1152000;
#endif
#ifdef B1500000
    case B1500000: return 1500000;
#endif
#ifdef B2000000
    case B2000000: return 2000000;
#endif
    default: return 0; // B0, BOTHER (custom rate) or unknown
    }
}

bool setNonBlocking(int fd)
{
    const int flags = ::fcntl(fd, F_GETFL);
    return flags >= 0 && ::fcntl(fd, F_SETFL, flags | O_NONBLOCK) == 0;
}
#endif
} // namespace

PtyEndpoint::PtyEndpoint(QObject *parent)
    : ByteEndpoint(parent)
{
}

PtyEndpoint::~PtyEndpoint()
{
    // No closed() from a destructor: nobody should be called back into a dying object.
    const QSignalBlocker block(this);
    close();
}

bool PtyEndpoint::isSupported()
{
#ifdef Q_OS_UNIX
    return true;
#else
    return false;
#endif
}

bool PtyEndpoint::isOpen() const
{
    return m_master >= 0;
}

#ifdef Q_OS_UNIX

Error PtyEndpoint::open(const QString &linkPath)
{
    if (isOpen())
        return {ErrorCode::Busy, tr("The simulated port %1 is already open.").arg(description())};

    const auto fail = [this](const QString &what, int err) {
        const Error e{ErrorCode::OpenFailed,
                      tr("Could not create a pseudo-terminal for the simulator (%1: %2).").arg(what, errnoText(err))};
        const QSignalBlocker block(this);
        close();
        return e;
    };

    m_master = ::posix_openpt(O_RDWR | O_NOCTTY);
    if (m_master < 0)
        return fail(QStringLiteral("posix_openpt"), errno);
    if (::grantpt(m_master) != 0)
        return fail(QStringLiteral("grantpt"), errno);
    if (::unlockpt(m_master) != 0)
        return fail(QStringLiteral("unlockpt"), errno);
#ifdef Q_OS_LINUX
    char name[128] = {};
    if (::ptsname_r(m_master, name, sizeof name) != 0)
        return fail(QStringLiteral("ptsname_r"), errno);
    m_slavePath = QString::fromLocal8Bit(name);
#else
    const char *name = ::ptsname(m_master); // called from the GUI / sim thread only
    if (!name)
        return fail(QStringLiteral("ptsname"), errno);
    m_slavePath = QString::fromLocal8Bit(name);
#endif
    if (!setNonBlocking(m_master))
        return fail(QStringLiteral("fcntl(O_NONBLOCK)"), errno);

    // Our own slave descriptor: keeps the line discipline alive between client sessions
    // (no EIO on the master when the client closes) and lets hostBaud() read the termios.
    m_slave = ::open(QFile::encodeName(m_slavePath).constData(), O_RDWR | O_NOCTTY | O_NONBLOCK);
    if (m_slave < 0)
        return fail(QStringLiteral("open %1").arg(m_slavePath), errno);
    struct termios tio;
    if (::tcgetattr(m_slave, &tio) != 0)
        return fail(QStringLiteral("tcgetattr"), errno);
    ::cfmakeraw(&tio);
    tio.c_cflag |= CLOCAL | CREAD;
    tio.c_cc[VMIN] = 1;
    tio.c_cc[VTIME] = 0;
    if (::tcsetattr(m_slave, TCSANOW, &tio) != 0)
        return fail(QStringLiteral("tcsetattr"), errno);

    if (!linkPath.isEmpty()) {
        const Error linkError = createLink(linkPath);
        if (linkError) {
            const QSignalBlocker block(this);
            close();
            return linkError;
        }
    }

    m_readNotifier = new QSocketNotifier(m_master, QSocketNotifier::Read, this);
    connect(m_readNotifier, &QSocketNotifier::activated, this, &PtyEndpoint::onReadable);
    m_writeNotifier = new QSocketNotifier(m_master, QSocketNotifier::Write, this);
    m_writeNotifier->setEnabled(false);
    connect(m_writeNotifier, &QSocketNotifier::activated, this, &PtyEndpoint::onWritable);

    qCDebug(lcSim).noquote() << "pty open:" << description();
    return Error::none();
}

Error PtyEndpoint::createLink(const QString &linkPath)
{
    const QByteArray link = QFile::encodeName(linkPath);
    struct stat st;
    if (::lstat(link.constData(), &st) == 0 && !S_ISLNK(st.st_mode)) {
        return {ErrorCode::OpenFailed,
                tr("Cannot create the link %1: a file that is not a symbolic link is in the way.").arg(linkPath)};
    }
    // symlink() to a unique temporary name, then rename() over the link: a client never
    // sees a half-made or missing link, and a stale link from an earlier run is replaced.
    const QByteArray tmp = link + ".tmp-" + QByteArray::number(::getpid()) + '-'
        + QByteArray::number(reinterpret_cast<quintptr>(this), 16);
    ::unlink(tmp.constData());
    if (::symlink(QFile::encodeName(m_slavePath).constData(), tmp.constData()) != 0) {
        const int err = errno;
        return {ErrorCode::OpenFailed, tr("Cannot create the link %1 (%2).").arg(linkPath, errnoText(err))};
    }
    if (::rename(tmp.constData(), link.constData()) != 0) {
        const int err = errno;
        ::unlink(tmp.constData());
        return {ErrorCode::OpenFailed, tr("Cannot create the link %1 (%2).").arg(linkPath, errnoText(err))};
    }
    m_linkPath = linkPath;
    m_linkCreated = true;
    return Error::none();
}

void PtyEndpoint::removeLink()
{
    if (!m_linkCreated)
        return;
    m_linkCreated = false;
    const QByteArray link = QFile::encodeName(m_linkPath);
    char target[512] = {};
    const ssize_t n = ::readlink(link.constData(), target, sizeof target - 1);
    // Only remove what is still ours: another simulator may have taken the name over.
    if (n > 0 && QFile::decodeName(QByteArray(target, static_cast<int>(n))) == m_slavePath)
        ::unlink(link.constData());
}

void PtyEndpoint::close()
{
    const bool wasOpen = isOpen();
    const bool announced = m_readNotifier != nullptr; // open() completed
    delete m_readNotifier;
    m_readNotifier = nullptr;
    delete m_writeNotifier;
    m_writeNotifier = nullptr;
    removeLink();
    if (m_master >= 0)
        ::close(m_master);
    if (m_slave >= 0)
        ::close(m_slave);
    m_master = -1;
    m_slave = -1;
    m_pending.clear();
    if (announced)
        qCDebug(lcSim).noquote() << "pty closed:" << m_slavePath;
    if (wasOpen)
        emit closed();
}

qint64 PtyEndpoint::write(const QByteArray &bytes)
{
    if (!isOpen())
        return -1;
    if (m_pending.size() + bytes.size() > MaxPendingBytes) {
        qCWarning(lcSim).noquote() << "pty" << m_slavePath << "is not being read; dropping" << bytes.size() << "bytes";
        return -1;
    }
    m_pending.append(bytes);
    if (!flushPending())
        return -1;
    return bytes.size();
}

bool PtyEndpoint::flushPending()
{
    while (!m_pending.isEmpty()) {
        const ssize_t n = ::write(m_master, m_pending.constData(), static_cast<size_t>(m_pending.size()));
        if (n > 0) {
            m_pending.remove(0, static_cast<qsizetype>(n));
            continue;
        }
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
            m_writeNotifier->setEnabled(true); // the slave's input queue is full
            return true;
        }
        const int err = errno;
        qCWarning(lcSim).noquote() << "pty write failed:" << errnoText(err);
        close();
        return false;
    }
    if (m_writeNotifier)
        m_writeNotifier->setEnabled(false);
    return true;
}

void PtyEndpoint::onWritable()
{
    flushPending();
}

void PtyEndpoint::onReadable()
{
    QByteArray data;
    bool broken = false;
    char buffer[4096];
    for (;;) {
        const ssize_t n = ::read(m_master, buffer, sizeof buffer);
        if (n > 0) {
            data.append(buffer, static_cast<qsizetype>(n));
            continue;
        }
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK))
            break;
        broken = true; // EOF or EIO: cannot happen while we hold the slave, so give up
        break;
    }
    if (!data.isEmpty())
        emit received(data);
    if (broken && isOpen()) {
        qCWarning(lcSim).noquote() << "pty" << m_slavePath << "broke; closing";
        close();
    }
}

int PtyEndpoint::hostBaud() const
{
    if (m_slave < 0)
        return 0;
    struct termios tio;
    if (::tcgetattr(m_slave, &tio) != 0)
        return 0;
    return baudFromSpeed(::cfgetospeed(&tio));
}

#else // !Q_OS_UNIX

Error PtyEndpoint::open(const QString &linkPath)
{
    Q_UNUSED(linkPath);
    return {ErrorCode::NotSupported,
            tr("Simulated serial ports (pseudo-terminals) are available on Linux and macOS only. "
               "Use the built-in demo link on this system.")};
}

Error PtyEndpoint::createLink(const QString &)
{
    return Error::none();
}
void PtyEndpoint::removeLink() { }
void PtyEndpoint::close() { }
qint64 PtyEndpoint::write(const QByteArray &)
{
    return -1;
}
bool PtyEndpoint::flushPending()
{
    return false;
}
void PtyEndpoint::onWritable() { }
void PtyEndpoint::onReadable() { }
int PtyEndpoint::hostBaud() const
{
    return 0;
}

#endif // Q_OS_UNIX

QString PtyEndpoint::description() const
{
    if (m_slavePath.isEmpty())
        return tr("pty (not open)");
    if (m_linkCreated)
        return tr("pty %1 (link %2)").arg(m_slavePath, m_linkPath);
    return tr("pty %1").arg(m_slavePath);
}

} // namespace dd
