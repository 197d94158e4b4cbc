#include "core/drive/drivehub.h"

#include "core/drive/drive.h"
#include "core/drive/driveconnection.h"
#include "core/drive/drivereply.h"
#include "core/link/traffictap.h"

#include <QPointer>
#include <QThread>
#include <QTimer>

namespace dd {

namespace {
// Runs `fn` on the thread of `context` (queued).
template <typename Fn>
void post(QObject *context, Fn &&fn)
{
    QMetaObject::invokeMethod(context, std::forward<Fn>(fn), Qt::QueuedConnection);
}
} // namespace

DriveHub::DriveHub(QObject *parent)
    : QObject(parent)
{
    qRegisterMetaType<dd::TrafficRecord>();
    qRegisterMetaType<dd::DriveStatus>();
    qRegisterMetaType<dd::DriveResult>();
    qRegisterMetaType<dd::Error>();
    qRegisterMetaType<dd::DiscoveredDrive>();
    qRegisterMetaType<dd::JogEnd>();
    m_thread = new QThread;
    m_thread->setObjectName(QStringLiteral("drivedesk-io"));
    m_ioContext = new QObject;
    m_ioContext->moveToThread(m_thread);
    m_thread->start(QThread::HighPriority);
}

DriveHub::~DriveHub()
{
    QMetaObject::invokeMethod(
        m_ioContext,
        [this] {
            for (Discovery *s : std::as_const(m_scans))
                s->cancel();
            m_scans.clear();
            qDeleteAll(m_connections);
            m_connections.clear();
            qDeleteAll(m_closing);
            m_closing.clear();
        },
        Qt::BlockingQueuedConnection);
    m_thread->quit();
    m_thread->wait();
    delete m_ioContext;
    delete m_thread;
}

DriveConnection *DriveHub::connectionOnIo(int id) const
{
    return m_connections.value(id, nullptr);
}

void DriveHub::openConnection(const ConnectionSettings &settings, std::function<void(int, const Error &)> done)
{
    const int id = m_nextId++;
    post(m_ioContext, [this, id, settings, done] {
        auto *c = new DriveConnection;
        Error e;
        if (!c->open(settings, &e)) {
            delete c;
            post(this, [done, e] {
                if (done)
                    done(0, e);
            });
            return;
        }
        m_connections.insert(id, c);
        connect(c->tap(), &TrafficTap::frameRecorded, c,
                [this, id](const TrafficRecord &r) { emit trafficRecorded(id, r); });
        connect(c, &DriveConnection::linkLost, c, [this, id](const Error &why) { emit linkLost(id, why); });
        post(this, [this, id, settings, done] {
            m_settings.insert(id, settings);
            if (done)
                done(id, Error::none());
        });
    });
}

void DriveHub::closeConnection(int id)
{
    m_settings.remove(id);
    post(m_ioContext, [this, id] {
        if (Discovery *s = m_scans.take(id))
            s->cancel();
        DriveConnection *c = m_connections.take(id);
        bool stopping = false;
        for (auto it = m_watched.begin(); it != m_watched.end();) {
            if (it.key().first != id) {
                ++it;
                continue;
            }
            // A held jog must not outlive its link (nothing could stop it from here on).
            if (Drive *d = c ? c->drive(it.key().second) : nullptr; d && d->isJogging()) {
                DriveReply *r = d->stop(false);
                connect(r, &DriveReply::finished, r, &QObject::deleteLater);
                stopping = true;
            }
            it = m_watched.erase(it);
        }
        if (!stopping) {
            delete c;
            return;
        }
        m_closing.insert(c);
        QTimer::singleShot(StopGraceMs, m_ioContext, [this, c] {
            if (m_closing.remove(c))
                delete c;
        });
    });
}

void DriveHub::closeAll()
{
    const QList<int> ids = m_settings.keys();
    for (int id : ids)
        closeConnection(id);
}

void DriveHub::watchDrive(int id, int address, Drive *drive)
{
    const QPair<int, int> key(id, address);
    if (m_watched.contains(key))
        return;
    m_watched.insert(key, true);
    connect(drive, &Drive::statusChanged, drive,
            [this, id, address](const DriveStatus &s) { emit statusChanged(id, address, s); });
    connect(drive, &Drive::alarmChanged, drive,
            [this, id, address](int code) { emit alarmChanged(id, address, code); });
    connect(drive, &Drive::jogLeaseExpired, drive, [this, id, address] { emit jogLeaseExpired(id, address); });
    connect(drive, &Drive::jogEnded, drive,
            [this, id, address](const JogEnd &end) { emit jogEnded(id, address, end); });
}

void DriveHub::run(int id, int address, Operation op, Done done, Progress progress)
{
    post(m_ioContext, [this, id, address, op, done, progress] {
        auto fail = [this, done](const Error &e) {
            DriveResult r;
            r.error = e;
            post(this, [done, r] {
                if (done)
                    done(r);
            });
        };
        DriveConnection *c = connectionOnIo(id);
        if (!c || !c->isOpen()) {
            fail({ErrorCode::LinkClosed, tr("The connection is closed.")});
            return;
        }
        Drive *d = c->drive(address);
        if (!d) {
            fail({ErrorCode::InvalidArgument, tr("There is no drive at address %1.").arg(address)});
            return;
        }
        watchDrive(id, address, d);
        DriveReply *reply = op(*d);
        if (!reply) {
            fail({ErrorCode::NotSupported, tr("The operation was not started.")});
            return;
        }
        if (progress)
            connect(reply, &DriveReply::progress, reply,
                    [this, progress](int n, int total) { post(this, [progress, n, total] { progress(n, total); }); });
        connect(reply, &DriveReply::finished, reply, [this, reply, done, drive = QPointer<Drive>(d)] {
            DriveResult r = DriveResult::from(*reply);
            if (drive)
                r.identity = drive->identity();
            reply->deleteLater();
            post(this, [done, r] {
                if (done)
                    done(r);
            });
        });
    });
}

void DriveHub::scan(int id, const ScanOptions &options, std::function<void(const DiscoveredDrive &)> found,
                    std::function<void(int, int)> progress, std::function<void(const Error &)> finished)
{
    post(m_ioContext, [this, id, options, found, progress, finished] {
        DriveConnection *c = connectionOnIo(id);
        Discovery *s = c ? c->createDiscovery(options) : nullptr;
        if (!s) {
            const Error e{ErrorCode::LinkClosed, tr("The connection is closed.")};
            post(this, [finished, e] {
                if (finished)
                    finished(e);
            });
            return;
        }
        if (Discovery *old = m_scans.take(id))
            old->cancel();
        m_scans.insert(id, s);
        connect(s, &Discovery::found, s, [this, found](const DiscoveredDrive &d) {
            post(this, [found, d] {
                if (found)
                    found(d);
            });
        });
        connect(s, &Discovery::progress, s, [this, progress](int done, int total) {
            post(this, [progress, done, total] {
                if (progress)
                    progress(done, total);
            });
        });
        connect(s, &Discovery::finished, s, [this, id, s, finished](const Error &e) {
            if (m_scans.value(id) == s)
                m_scans.remove(id);
            s->deleteLater();
            post(this, [finished, e] {
                if (finished)
                    finished(e);
            });
        });
        s->start();
    });
}

void DriveHub::cancelScan(int id)
{
    post(m_ioContext, [this, id] {
        if (Discovery *s = m_scans.value(id))
            s->cancel();
    });
}

void DriveHub::stopAll()
{
    post(m_ioContext, [this] {
        for (DriveConnection *c : std::as_const(m_connections))
            c->stopAll();
    });
    emit stopAllSent();
}

void DriveHub::renewJogLease(int id, int address)
{
    post(m_ioContext, [this, id, address] {
        if (DriveConnection *c = connectionOnIo(id))
            if (Drive *d = c->drive(address))
                d->renewJogLease();
    });
}

} // namespace dd
