#pragma once

#include "common/error.h"
#include "drive/connectionsettings.h"

#include <QObject>
#include <QStringList>

namespace dd {

// SimBench's objects on the bench thread: the buses and the simulated drives. Created,
// built and deleted on that thread only.
class SimBenchWorker : public QObject
{
    Q_OBJECT
public:
    explicit SimBenchWorker(QObject *parent = nullptr);
    ~SimBenchWorker() override;

    Error build();
    QList<ConnectionSettings> connections() const { return m_connections; }
    QStringList describe() const { return m_descriptions; }

private:
    QList<ConnectionSettings> m_connections;
    QStringList m_descriptions;
};

} // namespace dd
