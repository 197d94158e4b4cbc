#pragma once

#include "core/common/error.h"
#include "core/common/family.h"
#include "core/link/connectionsettings.h"

#include <QList>
#include <QObject>
#include <QStringList>

namespace dd {

class SimBench;

// DemoBench's objects on the bench thread: one SimBench per family. Created, built and
// deleted on that thread only.
class DemoBenchWorker : public QObject
{
    Q_OBJECT
public:
    explicit DemoBenchWorker(QObject *parent = nullptr);
    ~DemoBenchWorker() override;

    // Starts the buses; ready() follows once every CAN bus has connected (failed() if one
    // does not within SimCanBus::ConnectTimeoutMs).
    Error build(int address, double resonanceHz = 0.0);
    QList<ConnectionSettings> connections() const { return m_connections; }
    QStringList describe() const { return m_descriptions; }
    QList<Family> alarmFamilies() const;
    bool injectAlarm(Family family, int address, int code);

signals:
    void ready();
    void failed(const dd::Error &error);

private:
    void checkReady();

    QList<SimBench *> m_benches;
    QList<ConnectionSettings> m_connections;
    QStringList m_descriptions;
    bool m_readySent = false;
};

} // namespace dd
