#pragma once

#include "core/common/error.h"
#include "core/link/connectionsettings.h"

#include <QObject>
#include <memory>

namespace dd {

class ConnectionController;
class DemoBench;

// File → Demo bench and `drivedesk --demo`: starts the in-process simulated bench (one
// drive of each family, on its own thread — see DemoBench) and, once it is ready, connects
// to its links, scanning each, so the application can be tried with nothing plugged in.
// stop() (or destruction) ends the bench: close the connections to it first.
class DemoLauncher : public QObject
{
    Q_OBJECT
public:
    explicit DemoLauncher(ConnectionController *connections, QObject *parent = nullptr);
    ~DemoLauncher() override;

    Error start();
    void stop();
    bool isRunning() const;
    QList<ConnectionSettings> connections() const;
    DemoBench *bench() const { return m_bench.get(); }

signals:
    void started();
    void failed(const dd::Error &error);

private:
    void connectToBench();

    ConnectionController *m_connections = nullptr;
    std::unique_ptr<DemoBench> m_bench;
};

} // namespace dd
